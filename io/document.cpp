#include "io/document.hpp"

#include <cctype>
#include <map>
#include <utility>

namespace vssw::io {

DocBlock heading(int level, std::string text) {
    DocBlock b;
    b.kind = DocBlock::Kind::heading;
    b.level = level;
    b.text = std::move(text);
    return b;
}

DocBlock paragraph(std::string text) {
    DocBlock b;
    b.kind = DocBlock::Kind::paragraph;
    b.text = std::move(text);
    return b;
}

DocBlock list(std::vector<std::string> items) {
    DocBlock b;
    b.kind = DocBlock::Kind::list;
    b.items = std::move(items);
    return b;
}

DocBlock table(std::vector<std::string> header, std::size_t text_columns) {
    DocBlock b;
    b.kind = DocBlock::Kind::table;
    b.header = std::move(header);
    b.text_columns = text_columns;
    return b;
}

DocBlock plot(std::string title, std::string plot_name) {
    DocBlock b;
    b.kind = DocBlock::Kind::plot;
    b.text = std::move(title);
    b.plot_name = std::move(plot_name);
    return b;
}

DocBlock contents() {
    DocBlock b;
    b.kind = DocBlock::Kind::contents;
    return b;
}

std::vector<std::string> heading_anchors(const Document& doc) {
    std::vector<std::string> anchors(doc.blocks.size());
    std::map<std::string, int> seen;
    for (std::size_t i = 0; i < doc.blocks.size(); ++i) {
        if (doc.blocks[i].kind != DocBlock::Kind::heading) continue;
        std::string a;
        for (char c : doc.blocks[i].text) {
            const auto u = static_cast<unsigned char>(c);
            if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_') a += static_cast<char>(std::tolower(u));
            else if (c == ' ') a += '-';
        }
        const int n = seen[a]++;
        anchors[i] = n == 0 ? a : a + "-" + std::to_string(n);
    }
    return anchors;
}

}  // namespace vssw::io

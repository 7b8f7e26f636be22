#include "study/document.hpp"

#include <utility>

namespace vssw::study {

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

}  // namespace vssw::study

#include "study/document_markdown.hpp"

#include <ostream>
#include <string>
#include <vector>

#include "study/text.hpp"

namespace vssw::study {
namespace {

// A table cell on one line, its pipes escaped.
std::string cell(const std::string& text) {
    std::string s;
    for (char c : text) {
        if (c == '\n' || c == '\r') s += ' ';
        else if (c == '|') s += "\\|";
        else s += c;
    }
    return s;
}

// A cell's text as Markdown: bold when flagged or failed, its verdict's mark after it.
std::string cell_text(const DocCell& c) {
    std::string text = cell(c.text);
    if (c.verdict == DocCell::Verdict::pass) text += " \u2713";
    if (c.verdict == DocCell::Verdict::fail) text += " \u2717";
    return c.flagged || c.verdict == DocCell::Verdict::fail ? "**" + text + "**" : text;
}

}  // namespace

void write_markdown(std::ostream& out, const Document& doc) {
    out << "# " << one_line(doc.title) << "\n";
    const std::vector<std::string> anchors = heading_anchors(doc);
    for (std::size_t k = 0; k < doc.blocks.size(); ++k) {
        const DocBlock& b = doc.blocks[k];
        out << '\n';
        switch (b.kind) {
            case DocBlock::Kind::heading: out << std::string(static_cast<std::size_t>(b.level), '#') << ' ' << one_line(b.text) << '\n'; break;
            case DocBlock::Kind::paragraph: out << b.text << '\n'; break;
            case DocBlock::Kind::list:
                for (const std::string& item : b.items) out << "- " << one_line(item) << '\n';
                break;
            case DocBlock::Kind::table:
                out << '|';
                for (const std::string& h : b.header) out << ' ' << cell(h) << " |";
                out << "\n|";
                for (std::size_t i = 0; i < b.header.size(); ++i) out << (i < b.text_columns ? "---|" : "---:|");
                out << '\n';
                for (const auto& row : b.rows) {
                    out << '|';
                    for (const DocCell& c : row) out << ' ' << cell_text(c) << " |";
                    out << '\n';
                }
                break;
            case DocBlock::Kind::contents:
                for (std::size_t i = 0; i < doc.blocks.size(); ++i) {
                    const DocBlock& h = doc.blocks[i];
                    if (h.kind != DocBlock::Kind::heading || h.level < 2 || h.level > 3) continue;
                    out << (h.level == 2 ? "- " : "  - ") << '[' << one_line(h.text) << "](#" << anchors[i] << ")\n";
                }
                break;
            case DocBlock::Kind::plot:
                out << "![" << cell(b.text) << "](plots/" << b.plot_name << ".svg)\n";
                break;
        }
    }
}

}  // namespace vssw::study

#include "study/document_markdown.hpp"

#include <ostream>
#include <string>

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

}  // namespace

void write_markdown(std::ostream& out, const Document& doc) {
    out << "# " << one_line(doc.title) << "\n";
    for (const DocBlock& b : doc.blocks) {
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
                    for (const DocCell& c : row) out << ' ' << (c.flagged ? "**" + cell(c.text) + "**" : cell(c.text)) << " |";
                    out << '\n';
                }
                break;
            case DocBlock::Kind::plot:
                out << "![" << cell(b.text) << "](plots/" << b.plot_name << ".svg)\n";
                break;
        }
    }
}

}  // namespace vssw::study

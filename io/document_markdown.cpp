#include "io/document_markdown.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace vssw::io {
namespace {

// Text shown as text by every Markdown renderer, whatever it holds: '<', '>' and '&' as HTML entities (CommonMark
// honours a backslash before '<', Python-Markdown, which MkDocs uses, does not, and a name "<img onerror=...>" became
// a live tag there), and the characters that make links, images, emphasis and code spans backslash-escaped, an escape
// every renderer honours for them, so that "[x](javascript:...)" in a name stays text (without its brackets no link
// starts, so parentheses stay as written and the page's own prose, "Eq. (19)", reads as it is).
std::string as_text(const std::string& text) {
    std::string s;
    for (char c : text) {
        if (c == '<') s += "&lt;";
        else if (c == '>') s += "&gt;";
        else if (c == '&') s += "&amp;";
        else if (c == '[' || c == ']' || c == '*' || c == '_' || c == '`' || c == '\\')
            s += std::string("\\") + c;
        else s += c;
    }
    return s;
}

// Text on one line, for a heading, a list item or a table cell: every control character a space (a line break would
// end the block and start another).
std::string line_text(const std::string& text) {
    std::string s = as_text(text);
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == '\x7f') c = ' ';
    return s;
}

// A table cell on one line, its pipes escaped.
std::string cell(const std::string& text) {
    std::string s;
    for (char c : line_text(text)) {
        if (c == '|') s += "\\|";
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
    out << "# " << line_text(doc.title) << "\n";
    const std::vector<std::string> anchors = heading_anchors(doc);
    for (std::size_t k = 0; k < doc.blocks.size(); ++k) {
        const DocBlock& b = doc.blocks[k];
        out << '\n';
        switch (b.kind) {
            case DocBlock::Kind::heading: out << std::string(static_cast<std::size_t>(b.level), '#') << ' ' << line_text(b.text) << '\n'; break;
            case DocBlock::Kind::paragraph: out << as_text(b.text) << '\n'; break;
            case DocBlock::Kind::list:
                for (const std::string& item : b.items) out << "- " << line_text(item) << '\n';
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
                    out << (h.level == 2 ? "- " : "  - ") << '[' << cell(h.text) << "](#" << anchors[i] << ")\n";
                }
                break;
            case DocBlock::Kind::plot:
                out << "![" << cell(b.text) << "](plots/" << b.plot_name << ".svg)\n";
                break;
        }
    }
}

}  // namespace vssw::io

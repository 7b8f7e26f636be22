#include "study/document_html.hpp"

#include <fstream>
#include <ostream>
#include <sstream>

namespace vssw::study {
namespace {

const char* const kStyle = R"(
body { font-family: system-ui, sans-serif; max-width: 1200px; margin: 2em auto; padding: 0 1em; color: #222;
       line-height: 1.45; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; margin-top: 1.8em; } h3 { margin-top: 1.4em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; vertical-align: top; }
th { background: #f2f2f2; } .text { text-align: left; }
td.flag { color: #b00020; font-weight: bold; }
figure { margin: 1em 0; } figcaption { font-size: 0.9em; color: #555; }
figure svg { max-width: 100%; height: auto; }
)";

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    for (std::size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
        s.replace(pos, from.size(), to);
}

// The plot's SVG element, without the XML prolog and doctype, its ids prefixed so that two plots on one page do
// not share them. Empty when the file cannot be read or holds no <svg.
std::string inline_svg(const std::filesystem::path& file, const std::string& prefix) {
    std::ifstream f(file, std::ios::binary);
    if (!f) return "";
    std::ostringstream text;
    text << f.rdbuf();
    std::string svg = text.str();
    const auto start = svg.find("<svg");
    if (start == std::string::npos) return "";
    svg.erase(0, start);
    for (const char* q : {"'", "\""}) {
        replace_all(svg, std::string("id=") + q, std::string("id=") + q + prefix);
        replace_all(svg, std::string("href=") + q + "#", std::string("href=") + q + "#" + prefix);
    }
    replace_all(svg, "url(#", "url(#" + prefix);
    return svg;
}

}  // namespace

std::string html_escape(const std::string& text) {
    std::string s;
    s.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': s += "&amp;"; break;
            case '<': s += "&lt;"; break;
            case '>': s += "&gt;"; break;
            case '"': s += "&quot;"; break;
            default: s += c;
        }
    }
    return s;
}

void write_html(std::ostream& out, const Document& doc, const std::filesystem::path& plots_dir) {
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(doc.title)
        << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << html_escape(doc.title) << "</h1>\n";
    int plot_index = 0;
    for (const DocBlock& b : doc.blocks) {
        switch (b.kind) {
            case DocBlock::Kind::heading:
                out << "<h" << b.level << '>' << html_escape(b.text) << "</h" << b.level << ">\n";
                break;
            case DocBlock::Kind::paragraph: out << "<p>" << html_escape(b.text) << "</p>\n"; break;
            case DocBlock::Kind::list:
                out << "<ul>\n";
                for (const std::string& item : b.items) out << "<li>" << html_escape(item) << "</li>\n";
                out << "</ul>\n";
                break;
            case DocBlock::Kind::table:
                out << "<table>\n<thead><tr>";
                for (std::size_t i = 0; i < b.header.size(); ++i)
                    out << (i < b.text_columns ? "<th class=\"text\">" : "<th>") << html_escape(b.header[i]) << "</th>";
                out << "</tr></thead>\n<tbody>\n";
                for (const auto& row : b.rows) {
                    out << "<tr>";
                    for (std::size_t i = 0; i < row.size(); ++i) {
                        std::string cls = i < b.text_columns ? "text" : "";
                        if (row[i].flagged) cls += cls.empty() ? "flag" : " flag";
                        out << (cls.empty() ? std::string("<td>") : "<td class=\"" + cls + "\">")
                            << html_escape(row[i].text) << "</td>";
                    }
                    out << "</tr>\n";
                }
                out << "</tbody>\n</table>\n";
                break;
            case DocBlock::Kind::plot: {
                const std::string svg =
                    inline_svg(plots_dir / (b.plot_name + ".svg"), "p" + std::to_string(plot_index++) + "-");
                out << "<figure>\n";
                if (svg.empty()) out << "<p>(plots/" << html_escape(b.plot_name) << ".svg could not be read)</p>\n";
                else out << svg << '\n';
                out << "<figcaption>" << html_escape(b.text) << " (plots/" << html_escape(b.plot_name)
                    << ".svg)</figcaption>\n</figure>\n";
                break;
            }
        }
    }
    out << "</body>\n</html>\n";
}

}  // namespace vssw::study

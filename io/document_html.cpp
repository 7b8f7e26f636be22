#include "io/document_html.hpp"

#include <fstream>
#include <ostream>
#include <sstream>
#include <vector>

namespace vssw::io {
namespace {

const char* const kStyle = R"(
body { font-family: system-ui, sans-serif; max-width: 1140px; margin: 2em auto; padding: 0 1em; color: #222;
       line-height: 1.45; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; margin-top: 1.8em; } h3 { margin-top: 1.4em; }
div.table { overflow-x: auto; margin: 0.8em 0; }
table { border-collapse: collapse; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; vertical-align: top; }
td:not(.text) { white-space: nowrap; }
th { background: #f2f2f2; } .text { text-align: left; }
td.flag { color: #b00020; font-weight: bold; }
td.pass { background: #d9f2e3; } td.pass::after { content: " \2713"; color: #1b7a43; }
td.fail { background: #fbdada; color: #8a0018; font-weight: bold; } td.fail::after { content: " \2717"; }
th.apart, td.apart { background: #f7f7f7; color: #555; font-style: italic; }
th.first-apart, td.first-apart { border-left: 4px double #999; }
table.matrix td, table.matrix th { padding: 0.35em 0.8em; } table.matrix td { white-space: nowrap; }
nav.contents ul { margin: 0.2em 0; } nav.contents > ul { columns: 2; }
figure { margin: 1.6em 0 1em; } figcaption { font-size: 0.9em; color: #555; margin-bottom: 0.3em; }
figure svg { width: 100%; height: auto; display: block; }
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

namespace {

void write_table(std::ostream& out, const DocBlock& b) {
    // The class of column i: text or number, set apart or not.
    auto column_class = [&](std::size_t i) {
        std::string cls = i < b.text_columns ? "text" : "";
        if (b.apart_from > 0 && i >= b.apart_from) {
            cls += cls.empty() ? "apart" : " apart";
            if (i == b.apart_from) cls += " first-apart";
        }
        return cls;
    };
    // The wrapper scrolls a table wider than the page (the matrix of many engines) inside it, its numbers unbroken.
    out << "<div class=\"table\">"
        << (b.css_class.empty() ? std::string("<table>") : "<table class=\"" + html_escape(b.css_class) + "\">")
        << "\n<thead><tr>";
    for (std::size_t i = 0; i < b.header.size(); ++i) {
        const std::string cls = column_class(i);
        out << (cls.empty() ? std::string("<th>") : "<th class=\"" + cls + "\">") << html_escape(b.header[i]) << "</th>";
    }
    out << "</tr></thead>\n<tbody>\n";
    for (const auto& row : b.rows) {
        out << "<tr>";
        for (std::size_t i = 0; i < row.size(); ++i) {
            std::string cls = column_class(i);
            auto add = [&](const char* c) { cls += cls.empty() ? c : std::string(" ") + c; };
            if (row[i].flagged) add("flag");
            if (row[i].verdict == DocCell::Verdict::pass) add("pass");
            if (row[i].verdict == DocCell::Verdict::fail) add("fail");
            out << "<td";
            if (!cls.empty()) out << " class=\"" << cls << '"';
            if (!row[i].note.empty()) out << " title=\"" << html_escape(row[i].note) << '"';
            out << '>' << html_escape(row[i].text) << "</td>";
        }
        out << "</tr>\n";
    }
    out << "</tbody>\n</table></div>\n";
}

// The level-2 headings, each with its level-3 headings beneath.
void write_contents(std::ostream& out, const Document& doc, const std::vector<std::string>& anchors) {
    out << "<nav class=\"contents\">\n<ul>\n";
    bool open_sub = false, open_item = false;
    for (std::size_t i = 0; i < doc.blocks.size(); ++i) {
        const DocBlock& h = doc.blocks[i];
        if (h.kind != DocBlock::Kind::heading || h.level < 2 || h.level > 3) continue;
        const std::string link =
            "<a href=\"#" + html_escape(anchors[i]) + "\">" + html_escape(h.text) + "</a>";
        if (h.level == 2) {
            if (open_sub) out << "</ul>";
            if (open_item) out << "</li>\n";
            out << "<li>" << link;
            open_sub = false;
            open_item = true;
        } else {
            if (!open_sub) out << "\n<ul>\n";
            out << "<li>" << link << "</li>\n";
            open_sub = true;
        }
    }
    if (open_sub) out << "</ul>";
    if (open_item) out << "</li>\n";
    out << "</ul>\n</nav>\n";
}

}  // namespace

void write_html(std::ostream& out, const Document& doc, const std::filesystem::path& plots_dir) {
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
        << html_escape(doc.title) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>"
        << html_escape(doc.title) << "</h1>\n";
    const std::vector<std::string> anchors = heading_anchors(doc);
    int plot_index = 0;
    for (std::size_t k = 0; k < doc.blocks.size(); ++k) {
        const DocBlock& b = doc.blocks[k];
        switch (b.kind) {
            case DocBlock::Kind::heading:
                out << "<h" << b.level << " id=\"" << html_escape(anchors[k]) << "\">" << html_escape(b.text) << "</h"
                    << b.level << ">\n";
                break;
            case DocBlock::Kind::paragraph: out << "<p>" << html_escape(b.text) << "</p>\n"; break;
            case DocBlock::Kind::list:
                out << "<ul>\n";
                for (const std::string& item : b.items) out << "<li>" << html_escape(item) << "</li>\n";
                out << "</ul>\n";
                break;
            case DocBlock::Kind::table: write_table(out, b); break;
            case DocBlock::Kind::contents: write_contents(out, doc, anchors); break;
            case DocBlock::Kind::plot: {
                const std::string svg =
                    inline_svg(plots_dir / (b.plot_name + ".svg"), "p" + std::to_string(plot_index++) + "-");
                // The caption first: under its plot it read as the title of the next one.
                out << "<figure>\n<figcaption>" << html_escape(b.text) << " (plots/" << html_escape(b.plot_name)
                    << ".svg)</figcaption>\n";
                if (svg.empty()) out << "<p>(plots/" << html_escape(b.plot_name) << ".svg could not be read)</p>\n";
                else out << svg << '\n';
                out << "</figure>\n";
                break;
            }
        }
    }
    out << "</body>\n</html>\n";
}

}  // namespace vssw::io

#pragma once
// A document built once and rendered twice, as Markdown (io/document_markdown.hpp) and as one self-contained HTML
// page (io/document_html.hpp), so that the two say the same thing: headings, paragraphs, lists, tables and plots
// (SVGs in the document's plots/ folder). The validation report and a study's prose are both built as one.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace vssw::io {

struct DocCell {
    DocCell(std::string text_ = {}, bool flagged_ = false) : text(std::move(text_)), flagged(flagged_) {}
    std::string text;
    bool flagged = false;  // outside its target, or a failure: bold in Markdown, red in HTML
    // A verdict against a target (the report's matrix): a coloured background and a mark in HTML (green with a tick,
    // red with a cross), the mark in Markdown (a fail also bold); none: neither.
    enum class Verdict { none, pass, fail };
    Verdict verdict = Verdict::none;
    std::string note;  // HTML: the cell's tooltip (e.g. the case of a worst error); not in Markdown
};

struct DocBlock {
    // contents: a table of contents of the document's level-2 and level-3 headings, linked to their anchors.
    enum class Kind { heading, paragraph, list, table, plot, contents };
    Kind kind = Kind::paragraph;
    int level = 0;                                // heading: 1, 2, 3
    std::string text;                             // heading, paragraph; plot: its title
    std::vector<std::string> items;               // list
    std::vector<std::string> header;              // table
    std::size_t text_columns = 1;                 // table: the leading columns holding text (left-aligned)
    std::vector<std::vector<DocCell>> rows;       // table
    std::size_t apart_from = 0;                   // table: the columns from this one on are set apart (0: none)
    std::string css_class;                        // table: its HTML class ("matrix"), empty for none
    std::string plot_name;                        // plot: file stem in plots/
};

struct Document {
    std::string title;
    std::vector<DocBlock> blocks;
};

DocBlock heading(int level, std::string text);
DocBlock paragraph(std::string text);
DocBlock list(std::vector<std::string> items);
// A table without rows yet; its first text_columns columns are left-aligned text, the others numbers.
DocBlock table(std::vector<std::string> header, std::size_t text_columns);
DocBlock plot(std::string title, std::string plot_name);
DocBlock contents();

// The anchor of each block that is a heading ("" for the others), as GitHub makes them from a Markdown heading (lower
// case, punctuation dropped, spaces as '-', a repeat suffixed "-1", "-2", ...), so that the HTML's ids and the
// Markdown's links agree.
std::vector<std::string> heading_anchors(const Document& doc);

}  // namespace vssw::io

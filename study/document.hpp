#pragma once
// A document built once and rendered twice, as Markdown (study/document_markdown.hpp) and as one self-contained HTML
// page (study/document_html.hpp), so that the two say the same thing: headings, paragraphs, lists, tables and plots
// (SVGs in the document's plots/ folder). The validation report and a study's prose are both built as one.
#include <cstddef>
#include <string>
#include <vector>

namespace vssw::study {

struct DocCell {
    std::string text;
    bool flagged = false;  // outside its target, or a failure: bold in Markdown, red in HTML
};

struct DocBlock {
    enum class Kind { heading, paragraph, list, table, plot };
    Kind kind = Kind::paragraph;
    int level = 0;                                // heading: 1, 2, 3
    std::string text;                             // heading, paragraph; plot: its title
    std::vector<std::string> items;               // list
    std::vector<std::string> header;              // table
    std::size_t text_columns = 1;                 // table: the leading columns holding text (left-aligned)
    std::vector<std::vector<DocCell>> rows;       // table
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

}  // namespace vssw::study

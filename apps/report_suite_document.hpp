#pragma once
// The content of report.md and report.html, built once as a small document (headings, paragraphs, lists, tables,
// plots) and rendered by report_suite_markdown and report_suite_html, so the two say the same thing.
#include <string>
#include <vector>

#include "apps/report_suite.hpp"
#include "apps/report_suite_plots.hpp"

namespace vssw::cli {

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

// plots: what write_plots made (empty with --no-plots); plots_skipped: --no-plots was given.
Document build_document(const ReportInput& in, const PlotResult& plots, bool plots_skipped);

}  // namespace vssw::cli

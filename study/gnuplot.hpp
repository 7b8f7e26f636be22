#pragma once
// Plots drawn by gnuplot to SVG, each beside the .gp script and .dat data that made it (so that `cd plots && gnuplot
// NAME.gp` re-draws it). Scripts and data are written through AtomicFile; gnuplot runs once per script in the plots
// folder; a plot whose SVG is missing or empty afterwards counts as failed and its SVG is removed. When gnuplot cannot
// be run at all the scripts and data are still written and the result says why, for a warning: a missing gnuplot never
// fails a report or a study.
#include <filesystem>
#include <string>
#include <vector>

#include "study/document.hpp"

namespace vssw::study {

struct Plot {
    std::string section;  // the heading it appears under in a document ("Error against step size")
    std::string name;     // file stem in plots/: "trace_fig6-vssw_r0.5"
    std::string title;    // for people
    bool made = false;    // the .svg exists
};

struct PlotScript {
    Plot plot;
    std::string gp, dat;  // the contents of NAME.gp and NAME.dat
};

struct PlotResult {
    std::vector<Plot> plots;
    bool all_made = false;
    std::string note;  // empty when every plot was made; else what went wrong (for the document and a warning)
};

// Writes every script and its data into plots_dir (created) and runs `program` (looked up in PATH unless it holds a
// '/') on each.
PlotResult draw_plots(const std::vector<PlotScript>& scripts, const std::filesystem::path& plots_dir,
                      const std::string& program);

// The start of every script: SVG terminal of this size, output NAME.svg, '?' as missing data, a light grid, the
// legend inside the plot (top right, on white, framed).
// `drawn_by` names the command in the script's first comment ("vssw report").
std::string gp_preamble(const std::string& drawn_by, const std::string& name, int width, int height);
// A gnuplot string literal (double quotes, its quotes and backslashes escaped).
std::string gp_string(const std::string& text);
// A number for a data file; '?' (declared missing) for NaN, infinity and, on log axes, what is not positive.
std::string gp_number(double v, bool positive_only = false);

// The plots that were made, grouped under a level-3 heading per section in the order sections first appear.
std::vector<DocBlock> plot_blocks(const PlotResult& plots);

}  // namespace vssw::study

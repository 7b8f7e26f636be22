#pragma once
// Plots drawn by gnuplot to SVG, each beside the .gp script and .dat data that made it (so that `cd plots && gnuplot
// NAME.gp` re-draws it). Scripts and data are written through AtomicFile; gnuplot runs once per script in the plots
// folder; a plot whose SVG is missing or empty afterwards counts as failed and its SVG is removed. When gnuplot cannot
// be run at all the scripts and data are still written and the result says why, for a warning: a missing gnuplot never
// fails a report or a study.
#include <filesystem>
#include <string>
#include <vector>

#include "io/document.hpp"

namespace vssw::io {

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

// Writes every script and its data into plots_dir (created), runs `program` (looked up in PATH unless it holds a
// '/') on each and gives each SVG made native tooltips (svg_native_tooltips).
PlotResult draw_plots(const std::vector<PlotScript>& scripts, const std::filesystem::path& plots_dir,
                      const std::string& program);

// The one font of every plot's text (terminal, titles, keys, labels, tics), for the report's, a study's and a bench's
// plots alike: `font 'sans,11'`. gp_preamble sets it on the terminal; a script that sets a text's font (a legend
// panel's key) uses this, never a size of its own, so that plots side by side on a page read at one size.
std::string gp_font();

// The start of every script: SVG terminal of this size in gp_font(), output NAME.svg, '?' as missing data, a light
// grid, the legend below the plot's frame, in columns and framed: outside the data, never hiding a line. Not right of
// the frame: gnuplot leaves out a right-hand key whose titles do not fit that margin. (A plot that sets its own key
// position keeps it outside: `set key left` then puts it left of the frame.)
// `drawn_by` names the command in the script's first comment ("vssw report").
std::string gp_preamble(const std::string& drawn_by, const std::string& name, int width, int height);
// `set xlabel TEXT`, the text as gp_string has it. With key_below (the preamble's key, not unset by the plot) the label
// gets an empty second line: gnuplot puts the top of a key below the frame on the x label's baseline, so the key's box
// touched the label's descenders ("t [s]" on the trace plots); the empty line keeps a line's height between them.
std::string gp_xlabel(const std::string& text, bool key_below = true);

// Values on hover. A plot draws its visible markers as usual, then gp_hover_layer over them: the same points as
// gnuplot `labels hypertext`, drawn with the same marker (`style`: pt, ps and lc as the visible series has them) and
// notitle, so the plot and its legend look the same. gnuplot's SVG terminal writes each such point as a group that
// calls its JavaScript (gnuplot_svg.showHypertext), which vssw's pages do not load; draw_plots turns every group into a
// native SVG tooltip (svg_native_tooltips), which needs no script. Not on plots of thousands of points (the trace
// plots): a group per point would make the SVG, inlined in the page, several times larger.
// `source` is the data and its using spec, with the hover text as the third column: "'NAME.dat' index 2 using
// 1:2:(stringcolumn(3))".
std::string gp_hover_layer(const std::string& source, const std::string& style);
// The hover text of a point as a data file's label column (gp_data_string): "SERIES, WHERE: VALUE UNIT", the value to
// 4 significant digits; "SERIES, WHERE: no value" for NaN or infinity.
std::string gp_hover_text(const std::string& series, const std::string& where, double value, const std::string& unit);
// The SVG of a plot gnuplot wrote, with native tooltips: each hypertext group (`<g onmousemove="gnuplot_svg.
// showHypertext(evt,'TEXT')" onmouseout="..."><title> </title>`) becomes `<g><title>TEXT</title>`, TEXT XML-escaped
// again after gnuplot's own escaping is undone; gnuplot's meaningless group titles (`gnuplot_plot_3`, shown on
// hovering a line) are dropped and the document's title ("Gnuplot") becomes `title`. Nothing else changes.
std::string svg_native_tooltips(const std::string& svg, const std::string& title);
// Any text (a record's file name, a suite's wall name, a study's name) as a gnuplot string literal that shows it as it
// is and never runs: single-quoted, where gnuplot substitutes neither `command` nor @macro (in double quotes it runs
// the backquoted command in a shell), its ' doubled, and every control character (newline, CR, tab, DEL, ...) a
// space, since a newline would end the command and start another ("!cmd" runs a shell).
std::string gp_string(const std::string& text);
// Text for a comment line ("# TEXT") of a script or a data file: control characters as spaces, so that it stays one
// line, and a space after a final backslash, which would continue a script's comment over the next command.
std::string gp_comment(const std::string& text);
// A label column in a data file, for people reading it (gnuplot takes the labels from the script, gp_string): double
// quotes, inside which gnuplot reads a \" or \\ its own way, so quotes become ' and backslashes '/', and control
// characters spaces; always one column.
std::string gp_data_string(const std::string& text);
// Whether a plot's name is a plain file stem ([A-Za-z0-9._-], not starting with '.' or '-'): the names are written
// into scripts unquoted (`plot 'NAME.dat'`) and used as file names, so draw_plots refuses any other.
bool gp_safe_name(const std::string& name);
// A number for a data file; '?' (declared missing) for NaN, infinity and, on log axes, what is not positive.
std::string gp_number(double v, bool positive_only = false);

// The plots that were made, grouped under a level-3 heading per section in the order sections first appear.
std::vector<DocBlock> plot_blocks(const PlotResult& plots);

}  // namespace vssw::io

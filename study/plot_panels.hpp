#pragma once
// Small multiples for a study's plots (study/study_plots.hpp): which parameters get a panel (or a plot) of their own
// and which are summarised, the rows of one panel, the series' line styles, and the gnuplot layout of the panels with
// one legend for all of them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "study/study_data.hpp"
#include "io/palette.hpp"  // series_style, series_variants: every plot panel draws with them

namespace vssw::study {

// A plot holds at most this many panels, and a study draws at most this many plots of one kind per metric and record:
// twelve panels of 380 x 270 px still read on a screen, and more plots than that are more than anyone looks at.
constexpr std::size_t kMaxPanels = 12;

// The parameters that get a panel each (`split`: the first of `candidates`, in order, while the product of their
// level counts stays within `limit`) and those summarised in every panel (`rest`).
struct PanelSplit {
    std::vector<std::size_t> split, rest;
};
PanelSplit split_panels(const StudyData& d, const std::vector<std::size_t>& candidates, std::size_t limit);

// Every combination of the columns' levels (one empty combination for no columns), the last column varying fastest.
std::vector<std::vector<std::uint32_t>> combinations(const StudyData& d, const std::vector<std::size_t>& columns);
// Whether the row is at these levels of these columns (a column that does not apply to it: at every level).
// The positions in combinations(d, columns) of every combination the row is at (several when a column does not apply to
// it).
std::vector<std::size_t> combination_indices(const StudyData& d, const StudyRow& row,
                                             const std::vector<std::size_t>& columns);
// The position of a level in its column's order.
std::size_t level_position(const ColumnLevels& column, std::uint32_t level);
// "thickness 0.356, xi 0.1" ("" for no columns).
std::string levels_title(const StudyData& d, const std::vector<std::size_t>& columns,
                         const std::vector<std::uint32_t>& levels);
// " (median over hinge, xi)" when values are summarised ("share" for a 0/1 metric); "" when nothing is.
std::string summary_note(const StudyData& d, const std::vector<std::size_t>& rest, bool share);
// What one point shows of several values: their median, or for a 0/1 metric the share of ones; NaN for none.
double summarise(const std::vector<double>& values, bool share);

// The SVG size and gnuplot's multiplot layout for `panels` panels and, when there are several, a last panel that
// holds only the legend. A single panel is a plain plot with its key inside.
struct PanelLayout {
    std::size_t panels = 1, columns = 1, rows = 1;
    int width = 0, height = 0;
    bool multiplot() const { return panels > 1; }
};
PanelLayout panel_layout(std::size_t panels);
// After gp_preamble: the multiplot's title and layout, or the single plot's title.
std::string layout_begin(const PanelLayout& layout, const std::string& title);
// Before each panel's plot command (nothing for a single plot).
std::string panel_begin(const PanelLayout& layout, const std::string& title);
// The legend panel and the end of the multiplot (nothing for a single plot). Entries: (title, style) drawn as a line
// with points; `extra` is added verbatim to the plot command (e.g. an "overturned" marker entry).
std::string layout_end(const PanelLayout& layout, const std::vector<std::pair<std::string, std::string>>& entries,
                       const std::string& extra = "");

}  // namespace vssw::study

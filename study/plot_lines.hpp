#pragma once
// A figure of lines in small multiples (study/plot_panels.hpp) as a gnuplot script and its data: the value plots and
// the rocking curves of a study are both one.
#include <string>
#include <utility>
#include <vector>

#include "io/gnuplot.hpp"

namespace vssw::study {

struct LineFigure {
    std::string section, name, title, xlabel, ylabel;
    std::vector<std::string> panel_titles;                    // one per panel
    std::vector<std::pair<std::string, std::string>> lines;  // label and style (series_style), one per line
    std::vector<double> x;                                    // the points' x (a category's position for categories)
    std::vector<std::string> categories;                      // when x are categories: their tic labels
    // y[panel][line][point] (NaN: no value there); marked[...] true: an open circle on the point (e.g. overturned).
    std::vector<std::vector<std::vector<double>>> y;
    std::vector<std::vector<std::vector<bool>>> marked;
    std::string marker_title;  // the legend's word for the circle ("overturned"); "" when nothing is marked
    std::string setup;         // gnuplot lines before the panels (ranges, reference lines)
    // The hover text's words (gnuplot.hpp, gp_hover_text): "LINE, XNAME X: Y YUNIT" on every point.
    std::string xname, yunit;
    // When either is > 0, each panel's y axis spans at least this share of its largest |y|, and at least min_abs_span,
    // around its values' middle (a panel whose values agree to 7 digits would otherwise magnify rounding into a slope,
    // its tic labels all alike); both 0 leave the range to gnuplot or `setup`.
    double min_span = 0.0, min_abs_span = 0.0;

    // y and marked sized for these panels, lines and points, all NaN and unmarked.
    void resize();
    bool any_value() const;
};

// The figure's .gp and .dat: a block of (x, y, marked, hover text) per panel and line, a hover layer over each line's
// markers, the panel's lines drawn from it, a panel
// without any value labelled so (gnuplot refuses to autoscale nothing).
io::PlotScript line_figure_script(const LineFigure& figure);

}  // namespace vssw::study

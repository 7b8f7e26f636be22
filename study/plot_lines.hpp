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

    // y and marked sized for these panels, lines and points, all NaN and unmarked.
    void resize();
    bool any_value() const;
};

// The figure's .gp and .dat: a block of (x, y, marked) per panel and line, the panel's lines drawn from it, a panel
// without any value labelled so (gnuplot refuses to autoscale nothing).
PlotScript line_figure_script(const LineFigure& figure);

}  // namespace vssw::study

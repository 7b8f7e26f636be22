#include "study/plot_lines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "study/overturned_runs.hpp"  // kOverturnedRing
#include "study/plot_panels.hpp"

namespace vssw::study {
namespace {

// Categories sit at 0, 1, ...: half a category of room on either side keeps the first and last off the frame.
constexpr double kCategoryMargin = 0.5;

bool panel_has_value(const LineFigure& f, std::size_t p) {
    for (const auto& line : f.y[p])
        for (double v : line)
            if (std::isfinite(v)) return true;
    return false;
}

// A point's x in its hover text: its category, or its value.
std::string x_text(const LineFigure& f, std::size_t i) {
    const std::string x = i < f.categories.size() ? f.categories[i] : fmt::format("{:g}", f.x[i]);
    return f.xname.empty() ? x : f.xname + " " + x;
}

std::string data_of(const LineFigure& f) {
    std::string dat = fmt::format("# {}\n# x y marked hover_text   (one block per panel and line, in that order)\n",
                                  io::gp_comment(f.title));
    for (std::size_t p = 0; p < f.y.size(); ++p)
        for (std::size_t l = 0; l < f.lines.size(); ++l) {
            dat += fmt::format("# panel {}: {}; line {}: {}\n", p + 1, io::gp_comment(f.panel_titles[p]), l + 1,
                               io::gp_comment(f.lines[l].first));
            for (std::size_t i = 0; i < f.x.size(); ++i)
                dat += fmt::format("{} {} {} {}\n", io::gp_number(f.x[i]), io::gp_number(f.y[p][l][i]),
                                   f.marked[p][l][i] ? 1 : 0,
                                   io::gp_hover_text(f.lines[l].first, x_text(f, i), f.y[p][l][i], f.yunit));
            dat += "\n\n";
        }
    return dat;
}

// The panel's y range when its values span less than f.min_span of their largest |y| or f.min_abs_span, around their
// middle; else gnuplot's autoscale (an earlier panel may have set a range).
std::string panel_range(const LineFigure& f, std::size_t p) {
    if (f.min_span <= 0.0 && f.min_abs_span <= 0.0) return "";
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& line : f.y[p])
        for (double v : line)
            if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    const double span = std::max(f.min_span * std::max(std::abs(lo), std::abs(hi)), f.min_abs_span);
    const double middle = 0.5 * (lo + hi);
    if (!(hi >= lo) || !(hi - lo < span)) return "set autoscale y\n";  // no value, or a span of their own
    return fmt::format("set yrange [{}:{}]\n", io::gp_number(middle - 0.5 * span), io::gp_number(middle + 0.5 * span));
}

std::string panel_plot(const LineFigure& f, const PanelLayout& layout, std::size_t p) {
    std::string s = panel_begin(layout, f.panel_titles[p]) + panel_range(f, p);
    if (!panel_has_value(f, p))
        return s + "set label 1 'no value' at graph 0.5, graph 0.5 center\nplot [0:1][0:1] NaN notitle\n"
                   "unset label 1\n";
    std::string cmd;
    bool marker_titled = false;
    for (std::size_t l = 0; l < f.lines.size(); ++l) {
        const std::size_t index = p * f.lines.size() + l;
        cmd += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints {} title {}, \\\n     {}",
                           cmd.empty() ? "plot " : ", \\\n     ", f.name, index, f.lines[l].second,
                           io::gp_string(f.lines[l].first),
                           io::gp_hover_layer(fmt::format("'{}.dat' index {} using 1:2:(stringcolumn(4))", f.name, index),
                                          f.lines[l].second));
        if (f.marker_title.empty()) continue;
        cmd += fmt::format(", \\\n     '{}.dat' index {} using 1:($3 > 0.5 ? $2 : NaN) with points {} {}",
                           f.name, index, kOverturnedRing,
                           marker_titled ? "notitle" : "title " + io::gp_string(f.marker_title));
        marker_titled = true;
    }
    return s + cmd + "\n";
}

}  // namespace

void LineFigure::resize() {
    y.assign(panel_titles.size(),
             std::vector<std::vector<double>>(lines.size(), std::vector<double>(x.size(), std::nan(""))));
    marked.assign(panel_titles.size(),
                  std::vector<std::vector<bool>>(lines.size(), std::vector<bool>(x.size(), false)));
}

bool LineFigure::any_value() const {
    for (std::size_t p = 0; p < y.size(); ++p)
        if (panel_has_value(*this, p)) return true;
    return false;
}

io::PlotScript line_figure_script(const LineFigure& f) {
    const PanelLayout layout = panel_layout(f.panel_titles.size());
    std::string gp = io::gp_preamble("vssw study", f.name, layout.width, layout.height) +
                     io::gp_xlabel(f.xlabel, !layout.multiplot()) +
                     fmt::format("set ylabel {}\nset format y '%.4g'\n", io::gp_string(f.ylabel));
    if (!f.categories.empty()) {
        std::vector<std::string> tics;
        for (std::size_t i = 0; i < f.categories.size(); ++i)
            tics.push_back(fmt::format("{} {}", io::gp_string(f.categories[i]), i));
        gp += fmt::format("set xtics ({})\nset xrange [{}:{}]\nset offsets 0, 0, graph 0.05, graph 0.05\n",
                          fmt::join(tics, ", "), -kCategoryMargin,
                          static_cast<double>(f.categories.size()) - 1.0 + kCategoryMargin);
    } else {
        gp += "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n";
    }
    gp += f.setup + layout_begin(layout, f.title);
    for (std::size_t p = 0; p < f.panel_titles.size(); ++p) gp += panel_plot(f, layout, p);
    std::vector<std::pair<std::string, std::string>> entries = f.lines;
    const std::string marker =
        f.marker_title.empty() ? "" : fmt::format("NaN with points {} title {}", kOverturnedRing,
                                                  io::gp_string(f.marker_title));
    gp += layout_end(layout, entries, marker);
    return {{f.section, f.name, f.title, false}, gp, data_of(f)};
}

}  // namespace vssw::study

#include "study/plot_panels.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>

#include <fmt/format.h>

#include "study/effects.hpp"
#include "io/gnuplot.hpp"
#include "io/palette.hpp"

namespace vssw::study {
namespace {

// One panel of a multiplot in SVG pixels, and the room its title takes; a single plot is wider for its outside key.
constexpr int kPanelWidth = 380, kPanelHeight = 270, kTitleHeight = 40;
constexpr int kSingleWidth = 860, kSingleHeight = 440;
// Panels per row: four of 380 px fill a 1520 px page, about what a report's width allows.
constexpr std::size_t kMaxColumns = 4;

}  // namespace

PanelSplit split_panels(const StudyData& d, const std::vector<std::size_t>& candidates, std::size_t limit) {
    PanelSplit s;
    std::size_t product = 1;
    for (std::size_t c : candidates) {
        const std::size_t n = std::max<std::size_t>(1, d.columns[c].order.size());
        if (product * n <= limit && s.rest.empty()) {
            s.split.push_back(c);
            product *= n;
        } else {
            s.rest.push_back(c);
        }
    }
    return s;
}

std::vector<std::vector<std::uint32_t>> combinations(const StudyData& d, const std::vector<std::size_t>& columns) {
    std::vector<std::vector<std::uint32_t>> out = {{}};
    for (std::size_t c : columns) {
        std::vector<std::vector<std::uint32_t>> next;
        for (const auto& combo : out)
            for (std::uint32_t level : d.columns[c].order) {
                next.push_back(combo);
                next.back().push_back(level);
            }
        out = std::move(next);
    }
    return out;
}

std::size_t level_position(const ColumnLevels& column, std::uint32_t level) {
    return static_cast<std::size_t>(std::find(column.order.begin(), column.order.end(), level) - column.order.begin());
}

std::vector<std::size_t> combination_indices(const StudyData& d, const StudyRow& row,
                                             const std::vector<std::size_t>& columns) {
    std::vector<std::size_t> out = {0};
    for (std::size_t c : columns) {
        const ColumnLevels& col = d.columns[c];
        const std::size_t n = col.order.size();
        std::vector<std::size_t> next;
        for (std::size_t base : out) {
            if (row.levels[c] != kEmptyLevel) {
                next.push_back(base * n + level_position(col, row.levels[c]));
                continue;
            }
            for (std::size_t k = 0; k < n; ++k) next.push_back(base * n + k);
        }
        out = std::move(next);
    }
    return out;
}

std::string levels_title(const StudyData& d, const std::vector<std::size_t>& columns,
                         const std::vector<std::uint32_t>& levels) {
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < columns.size(); ++i) {
        const ColumnLevels& c = d.columns[columns[i]];
        const std::string& text = c.texts[levels[i]];
        // A record by its file's name: its folder is the same for all and makes a title too long to read.
        parts.push_back(fmt::format("{} {}", c.key,
                                    c.key == "file" ? std::filesystem::path(text).filename().string() : text));
    }
    return fmt::format("{}", fmt::join(parts, ", "));
}

std::string summary_note(const StudyData& d, const std::vector<std::size_t>& rest, bool share) {
    if (rest.empty()) return "";
    std::vector<std::string> keys;
    for (std::size_t c : rest) keys.push_back(d.columns[c].key);
    return fmt::format(" ({} over {})", share ? "share" : "median", fmt::join(keys, ", "));
}

double summarise(const std::vector<double>& values, bool share) {
    if (values.empty()) return std::nan("");
    if (!share) return median(values);
    double ones = 0.0;
    for (double v : values) ones += v;
    return ones / static_cast<double>(values.size());
}

PanelLayout panel_layout(std::size_t panels) {
    PanelLayout l;
    l.panels = std::max<std::size_t>(1, panels);
    if (!l.multiplot()) {
        l.width = kSingleWidth;
        l.height = kSingleHeight;
        return l;
    }
    const std::size_t slots = l.panels + 1;  // the legend's
    l.columns = std::min(kMaxColumns, static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(slots)))));
    l.rows = (slots + l.columns - 1) / l.columns;
    l.width = kPanelWidth * static_cast<int>(l.columns);
    l.height = kPanelHeight * static_cast<int>(l.rows) + kTitleHeight;
    return l;
}

std::string layout_begin(const PanelLayout& layout, const std::string& title) {
    if (!layout.multiplot()) return fmt::format("set title {}\n", io::gp_string(title));
    return fmt::format("unset key\nset multiplot layout {},{} title {}\n", layout.rows, layout.columns,
                       io::gp_string(title));
}

std::string panel_begin(const PanelLayout& layout, const std::string& title) {
    return layout.multiplot() ? fmt::format("set title {}\n", io::gp_string(title)) : "";
}

std::string layout_end(const PanelLayout& layout, const std::vector<std::pair<std::string, std::string>>& entries,
                       const std::string& extra) {
    if (!layout.multiplot()) return "";
    std::string s =
        "unset title\nunset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\nunset colorbox\n"
        "unset arrow\nset lmargin 0\nset rmargin 0\nset xrange [0:1]\nset yrange [0:1]\n"
        "set key left center vertical reverse Left samplen 2 noautotitle\n";  // in the plots' one font
    std::string cmd;
    for (const auto& [title, style] : entries)
        cmd += fmt::format("{}NaN with linespoints {} title {}", cmd.empty() ? "plot " : ", \\\n     ", style,
                           io::gp_string(title));
    if (!extra.empty()) cmd += (cmd.empty() ? "plot " : ", \\\n     ") + extra;
    return s + cmd + "\nunset multiplot\n";
}

}  // namespace vssw::study

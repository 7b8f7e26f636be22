// Value plots: each metric against each varied parameter (study/study_plots.hpp).
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "analytic/simulate.hpp"  // SimulationOptions::energy_ceiling
#include "compare/metric_catalog.hpp"
#include "compare/targets.hpp"
#include "study/overturned_runs.hpp"
#include "study/plot_lines.hpp"
#include "study/plot_panels.hpp"
#include "study/spec.hpp"
#include "study/study_plots.hpp"
#include "io/text.hpp"

namespace vssw::study {
namespace {

// A value plot's y axis spans at least +- the metric's target around its values' middle (relative to their largest
// |value|; compare/targets.hpp: threshold and period 0.5 %, restitution 2 %; a metric without one the smallest, 0.5 %):
// differences below the accuracy asked of an engine are rounding and noise, not a trend to read, and they look flat.
// With it the '%.4g' tic labels stay apart (tics a fifth of the span: 2e-3 of it at the smallest).
double min_value_span(const std::string& metric) {
    const double smallest = std::min({compare::kThresholdTarget, compare::kPeriodTarget, compare::kRestitutionTarget});
    const compare::MetricInfo* m = compare::find_metric(metric);
    return 2.0 * (m && m->target > 0.0 ? m->target : smallest);
}

// A line of a value plot: a series, with the x parameter left out of the analytic ones when it is an assumption (the
// line then runs across that assumption's levels).
struct ValueLine {
    Series series;
    std::string label;
};

std::vector<ValueLine> value_lines(const StudyData& d, std::size_t x, const std::vector<std::size_t>& ignored) {
    std::vector<ValueLine> lines;
    std::set<std::string> seen;
    for (const Series& s : d.series) {
        Series projected = s;
        for (std::size_t i = 0; i < kAssumptionKeys.size(); ++i)
            if (d.assumption_columns[i] == x) projected.assumptions[i].clear();
        const std::string key = fmt::format("{}\n{}\n{}", projected.engine, projected.settings,
                                            fmt::join(projected.assumptions, "\n"));
        if (seen.insert(key).second) lines.push_back({projected, d.series_label(s, ignored)});
    }
    return lines;
}

// The parameters a value plot of x gets panels for: the other varied wall and excitation parameters.
std::vector<std::size_t> panel_candidates(const StudyData& d, std::size_t x) {
    std::vector<std::size_t> out;
    for (std::size_t c : d.varied())
        if (c != x && !d.columns[c].assumption) out.push_back(c);
    return out;
}

// The metric's values bucketed by panel, line and x level, then summarised into the figure. A peak rotation of an
// overturned run (its collapse angle) counts and is drawn as the rocking curves draw it (study/overturned_runs.hpp).
void fill_values(const StudyData& d, std::size_t metric, std::size_t x, const PanelSplit& split,
                 const std::vector<ValueLine>& lines, const std::vector<std::size_t>& ignored,
                 const Overturning* over, LineFigure& f) {
    const ColumnLevels& xc = d.columns[x];
    std::vector<std::vector<std::vector<std::vector<double>>>> buckets(
        f.panel_titles.size(),
        std::vector<std::vector<std::vector<double>>>(lines.size(), std::vector<std::vector<double>>(f.x.size())));
    for (const StudyRow& r : d.rows) {
        if (r.metric != metric || !std::isfinite(r.value)) continue;
        std::vector<std::size_t> points;
        if (r.levels[x] != kEmptyLevel) points.push_back(level_position(xc, r.levels[x]));
        else
            for (std::size_t k = 0; k < f.x.size(); ++k) points.push_back(k);
        const std::vector<std::size_t> panels = combination_indices(d, r, split.split);
        for (std::size_t l = 0; l < lines.size(); ++l) {
            if (!d.in_series(r, lines[l].series, ignored)) continue;
            const double value = over != nullptr && over->overturned(r) ? kOverturnedPeak : r.value;
            for (std::size_t p : panels)
                for (std::size_t k : points) buckets[p][l][k].push_back(value);
        }
    }
    const bool share = d.metrics[metric].binary;
    for (std::size_t p = 0; p < buckets.size(); ++p)
        for (std::size_t l = 0; l < lines.size(); ++l)
            for (std::size_t k = 0; k < f.x.size(); ++k) {
                if (over == nullptr) {
                    f.y[p][l][k] = summarise(buckets[p][l][k], share);
                    continue;
                }
                if (buckets[p][l][k].empty()) continue;
                const auto [value, overturned] = peak_point(buckets[p][l][k]);
                f.y[p][l][k] = value;
                f.marked[p][l][k] = overturned;
            }
}

// Empty when the metric has no value to draw against x.
std::optional<io::PlotScript> value_plot(const StudyData& d, std::size_t metric, std::size_t x) {
    const ColumnLevels& xc = d.columns[x];
    const MetricMeta& m = d.metrics[metric];
    const std::vector<std::size_t> ignored = xc.assumption ? std::vector<std::size_t>{x} : std::vector<std::size_t>{};
    const std::vector<ValueLine> lines = value_lines(d, x, ignored);
    const PanelSplit split = split_panels(d, panel_candidates(d, x), kMaxPanels);

    LineFigure f;
    f.section = kValueSection;
    f.name = io::file_stem(fmt::format("value_{}_vs_{}", m.name, xc.key));
    f.title = fmt::format("{} against {}{}", m.name, xc.key, summary_note(d, split.rest, m.binary));
    f.xlabel = parameter_label(xc.key);
    f.ylabel = m.binary ? m.name + " (share of runs)" : metric_label(m);
    f.xname = xc.key;
    f.yunit = m.binary ? "share of runs" : m.unit;
    // A share runs from 0 to 1 whatever its values; a value's axis is never narrower than its target allows.
    if (m.binary) f.setup = "set yrange [-0.05:1.05]\n";
    else f.min_span = min_value_span(m.name);
    // A run's energy balance error is a relative error that passes up to the ceiling simulate() allows (1e-6): below
    // that it is the integrator's round-off, which would fill the axis.
    if (m.name == "energy_balance_error") f.min_abs_span = SimulationOptions{}.energy_ceiling;
    for (const auto& combo : combinations(d, split.split))
        f.panel_titles.push_back(split.split.empty() ? f.title : levels_title(d, split.split, combo));
    std::vector<std::string> engines;
    for (const ValueLine& line : lines) engines.push_back(line.series.engine);
    const std::vector<std::size_t> variants = io::series_variants(engines);
    for (std::size_t l = 0; l < lines.size(); ++l)
        f.lines.push_back({lines[l].label, io::series_style(lines[l].series.engine, variants[l])});
    for (std::size_t k = 0; k < xc.order.size(); ++k) {
        f.x.push_back(xc.numeric ? xc.values[xc.order[k]] : static_cast<double>(k));
        if (!xc.numeric) f.categories.push_back(xc.texts[xc.order[k]]);
    }
    // The peak rotation of an overturned run: at 1, ringed ("overturned" in the legend), as in the rocking curves.
    const Overturning overturning(d);
    const Overturning* over = m.name == "peak_rotation" && overturning.measured() ? &overturning : nullptr;
    if (over != nullptr) {
        f.marker_title = "overturned";
        f.setup += "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb '#999999'\n";
    }
    f.resize();
    fill_values(d, metric, x, split, lines, ignored, over, f);
    if (!f.any_value()) return std::nullopt;
    return line_figure_script(f);
}

}  // namespace

void add_value_plots(const StudyData& d, StudyPlots& out) {
    std::size_t drawn = 0, left_out = 0;
    for (std::size_t m = 0; m < d.metrics.size(); ++m) {
        if (!d.metrics[m].any_value) {
            out.notes.push_back(fmt::format("{} has no value in any row: it is not plotted.", d.metrics[m].name));
            continue;
        }
        for (std::size_t x : d.varied()) {
            if (d.columns[x].order.size() < 2) continue;
            if (drawn == kMaxValuePlots) {
                ++left_out;
                continue;
            }
            if (std::optional<io::PlotScript> s = value_plot(d, m, x)) {
                out.scripts.push_back(std::move(*s));
                ++drawn;
            }
        }
    }
    if (left_out > 0)
        out.notes.push_back(fmt::format("{} value plot{} (metric against parameter) not drawn: a study draws at most "
                                        "{}.",
                                        left_out, left_out == 1 ? "" : "s", kMaxValuePlots));
}

}  // namespace vssw::study

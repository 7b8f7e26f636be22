// The response plots of record and pulse studies (study/study_plots.hpp): rocking curves as the paper's Fig. 10/11,
// and overturning maps.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "study/overturned_runs.hpp"
#include "study/plot_lines.hpp"
#include "study/plot_panels.hpp"
#include "study/study_plots.hpp"
#include "io/text.hpp"

namespace vssw::study {
namespace {

std::optional<std::size_t> metric_index(const StudyData& d, const std::string& name) {
    for (std::size_t m = 0; m < d.metrics.size(); ++m)
        if (d.metrics[m].name == name && d.metrics[m].any_value) return m;
    return std::nullopt;
}

std::optional<std::size_t> varied_column(const StudyData& d, const std::string& key) {
    const std::size_t c = d.column(key);
    if (c == std::string::npos || !d.columns[c].varied || d.columns[c].order.size() < 2) return std::nullopt;
    return c;
}

// The varied wall and excitation parameters other than `drawn`, those in `first` ahead: each combination of the ones
// that fit gets a plot of its own, the others are summarised. The record's file is always among them, varied or not,
// so that it names the plot.
PanelSplit plot_split(const StudyData& d, const std::vector<std::string>& drawn,
                      const std::vector<std::string>& first) {
    std::vector<std::size_t> candidates;
    for (const std::string& key : first)
        if (const std::size_t c = d.column(key);
            c != std::string::npos && (d.columns[c].varied || (key == "file" && !d.columns[c].order.empty())))
            candidates.push_back(c);
    for (std::size_t c : d.varied()) {
        const std::string& key = d.columns[c].key;
        if (d.columns[c].assumption || std::find(drawn.begin(), drawn.end(), key) != drawn.end() ||
            std::find(first.begin(), first.end(), key) != first.end())
            continue;
        candidates.push_back(c);
    }
    return split_panels(d, candidates, kMaxPanels);
}

// A record's part of a plot's name: its file's stem as a file stem, numbered (-1, -2, ...) when two of the study's
// records reduce to the same one (a/r.AT2 and b/r.AT2, or r`x`.AT2 and r-x-.AT2): one plot must not replace another.
std::string record_label(const ColumnLevels& c, std::uint32_t level) {
    const auto stem_of = [&](std::uint32_t l) { return io::file_stem(std::filesystem::path(c.texts[l]).stem().string()); };
    const std::string stem = stem_of(level);
    for (std::uint32_t l = 0; l < c.texts.size(); ++l)
        if (l != level && stem_of(l) == stem) {
            // Numbered by the record's place in the study file (level ids count an empty level first).
            const auto at = std::find(c.order.begin(), c.order.end(), level);
            return fmt::format("{}-{}", stem, at - c.order.begin() + 1);
        }
    return stem;
}

// "rocking_NGA_no_1063_RRS228_pga0.3": the plot's split levels in its name (a record by its file's stem).
std::string split_name(const StudyData& d, const std::string& prefix, const PanelSplit& split,
                       const std::vector<std::uint32_t>& combo) {
    std::string name = prefix;
    for (std::size_t i = 0; i < split.split.size(); ++i) {
        const ColumnLevels& c = d.columns[split.split[i]];
        const std::string& text = c.texts[combo[i]];
        name += "_" + (c.key == "file" ? record_label(c, combo[i]) : c.key + text);
    }
    return io::file_stem(name);
}

io::PlotScript rocking_plot(const StudyData& d, std::size_t peak, const Overturning& over, const PanelSplit& split,
                        std::size_t plot, const std::vector<std::uint32_t>& combo) {
    const std::size_t alpha = d.column("alpha"), R = d.column("R");
    const ColumnLevels& ac = d.columns[alpha];
    const ColumnLevels& rc = d.columns[R];
    const std::size_t panels = std::min(rc.order.size(), kMaxPanels);
    LineFigure f;
    f.section = kRockingSection;
    f.name = split_name(d, "rocking", split, combo);
    const std::string where = levels_title(d, split.split, combo);
    f.title = fmt::format("Rocking curves: peak rotation against alpha{}{}{}{}", where.empty() ? "" : ", ", where,
                          summary_note(d, split.rest, false),
                          panels < rc.order.size() ? fmt::format(" (the first {} R of {})", panels, rc.order.size())
                          : over.measured()        ? ""
                                                   : " (overturning not measured)");
    f.xlabel = parameter_label("alpha");
    f.ylabel = "peak rotation [alpha1]";
    f.xname = "alpha";
    f.yunit = "alpha1";
    for (std::size_t p = 0; p < panels; ++p) f.panel_titles.push_back("R " + rc.texts[rc.order[p]] + " m");
    std::vector<std::string> engines;
    for (const Series& s : d.series) engines.push_back(s.engine);
    const std::vector<std::size_t> variants = io::series_variants(engines);
    for (std::size_t l = 0; l < d.series.size(); ++l)
        f.lines.push_back({d.series[l].label, io::series_style(d.series[l].engine, variants[l])});
    for (std::uint32_t level : ac.order) f.x.push_back(ac.values[level]);
    f.marker_title = over.measured() ? "overturned" : "";
    f.setup = "set xrange [0:*]\nset yrange [0:*]\nset arrow from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc "
              "rgb '#999999'\n";
    f.resize();
    using Buckets = std::vector<std::vector<std::vector<double>>>;  // line -> point -> peaks
    std::vector<Buckets> peaks(panels, Buckets(d.series.size(), std::vector<std::vector<double>>(f.x.size())));
    for (const StudyRow& r : d.rows) {
        if (r.metric != peak || !std::isfinite(r.value)) continue;
        const std::vector<std::size_t> plots = combination_indices(d, r, split.split);
        if (std::find(plots.begin(), plots.end(), plot) == plots.end()) continue;
        const std::size_t p = level_position(rc, r.levels[R]), k = level_position(ac, r.levels[alpha]);
        if (p >= panels || k >= f.x.size()) continue;
        for (std::size_t l = 0; l < d.series.size(); ++l)
            if (d.in_series(r, d.series[l])) peaks[p][l][k].push_back(over.overturned(r) ? kOverturnedPeak : r.value);
    }
    for (std::size_t p = 0; p < panels; ++p)
        for (std::size_t l = 0; l < d.series.size(); ++l)
            for (std::size_t k = 0; k < f.x.size(); ++k) {
                if (peaks[p][l][k].empty()) continue;
                const auto [value, overturned] = peak_point(peaks[p][l][k]);
                f.y[p][l][k] = value;
                f.marked[p][l][k] = overturned;
            }
    return line_figure_script(f);
}

// The rocking curves of one physical assumption relaxed under one record: peak rotation against alpha, a panel per
// backend (the analytic model's first), a line per level of the relaxation (the paper's first), every other physical
// assumption at the paper's level (its first), other parameters summarised by their median.
// None when no row of that record has a peak (an ensemble's records measure collapse).
std::optional<io::PlotScript> relaxation_curves(const StudyData& d, std::size_t peak, const Overturning& over,
                                                std::size_t key, std::optional<std::uint32_t> file) {
    const std::size_t alpha = d.column("alpha"), file_column = d.column("file");
    const ColumnLevels& kc = d.columns[key];
    const auto at_papers = [&](const StudyRow& r) {  // every other physical assumption at its first level
        for (std::size_t c = 0; c < d.columns.size(); ++c)
            if (c != key && d.columns[c].physical && d.columns[c].varied && r.levels[c] != kEmptyLevel &&
                r.levels[c] != d.columns[c].order.front())
                return false;
        return true;
    };
    std::vector<double> xs;  // the alphas of the rows drawn, ascending
    for (const StudyRow& r : d.rows)
        if (r.metric == peak && (!file || r.levels[file_column] == *file) && at_papers(r))
            xs.push_back(d.columns[alpha].values[r.levels[alpha]]);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    if (xs.size() < 2) return std::nullopt;  // a curve needs two slendernesses
    const std::size_t panels = std::min(d.series.size(), kMaxPanels);
    LineFigure f;
    f.section = kRelaxationSection;
    const std::string record = file ? record_label(d.columns[file_column], *file) : "";
    f.name = io::file_stem("relaxed_" + kc.key + (record.empty() ? "" : "_" + record));
    f.title = fmt::format("Rocking curves with {} relaxed{}{}: peak rotation against alpha, a line per level (the "
                          "paper's first), a panel per backend",
                          kc.key, record.empty() ? "" : ", ", record);
    f.xlabel = parameter_label("alpha");
    f.ylabel = "peak rotation [alpha1]";
    f.xname = "alpha";
    f.yunit = "alpha1";
    for (std::size_t p = 0; p < panels; ++p) f.panel_titles.push_back(d.series[p].label);
    for (std::size_t l = 0; l < kc.order.size(); ++l)
        f.lines.push_back({fmt::format("{} {}{}", kc.key, kc.texts[kc.order[l]], l == 0 ? " (the paper's)" : ""),
                           // The paper's level black and solid, the others a spare colour each (io/palette.hpp).
                           io::series_style(l == 0 ? "analytic" : fmt::format("relaxed level {}", l), 0)});
    f.x = xs;
    f.marker_title = over.measured() ? "overturned" : "";
    f.setup = "set xrange [0:*]\nset yrange [0:*]\nset arrow from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc "
              "rgb '#999999'\n";
    f.resize();
    using Buckets = std::vector<std::vector<std::vector<double>>>;  // level -> point -> peaks
    std::vector<Buckets> peaks(panels, Buckets(kc.order.size(), std::vector<std::vector<double>>(xs.size())));
    for (const StudyRow& r : d.rows) {
        if (r.metric != peak || !std::isfinite(r.value) || (file && r.levels[file_column] != *file) || !at_papers(r))
            continue;
        const std::size_t l = level_position(kc, r.levels[key]);
        const std::size_t k = static_cast<std::size_t>(
            std::lower_bound(xs.begin(), xs.end(), d.columns[alpha].values[r.levels[alpha]]) - xs.begin());
        if (l >= kc.order.size() || k >= xs.size()) continue;
        for (std::size_t p = 0; p < panels; ++p)
            if (d.in_series(r, d.series[p])) peaks[p][l][k].push_back(over.overturned(r) ? kOverturnedPeak : r.value);
    }
    for (std::size_t p = 0; p < panels; ++p)
        for (std::size_t l = 0; l < kc.order.size(); ++l)
            for (std::size_t k = 0; k < xs.size(); ++k)
                if (!peaks[p][l][k].empty()) {
                    const auto [value, overturned] = peak_point(peaks[p][l][k]);
                    f.y[p][l][k] = value;
                    f.marked[p][l][k] = overturned;
                }
    return line_figure_script(f);
}

// The overturning map of one plot: a panel per series (the first kMaxPanels), a point per amplitude and pulse period.
io::PlotScript map_plot(const StudyData& d, std::optional<std::size_t> peak, const Overturning& over,
                    const PanelSplit& split, std::size_t plot, const std::vector<std::uint32_t>& combo) {
    const std::size_t amp = d.column("amplitude"), period = d.column("pulse_period");
    const ColumnLevels& ac = d.columns[amp];
    const ColumnLevels& pc = d.columns[period];
    const std::size_t panels = std::min(d.series.size(), kMaxPanels), points = ac.order.size() * pc.order.size();
    // Per panel and point: the peaks (an overturned run as the largest) and the overturned verdicts.
    std::vector<std::vector<std::vector<double>>> peaks(panels, std::vector<std::vector<double>>(points)),
        verdicts(panels, std::vector<std::vector<double>>(points));
    for (const StudyRow& r : d.rows) {
        const bool is_peak = peak && r.metric == *peak;
        if (!is_peak && !(over.measured() && !peak)) continue;
        if (!std::isfinite(r.value)) continue;
        const std::vector<std::size_t> plots = combination_indices(d, r, split.split);
        if (std::find(plots.begin(), plots.end(), plot) == plots.end()) continue;
        const std::size_t k =
            level_position(ac, r.levels[amp]) * pc.order.size() + level_position(pc, r.levels[period]);
        if (k >= points) continue;
        for (std::size_t l = 0; l < panels; ++l) {
            if (!d.in_series(r, d.series[l])) continue;
            if (is_peak) peaks[l][k].push_back(over.overturned(r) ? kOverturnedPeak : r.value);
            else verdicts[l][k].push_back(over.overturned(r) ? 1.0 : 0.0);
        }
    }
    io::PlotScript s;
    s.plot.section = kMapSection;
    s.plot.name = split_name(d, "overturning_map", split, combo);
    const std::string where = levels_title(d, split.split, combo);
    s.plot.title = fmt::format("Overturning map: {}{}{}{}{}",
                               peak ? "peak rotation (capped at 1)" : "overturned or not",
                               where.empty() ? "" : ", ", where, summary_note(d, split.rest, false),
                               panels < d.series.size() ? fmt::format(" (the first {} series of {})", panels,
                                                                      d.series.size())
                                                        : "");
    s.dat = "# pulse_period amplitude peak_capped overturned   (one block per series)\n";
    for (std::size_t l = 0; l < panels; ++l) {
        s.dat += fmt::format("# {}\n", io::gp_comment(d.series[l].label));
        for (std::size_t k = 0; k < points; ++k) {
            double shown = std::nan("");
            bool overturned = false;
            if (peak && !peaks[l][k].empty()) std::tie(shown, overturned) = peak_point(peaks[l][k]);
            if (!peak && !verdicts[l][k].empty()) overturned = summarise(verdicts[l][k], true) > 0.5;
            const bool any = !(peak ? peaks[l][k] : verdicts[l][k]).empty();
            // The last column: 1 overturned, 0 standing, -1 no run there.
            s.dat += fmt::format("{} {} {} {}\n", io::gp_number(pc.values[pc.order[k % pc.order.size()]]),
                                 io::gp_number(ac.values[ac.order[k / pc.order.size()]]),
                                 io::gp_number(peak ? std::min(shown, 1.0) : std::nan("")),
                                 any ? (overturned ? 1 : 0) : -1);
        }
        s.dat += "\n\n";
    }
    const PanelLayout layout = panel_layout(panels);
    s.gp = io::gp_preamble("vssw study", s.plot.name, layout.width, layout.height) +
           io::gp_xlabel(parameter_label("pulse_period"), !layout.multiplot()) +
           fmt::format("set ylabel {}\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
                       "set palette defined (0 '#2c7bb6', 0.5 '#ffffbf', 1 '#d7191c')\nset cbrange [0:1]\n"
                       "set cblabel 'peak rotation / alpha1 (capped at 1)'\n",
                       io::gp_string(parameter_label("amplitude"))) +
           layout_begin(layout, s.plot.title);
    const std::string standing =
        peak ? "with points pt 7 ps 1.6 lc palette" : "with points pt 7 ps 1.6 lc rgb '#2c7bb6'";
    const std::string overturned = "with points pt 2 ps 1.6 lw 2 lc rgb 'black'";
    for (std::size_t l = 0; l < panels; ++l) {
        s.gp += panel_begin(layout, d.series[l].label);
        s.gp += fmt::format("plot '{0}.dat' index {1} using 1:($4 == 0 ? $2 : NaN){2} {3} title 'standing', \\\n"
                            "     '{0}.dat' index {1} using 1:($4 == 1 ? $2 : NaN) {4} title 'overturned'\n",
                            s.plot.name, l, peak ? ":3" : "", standing, overturned);
    }
    s.gp += layout_end(layout, {}, "NaN " + overturned + " title 'overturned'");
    return s;
}

}  // namespace

void add_rocking_curves(const StudyData& d, StudyPlots& out) {
    if (d.kind != "record") return;
    const std::optional<std::size_t> peak = metric_index(d, "peak_rotation");
    if (!peak || !varied_column(d, "alpha") || d.column("R") == std::string::npos) {
        out.notes.push_back("No rocking curves: they need alpha varied (the wall given by alpha and R) and the metric "
                            "peak_rotation.");
        return;
    }
    const Overturning over(d);
    const PanelSplit split = plot_split(d, {"alpha", "R"}, {"file", "scale", "pga"});
    const auto combos = combinations(d, split.split);
    for (std::size_t i = 0; i < combos.size(); ++i)
        out.scripts.push_back(rocking_plot(d, *peak, over, split, i, combos[i]));
}

void add_overturning_maps(const StudyData& d, StudyPlots& out) {
    if (d.kind != "pulse") return;
    const std::optional<std::size_t> peak = metric_index(d, "peak_rotation");
    const Overturning over(d);
    const bool varied = varied_column(d, "amplitude") || varied_column(d, "pulse_period");
    if (!varied || (!peak && !over.measured()) || d.column("amplitude") == std::string::npos ||
        d.column("pulse_period") == std::string::npos) {
        out.notes.push_back("No overturning map: it needs amplitude or pulse_period varied and the metric "
                            "peak_rotation or overturned.");
        return;
    }
    const PanelSplit split = plot_split(d, {"amplitude", "pulse_period"}, {});
    const auto combos = combinations(d, split.split);
    for (std::size_t i = 0; i < combos.size(); ++i) out.scripts.push_back(map_plot(d, peak, over, split, i, combos[i]));
}

// Record rows (of a record study, or a study of several kinds) with alpha varied and a physical assumption relaxed:
// a plot per relaxation and record.
void add_relaxation_curves(const StudyData& d, StudyPlots& out) {
    const std::optional<std::size_t> peak = metric_index(d, "peak_rotation");
    const std::size_t alpha = d.column("alpha");
    if (!peak || alpha == std::string::npos || !d.columns[alpha].varied || !d.columns[alpha].numeric) return;
    const Overturning over(d);
    const std::size_t file = d.column("file");
    std::vector<std::optional<std::uint32_t>> records = {std::nullopt};
    if (file != std::string::npos && !d.columns[file].order.empty())
        records.assign(d.columns[file].order.begin(), d.columns[file].order.end());
    for (std::size_t c = 0; c < d.columns.size(); ++c)
        if (d.columns[c].physical && d.columns[c].varied)
            for (const std::optional<std::uint32_t>& r : records)
                if (std::optional<io::PlotScript> s = relaxation_curves(d, *peak, over, c, r))
                    out.scripts.push_back(std::move(*s));
}

}  // namespace vssw::study

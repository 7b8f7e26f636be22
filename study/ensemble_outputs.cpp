#include "study/ensemble_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "io/csv.hpp"
#include "io/gnuplot.hpp"
#include "study/overturned_runs.hpp"
#include "study/plot_panels.hpp"
#include "study/study_prose.hpp"

namespace vssw::study {

const char* const kEnsembleSection = "Ensemble: fragility and agreement with the reference";

namespace {

// A fragility plot's PGA axis reaches this far past the largest record shown.
constexpr double kAxisMargin = 1.1;

std::string reference_label(const StudyData& d, const EnsembleMeasures& e) {
    return e.has_reference ? d.series[e.reference].label : "";
}

// engine, assumptions (the first two columns of both files).
std::string series_columns(const Series& s) {
    return io::csv_field(s.engine) + "," + io::csv_field(assumptions_text(s));
}

// settings, wall, reference (the last columns of both files).
std::string tail_columns(const StudyData& d, const EnsembleMeasures& e, const SeriesMeasures& m) {
    return fmt::format("{},{},{}", io::csv_field(d.series[m.series].settings), io::csv_field(e.walls[m.wall]),
                       io::csv_field(reference_label(d, e)));
}

std::string interval_columns(const compare::Interval& i) {
    return fmt::format("{},{},{},{}", io::csv_number(i.value), io::csv_number(i.lo), io::csv_number(i.hi), i.n);
}

bool is_reference(const EnsembleMeasures& e, const SeriesMeasures& m) {
    return e.has_reference && m.series == e.reference;
}

std::string level_text(double level) { return fmt::format("{:.6g}", level); }

// A stripe fit's points: each level's share overturned.
std::vector<std::pair<double, double>> stripe_points(const SeriesMeasures& m) {
    std::vector<std::pair<double, double>> out;
    for (const StripeShare& l : m.levels) out.push_back({l.pga, l.share.value});
    return out;
}

// The ECDF of a series' collapse PGAs: the collapsed records' PGAs sorted, each at its rank over all records.
std::vector<std::pair<double, double>> ecdf(const SeriesMeasures& m) {
    std::vector<double> x;
    for (const compare::IdaRecord& r : m.records)
        if (r.collapsed) x.push_back(r.im);
    std::sort(x.begin(), x.end());
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 0; i < x.size(); ++i)
        out.push_back({x[i], static_cast<double>(i + 1) / static_cast<double>(m.records.size())});
    return out;
}

struct Styles {
    std::vector<std::size_t> variants;
    std::string of(const StudyData& d, std::size_t s) const {
        return io::series_style(d.series[s].engine, variants[s]);
    }
};

Styles styles_of(const StudyData& d) {
    std::vector<std::string> engines;
    for (const Series& s : d.series) engines.push_back(s.engine);
    return {io::series_variants(engines)};
}

// The legend panel's entries: each series once (a study of several parts lists its runs per part).
std::vector<std::pair<std::string, std::string>> series_entries(const StudyData& d, const Styles& styles) {
    std::vector<std::pair<std::string, std::string>> entries;
    for (std::size_t i = 0; i < d.series.size(); ++i)
        if (!repeats_earlier(d, i)) entries.push_back({d.series[i].label, styles.of(d, i)});
    return entries;
}

// One panel of the fragility plot: per series its curve, the ECDF of its records and its median's interval at 0.5.
std::string fragility_panel(const StudyData& d, const EnsembleMeasures& e, std::size_t wall, const Styles& styles,
                            const std::string& name, std::string& dat, std::size_t& block) {
    double xmax = 0.0;
    std::string cmd;
    std::string unfitted;  // series with data but no fit: named in the key, nothing drawn
    for (const SeriesMeasures& m : e.measures) {
        if (m.wall == wall && m.fitted() && !m.fit.fit.ok())
            unfitted += fmt::format(", \\\n     NaN with lines {} title {}", styles.of(d, m.series),
                                    io::gp_string(d.series[m.series].label + " (no fit)"));
        if (m.wall != wall || !m.fitted() || !m.fit.fit.ok()) continue;
        for (const compare::IdaRecord& r : m.records) xmax = std::max(xmax, r.im);
        for (const StripeShare& l : m.levels) xmax = std::max(xmax, l.pga);
        xmax = std::max(xmax, std::isfinite(m.fit.median.hi) ? m.fit.median.hi : 0.0);
        const std::string style = styles.of(d, m.series);
        dat += fmt::format("# wall {}: {}: {}\n", io::gp_comment(e.walls[wall]), io::gp_comment(d.series[m.series].label),
                           fmt::format(m.ida ? "collapse {}, ECDF" : "stripe {}, share overturned", e.label));
        for (const auto& [x, y] : m.ida ? ecdf(m) : stripe_points(m))
            dat += fmt::format("{} {} {}\n", io::gp_number(x), io::gp_number(y),
                               io::gp_hover_text(d.series[m.series].label, fmt::format("{} {:.4g} {}", e.name, x, e.unit), y,
                                             m.ida ? "collapsed (ECDF)" : "overturned"));
        dat += fmt::format("\n\n# median [{}], 0.5, median_lo, median_hi\n{} 0.5 {} {}\n\n\n", e.unit,
                           io::gp_number(m.fit.median.value), io::gp_number(m.fit.median.lo), io::gp_number(m.fit.median.hi));
        cmd += fmt::format("{}norm(log(x/{})/{}) with lines {} title {}", cmd.empty() ? "plot " : ", \\\n     ",
                           io::gp_number(m.fit.fit.median), io::gp_number(m.fit.fit.beta), style,
                           io::gp_string(d.series[m.series].label));
        const std::string points = fmt::format("'{}.dat' index {} using 1:2", name, block);
        cmd += fmt::format(", \\\n     {0} with points {1} notitle, \\\n     {2}", points, style,
                           io::gp_hover_layer(points + ":(stringcolumn(3))", style));
        cmd += fmt::format(", \\\n     '{}.dat' index {} using 1:2:3:4 with xerrorbars {} notitle", name, block + 1,
                           style);
        block += 2;
    }
    if (cmd.empty()) return "set label 1 'no fit' at graph 0.5, graph 0.5 center\nplot [0:1][0:1] NaN notitle\n"
                            "unset label 1\n";
    // y beyond [0, 1]: a point at a share of 0 or 1 drawn whole, not halved by the frame.
    return fmt::format("set xrange [0:{}]\nset yrange [-0.05:1.05]\n", io::gp_number(kAxisMargin * xmax)) + cmd +
           unfitted + "\n";
}

io::PlotScript fragility_plot(const StudyData& d, const EnsembleMeasures& e) {
    const Styles styles = styles_of(d);
    const PanelLayout layout = panel_layout(e.walls.size());
    io::PlotScript s;
    s.plot = {kEnsembleSection, "fragility",
              "Collapse fragility: lognormal fits (lines), data (points), 95 % interval of the median (bar)",
              false};
    s.dat = "# " + io::gp_comment(s.plot.title) + "\n";
    std::string gp = io::gp_preamble("vssw study", s.plot.name, layout.width, layout.height) +
                     io::gp_xlabel(e.label, !layout.multiplot()) +
                     fmt::format("set ylabel {}\nset samples 300\n", io::gp_string("P(collapse | " + e.name + ")")) +
                     layout_begin(layout, s.plot.title);
    std::size_t block = 0;
    for (std::size_t w = 0; w < e.walls.size(); ++w)
        gp += panel_begin(layout, e.walls[w]) + fragility_panel(d, e, w, styles, s.plot.name, s.dat, block);
    s.gp = gp + layout_end(layout, series_entries(d, styles));
    return s;
}

io::PlotScript stripes_plot(const StudyData& d, const EnsembleMeasures& e) {
    const Styles styles = styles_of(d);
    const PanelLayout layout = panel_layout(e.walls.size());
    io::PlotScript s;
    s.plot = {kEnsembleSection, "stripes",
              fmt::format("Share of records that overturned at each {} level (95 % Wilson bars)", e.name), false};
    s.dat = "# " + io::gp_comment(s.plot.title) + "\n";
    std::string gp = io::gp_preamble("vssw study", s.plot.name, layout.width, layout.height) +
                     io::gp_xlabel(e.label, !layout.multiplot()) + "set ylabel 'share overturned'\n" +
                     layout_begin(layout, s.plot.title);
    std::size_t block = 0;
    for (std::size_t w = 0; w < e.walls.size(); ++w) {
        std::string cmd;
        for (const SeriesMeasures& m : e.measures) {
            if (m.wall != w || m.levels.empty()) continue;
            const std::string& label = d.series[m.series].label;
            s.dat += fmt::format("# {}: {} share lo hi runs hover_text\n", io::gp_comment(label), e.intensity);
            for (const StripeShare& l : m.levels)
                s.dat += fmt::format("{} {} {} {} {} {}\n", io::gp_number(l.pga), io::gp_number(l.share.value),
                                     io::gp_number(l.share.lo), io::gp_number(l.share.hi), l.share.n,
                                     io::gp_hover_text(label, fmt::format("{} {:.4g} {}, {} runs", e.name, l.pga, e.unit, l.share.n),
                                                   l.share.value, "overturned"));
            s.dat += "\n\n";
            const std::string style = styles.of(d, m.series);
            cmd += fmt::format("{}'{}.dat' index {} using 1:2:3:4 with yerrorlines {} title {}, \\\n     {}",
                               cmd.empty() ? "plot " : ", \\\n     ", s.plot.name, block, style, io::gp_string(label),
                               io::gp_hover_layer(fmt::format("'{}.dat' index {} using 1:2:(stringcolumn(6))", s.plot.name,
                                                          block),
                                              style));
            ++block;
        }
        // Room beyond the first and last level: a bar there would lie on the frame and be hidden by it.
        gp += panel_begin(layout, e.walls[w]) + "set yrange [-0.05:1.05]\nset offsets graph 0.05, graph 0.05, 0, 0\n" +
              (cmd.empty() ? "plot [0:1][0:1] NaN notitle\n" : cmd + "\n");
    }
    s.gp = gp + layout_end(layout, series_entries(d, styles));
    return s;
}

// Fig. 10's rocking curves with the ensemble's spread: one panel per stripe (PGA), per series and size R the median
// peak over the records against alpha with its quartiles as bars.
io::PlotScript rocking_plot(const StudyData& d, const EnsembleMeasures& e, const std::vector<RockingCurve>& curves) {
    std::vector<double> stripes;
    for (const RockingCurve& c : curves)
        if (std::find(stripes.begin(), stripes.end(), c.pga) == stripes.end()) stripes.push_back(c.pga);
    std::vector<double> sizes;
    for (const RockingCurve& c : curves)
        if (std::find(sizes.begin(), sizes.end(), c.R) == sizes.end()) sizes.push_back(c.R);
    const Styles styles = styles_of(d);
    const PanelLayout layout = panel_layout(stripes.size());
    io::PlotScript s;
    s.plot = {kEnsembleSection, "ensemble_rocking",
              "Rocking curves (Fig. 10): peak |theta1|/alpha1 over the records against alpha, median and quartiles",
              false};
    s.dat = "# " + io::gp_comment(s.plot.title) + "\n";
    std::string gp = io::gp_preamble("vssw study", s.plot.name, layout.width, layout.height) +
                     io::gp_xlabel("alpha [rad]", !layout.multiplot()) + "set ylabel 'peak |theta1| / alpha1'\n" +
                     // Room above 1, where an overturned median's ring sits, so the frame does not cut it.
                     "set offsets 0, 0, graph 0.08, 0\n" +
                     layout_begin(layout, s.plot.title);
    std::size_t block = 0;
    std::vector<std::pair<std::string, std::string>> entries;
    // The key names the ring "overturned" only when some median overturned (the first curve's ring carries it).
    bool any_overturned = false;
    for (const RockingCurve& c : curves)
        for (const RockingPoint& p : c.points) any_overturned = any_overturned || std::isinf(p.peak.median);
    for (double pga : stripes) {
        std::string cmd;
        for (const RockingCurve& c : curves) {
            if (!(c.pga == pga || (std::isnan(c.pga) && std::isnan(pga)))) continue;
            const std::size_t r = static_cast<std::size_t>(std::find(sizes.begin(), sizes.end(), c.R) - sizes.begin());
            const std::string style =
                io::series_style(d.series[c.series].engine, styles.variants[c.series] * sizes.size() + r);
            const std::string label = d.series[c.series].label + (sizes.size() > 1 ? fmt::format(" R={:g}", c.R) : "");
            // An overturned quartile at 1, the median's point then ringed (study/overturned_runs.hpp).
            const auto drawn = [](double q) { return io::gp_number(std::isinf(q) ? kOverturnedDrawnAt : q); };
            s.dat += fmt::format("# {}: alpha median q1 q3 records overturned median_overturned\n",
                                 io::gp_comment(label));
            for (const RockingPoint& p : c.points)
                s.dat += fmt::format("{} {} {} {} {} {} {}\n", io::gp_number(p.alpha), drawn(p.peak.median),
                                     drawn(p.peak.q1), drawn(p.peak.q3), p.peak.n, p.overturned,
                                     std::isinf(p.peak.median) ? 1 : 0);
            s.dat += "\n\n";
            // A single panel has its key below the frame (titles); several share the legend panel (entries).
            cmd += fmt::format("{}'{}.dat' index {} using 1:2:3:4 with yerrorlines {} {}, \\\n     "
                               "'{}.dat' index {} using 1:($7 > 0.5 ? $2 : NaN) with points {} {}",
                               cmd.empty() ? "plot " : ", \\\n     ", s.plot.name, block, style,
                               layout.multiplot() ? "notitle" : "title " + io::gp_string(label), s.plot.name, block,
                               kOverturnedRing,
                               layout.multiplot() || block > 0 || !any_overturned ? "notitle" : "title 'overturned'");
            ++block;
            if (pga == stripes.front()) entries.push_back({label, style});
        }
        gp += panel_begin(layout, std::isnan(pga) ? "" : fmt::format("{} {:g} {}", e.name, pga, e.unit)) + cmd + "\n";
    }
    s.gp = gp + layout_end(layout, entries,
                           any_overturned ? fmt::format("NaN with points {} title 'overturned'", kOverturnedRing) : "");
    return s;
}

std::string interval_text(const compare::Interval& i, const std::string& format) {
    if (!std::isfinite(i.value)) return "-";
    return fmt::format("{} [{}, {}]", fmt::format(fmt::runtime(format), i.value),
                       std::isfinite(i.lo) ? fmt::format(fmt::runtime(format), i.lo) : "?",
                       std::isfinite(i.hi) ? fmt::format(fmt::runtime(format), i.hi) : "?");
}

}  // namespace

std::string fit_note(const compare::FitBootstrap& f) {
    if (!f.fit.ok()) return f.fit.reason;
    if (!f.interval_reason.empty()) return f.interval_reason;
    // A fit whose resamples all give one median: the records cannot move it, so its interval says nothing.
    if (f.median.n > 0 && f.median.lo == f.median.hi) return "not resolved: every resample gives the same median";
    return "";
}

void write_fragility_csv(std::ostream& out, const StudyData& d, const EnsembleMeasures& e) {
    out << "engine,assumptions,intensity,median,beta,median_lo,median_hi,beta_lo,beta_hi,records,collapsed,"
           "median_ratio,ratio_lo,ratio_hi,settings,wall,reference,seed,replicates,failed_replicates,"
           "ratio_failed_replicates,note,intensity_unit\n";
    for (const SeriesMeasures& m : e.measures) {
        if (!m.fitted()) continue;
        const compare::FitBootstrap& f = m.fit;
        const bool ratio = !is_reference(e, m) && e.has_reference;
        out << series_columns(d.series[m.series]) << ',' << m.intensity << ','
            << fmt::format("{},{},{},{},{},{},{},{},", io::csv_number(f.fit.median), io::csv_number(f.fit.beta),
                           io::csv_number(f.median.lo), io::csv_number(f.median.hi), io::csv_number(f.beta.lo),
                           io::csv_number(f.beta.hi), f.fit.records, f.fit.collapsed)
            << fmt::format("{},{},{},", io::csv_number(ratio ? m.ratio.ratio.value : NAN),
                           io::csv_number(ratio ? m.ratio.ratio.lo : NAN), io::csv_number(ratio ? m.ratio.ratio.hi : NAN))
            << tail_columns(d, e, m)
            << fmt::format(",{},{},{},{},{},{}\n", kEnsembleSeed, kEnsembleReplicates, f.failed,
                           ratio ? std::to_string(m.ratio.failed) : std::string(), io::csv_field(fit_note(f)),
                           io::csv_field(e.unit));
    }
}

void write_agreement_csv(std::ostream& out, const StudyData& d, const EnsembleMeasures& e) {
    out << "engine,assumptions,measure,value,lo,hi,n,settings,wall,reference\n";
    for (const SeriesMeasures& m : e.measures) {
        const std::string head = series_columns(d.series[m.series]), tail = tail_columns(d, e, m);
        const auto row = [&](const std::string& measure, const compare::Interval& i) {
            out << head << ',' << io::csv_field(measure) << ',' << interval_columns(i) << ',' << tail << '\n';
        };
        const bool compared = e.has_reference && !is_reference(e, m);
        if (m.stripes && compared) {
            const compare::Quartiles& q = m.peak_ratio;
            row("overturning_agreement", m.overturning);
            row("peak_ratio_median", {q.median, q.q1, q.q3, q.n});
            row("peak_ratio_q1", {q.q1, NAN, NAN, q.n});
            row("peak_ratio_q3", {q.q3, NAN, NAN, q.n});
            if (m.band) row("inside_band", {static_cast<double>(m.inside.inside), NAN, NAN, m.inside.runs});
            // The paired measures (docs/earthquakes.md, "Verdicts"): the median ln peak ratio (n: its runs) and McNemar's counts.
            const compare::Interval& d_median = m.log_peak_ratio.median;
            row("peak_log_ratio_median", {d_median.value, d_median.lo, d_median.hi, m.log_peak_ratio.values});
            row("overturned_alone", {static_cast<double>(m.overturned_alone), NAN, NAN, m.overturning.n});
            row("stood_alone", {static_cast<double>(m.stood_alone), NAN, NAN, m.overturning.n});
            row("failed_paired", {static_cast<double>(m.failed_paired), NAN, NAN, m.overturning.n});
        }
        if (m.fitted() && compared) row("fragility_median_ratio", {m.ratio.ratio.value, m.ratio.ratio.lo,
                                                              m.ratio.ratio.hi, m.paired});
        for (const StripeShare& l : m.levels)
            row("overturned_share_" + e.intensity + "_" + level_text(l.pga), l.share);
    }
}

void add_ensemble_plots(const StudyData& d, const EnsembleMeasures& e, StudyPlots& out) {
    if (!e.applies) return;
    const bool fits = std::any_of(e.measures.begin(), e.measures.end(),
                                  [](const SeriesMeasures& m) { return m.fitted() && m.fit.fit.ok(); });
    const bool stripes = std::any_of(e.measures.begin(), e.measures.end(),
                                     [](const SeriesMeasures& m) { return !m.levels.empty(); });
    if (fits) out.scripts.push_back(fragility_plot(d, e));
    if (stripes) out.scripts.push_back(stripes_plot(d, e));
    if (const std::vector<RockingCurve> curves = rocking_curves(d); !curves.empty())
        out.scripts.push_back(rocking_plot(d, e, curves));
}

void add_ensemble_section(std::vector<io::DocBlock>& b, const StudyData& d, const EnsembleMeasures& e) {
    if (!e.applies) return;
    b.push_back(io::heading(2, "Ensemble"));
    b.push_back(io::paragraph(fmt::format(
        "Each series against the reference, {} ({}), over the study's records (fragility.csv and agreement.csv hold "
        "every number). Fragility: a lognormal fit to each record's collapse {} (IDA), a record still standing at "
        "max_pga right-censored there, or to the stripes' overturning counts by maximum likelihood; 95 % percentile bootstrap intervals of {} resamples of the records (seed {}), the "
        "ratio to the reference's median paired over the records both have. Overturning agreement: the share of "
        "records x levels where the series and the reference agree (95 % Wilson interval). Inside band: the runs "
        "whose peak lies within the reference's own spread under its perturbed repeats.",
        e.has_reference ? d.series[e.reference].label : "none (the study ran no analytic series)",
        e.preferred_reference ? "the set mechanism: exact kinematics, whole-mechanism impact, unilateral roller"
                              : "the first analytic series: the study did not run the set mechanism (exact / "
                                "whole-mechanism / unilateral)",
        e.name, kEnsembleReplicates, kEnsembleSeed)));
    io::DocBlock t = io::table({"series", "wall", fmt::format("fragility median [{}]", e.unit), "beta", "median / reference's",
                        "overturning agreement", "inside band"},
                       2);
    for (const SeriesMeasures& m : e.measures) {
        const bool compared = e.has_reference && !is_reference(e, m);
        t.rows.push_back({{d.series[m.series].label + (is_reference(e, m) ? " (reference)" : "")},
                          {e.walls[m.wall].empty() ? "-" : e.walls[m.wall]},
                          {m.fitted() ? interval_text(m.fit.median, "{:.3g}") : "-"},
                          {m.fitted() ? interval_text(m.fit.beta, "{:.2f}") : "-"},
                          {m.fitted() && compared ? interval_text(m.ratio.ratio, "{:.3f}") : "-"},
                          {m.stripes && compared ? interval_text(m.overturning, "{:.3f}") : "-"},
                          {m.band && compared ? fmt::format("{} of {}", m.inside.inside, m.inside.runs) : "-"}});
    }
    b.push_back(t);
}

}  // namespace vssw::study

#include "validation/earthquake_plots.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "study/ensemble_outputs.hpp"  // fit_note
#include "study/plot_panels.hpp"

namespace vssw::validation {
namespace {

const char* const kSection = "Under earthquake records";
// The marker of a run where either overturned, drawn at the panel's edge (its peak is the collapse angle, not a
// response to compare), and the reference's lines: grey, apart from every engine's colour (io/palette.hpp).
const char* const kOverturnedStyle = "pt 2 ps 1.2 lc rgb '#d62728'";
const char* const kReferenceStyle = "lw 2 dt 2 lc rgb '#555555'";
const char* const kReferencePoints = "pt 6 ps 1.0 lc rgb '#555555'";
// The peaks' axes reach this factor past the smallest and largest value shown (log axes): the edge markers sit
// inside the frame.
constexpr double kLogMargin = 1.5;
// The fragility panels' level axis reaches this far past the largest level (as the study's fragility plot).
constexpr double kAxisReach = 1.1;

std::vector<const study::SeriesMeasures*> compared(const study::EnsembleMeasures& e) {
    std::vector<const study::SeriesMeasures*> out;
    for (const study::SeriesMeasures& m : e.measures)
        if (e.has_reference && m.series != e.reference && m.stripes) out.push_back(&m);
    return out;
}

std::vector<std::string> engines_of(const study::StudyData& d) {
    std::vector<std::string> engines;
    for (const study::Series& s : d.series) engines.push_back(s.engine);
    return engines;
}

// A plot of one panel per series: its script begun up to the axes' settings (`axes`), the data file's title line.
io::PlotScript panel_plot(const char* name, const std::string& title, const study::PanelLayout& layout,
                      const std::string& xlabel, const std::string& axes) {
    io::PlotScript s;
    s.plot = {kSection, name, title, false};
    s.dat = "# " + io::gp_comment(title) + "\n";
    s.gp = io::gp_preamble("vssw report", name, layout.width, layout.height) + io::gp_xlabel(xlabel, !layout.multiplot()) +
           axes + study::layout_begin(layout, title);
    return s;
}

bool stands(double overturned) { return std::isfinite(overturned) && overturned < 0.5; }

io::PlotScript peaks_plot(const study::StudyData& d, const std::vector<const study::SeriesMeasures*>& series) {
    const std::vector<std::size_t> variants = io::series_variants(engines_of(d));
    // The axes: over every positive peak and band end of the runs where both stand (an overturned run's peak is its
    // collapse angle, drawn at the edge), the same in every panel.
    double lo = INFINITY, hi = 0.0;
    for (const study::SeriesMeasures* m : series)
        for (const study::PairedRun& r : m->paired_runs)
            for (double v : {r.peak, r.reference_peak, r.band_lo, r.band_hi})
                if (stands(r.overturned) && stands(r.reference_overturned) && std::isfinite(v) && v > 0.0) {
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
    if (!(hi > 0.0)) lo = 1e-3, hi = 1.0;
    const double edge = hi * std::sqrt(kLogMargin);  // inside the frame, past every peak
    lo /= kLogMargin;
    hi *= kLogMargin;
    const study::PanelLayout layout = study::panel_layout(series.size());
    io::PlotScript s = panel_plot("engine_peaks", "Peak |theta1| / alpha1 per run, engine against reference (log-log)",
                              layout, "reference peak",
                              fmt::format("set ylabel 'engine peak'\nset logscale xy\nset format xy '%g'\n"
                                          "set xrange [{0}:{1}]\nset yrange [{0}:{1}]\n",
                                          io::gp_number(lo), io::gp_number(hi)));
    std::string gp = std::move(s.gp);
    std::size_t block = 0;
    for (const study::SeriesMeasures* m : series) {
        const std::string& label = d.series[m->series].label;
        const std::string style = io::series_style(d.series[m->series].engine, variants[m->series]);
        // Block 1: the runs where both stand; block 2: those where either overturned, at the edge.
        s.dat += fmt::format("# {}: reference_peak engine_peak band_lo band_hi hover_text (both stand)\n",
                             io::gp_comment(label));
        std::string edges;
        for (const study::PairedRun& r : m->paired_runs) {
            if (stands(r.overturned) && stands(r.reference_overturned)) {
                s.dat += fmt::format("{} {} {} {} {}\n", io::gp_number(r.reference_peak, true), io::gp_number(r.peak, true),
                                     io::gp_number(r.band_lo, true), io::gp_number(r.band_hi, true),
                                     io::gp_hover_text(label, r.name + ", reference " + fmt::format("{:.4g}",
                                                                                                r.reference_peak),
                                                   r.peak, ""));
                continue;
            }
            const std::string who = !std::isfinite(r.overturned) ? "it failed"
                                    : r.overturned > 0.5 && r.reference_overturned > 0.5 ? "both overturned"
                                    : r.overturned > 0.5 ? "it overturned alone" : "the reference overturned alone";
            const double x = stands(r.reference_overturned) ? r.reference_peak : edge;
            const double y = stands(r.overturned) ? r.peak : edge;
            edges += fmt::format("{} {} {}\n", io::gp_number(x, true), io::gp_number(y, true),
                                 io::gp_data_string(label + ", " + r.name + ": " + who));
        }
        s.dat += fmt::format("\n\n# {}: reference_peak engine_peak hover_text (overturned or failed: at the edge)\n{}"
                             "\n\n",
                             io::gp_comment(label), edges);
        const std::string points = fmt::format("'{}.dat' index {} using 1:2", s.plot.name, block);
        const std::string at_edge = fmt::format("'{}.dat' index {} using 1:2", s.plot.name, block + 1);
        gp += study::panel_begin(layout, label) +
              fmt::format("plot x with lines lc rgb '#888888' title 'identity', \\\n"
                          "     '{0}.dat' index {1} using 1:1:3:4 with yerrorbars {2} title \"reference's band\", \\\n"
                          "     {3} with points {4} title {5}, \\\n     {6}, \\\n"
                          "     {7} with points {8} title 'overturned or failed (at the edge)', \\\n     {9}\n",
                          s.plot.name, block, kReferencePoints, points, style, io::gp_string(label),
                          io::gp_hover_layer(points + ":(stringcolumn(5))", style), at_edge, kOverturnedStyle,
                          io::gp_hover_layer(at_edge + ":(stringcolumn(3))", kOverturnedStyle));
        block += 2;
    }
    std::vector<std::pair<std::string, std::string>> entries;
    for (const study::SeriesMeasures* m : series)
        entries.push_back({d.series[m->series].label, io::series_style(d.series[m->series].engine, variants[m->series])});
    s.gp = gp + "unset logscale\n" + study::layout_end(layout, entries,
                           fmt::format("NaN with lines lc rgb '#888888' title 'identity', NaN with points {} title "
                                       "\"the reference's band (bar)\", NaN with points {} title "
                                       "'overturned or failed (at the edge)'",
                                       kReferencePoints, kOverturnedStyle));
    return s;
}

// One series' stripes (block) and, when its fit is resolved, its curve; the note when it is not.
std::string fragility_layer(const study::SeriesMeasures& m, const std::string& label, const std::string& curve_style,
                            const std::string& point_style, const std::string& name, std::size_t block,
                            std::string& dat, std::string& notes) {
    dat += fmt::format("# {}: level share_overturned hover_text\n", io::gp_comment(label));
    for (const study::StripeShare& l : m.levels)
        dat += fmt::format("{} {} {}\n", io::gp_number(l.pga), io::gp_number(l.share.value),
                           io::gp_hover_text(label, fmt::format("level {:.4g}", l.pga), l.share.value, "overturned"));
    dat += "\n\n";
    const std::string points = fmt::format("'{}.dat' index {} using 1:2", name, block);
    std::string cmd = fmt::format("{} with points {} notitle, \\\n     {}", points, point_style,
                                  io::gp_hover_layer(points + ":(stringcolumn(3))", point_style));
    const std::string note = m.fitted() ? study::fit_note(m.fit) : "no stripes to fit";
    if (note.empty())
        cmd += fmt::format(", \\\n     norm(log(x/{})/{}) with lines {} title {}", io::gp_number(m.fit.fit.median),
                           io::gp_number(m.fit.fit.beta), curve_style, io::gp_string(label));
    else
        notes += fmt::format("{}, stripes only: {}", label,
                             note.rfind("not resolved", 0) == 0 ? note : "not resolved: " + note);
    return cmd;
}

io::PlotScript fragility_plot(const study::StudyData& d, const study::EnsembleMeasures& e,
                          const std::vector<const study::SeriesMeasures*>& series) {
    const std::vector<std::size_t> variants = io::series_variants(engines_of(d));
    const study::SeriesMeasures* reference = nullptr;
    for (const study::SeriesMeasures& m : e.measures)
        if (m.series == e.reference) reference = &m;
    double xmax = 0.0;
    for (const study::SeriesMeasures* m : series)
        for (const study::StripeShare& l : m->levels) xmax = std::max(xmax, l.pga);
    const study::PanelLayout layout = study::panel_layout(series.size());
    io::PlotScript s = panel_plot(
        "fragility_by_engine",
        "Fragility per engine: its stripes (points) and lognormal fit (line) against the reference's (grey)", layout,
        e.label,
        // y beyond [0, 1]: a stripe at a share of 0 or 1 drawn whole, not halved by the frame.
        fmt::format("set ylabel {}\nset samples 300\nset xrange [0:{}]\nset yrange [-0.05:1.05]\n",
                    io::gp_string("P(overturn | " + e.name + ")"), io::gp_number(kAxisReach * std::max(xmax, 1e-3))));
    std::string gp = std::move(s.gp);
    std::size_t block = 0;
    for (const study::SeriesMeasures* m : series) {
        const std::string& label = d.series[m->series].label;
        const std::string style = io::series_style(d.series[m->series].engine, variants[m->series]);
        std::string notes, cmd;
        if (reference) {
            cmd = fragility_layer(*reference, "reference: " + d.series[reference->series].label, kReferenceStyle,
                                  kReferencePoints, s.plot.name, block++, s.dat, notes);
            notes.clear();  // the reference's own note is the section's (its fragility median)
        }
        cmd += (cmd.empty() ? "" : ", \\\n     ") +
               fragility_layer(*m, label, style, style, s.plot.name, block++, s.dat, notes);
        // Not resolved: the panel's title says so, the reason is in the data file and the section's list.
        if (!notes.empty()) s.dat += "# " + io::gp_comment(notes) + "\n";
        const std::string title = notes.empty() ? label : label + " (not resolved: stripes only)";
        gp += (layout.multiplot() || notes.empty() ? study::panel_begin(layout, title)
                                                    : fmt::format("set title {}\n", io::gp_string(title))) +
              "plot " + cmd + "\n";
    }
    std::vector<std::pair<std::string, std::string>> entries;
    if (reference) entries.push_back({"reference", kReferenceStyle});
    for (const study::SeriesMeasures* m : series)
        entries.push_back({d.series[m->series].label, io::series_style(d.series[m->series].engine, variants[m->series])});
    s.gp = gp + study::layout_end(layout, entries);
    return s;
}

}  // namespace

std::vector<io::PlotScript> earthquake_plot_scripts(const study::StudyData& d, const study::EnsembleMeasures& e) {
    const std::vector<const study::SeriesMeasures*> series = compared(e);
    if (series.empty()) return {};
    return {peaks_plot(d, series), fragility_plot(d, e, series)};
}

}  // namespace vssw::validation

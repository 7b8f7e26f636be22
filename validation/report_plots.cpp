#include "validation/report_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "compare/targets.hpp"
#include "io/palette.hpp"  // series_style, series_variants
#include "validation/report_data.hpp"  // trace_number
#include "multibody/engine.hpp"

namespace vssw::validation {
namespace fs = std::filesystem;
namespace {

// The report's plot sections, in the order it shows them.
const char* const kTraceSection = "Time histories: theta1 / alpha1, the analytic model and each engine";
const char* const kErrorSection = "Relative error per metric, case and engine";
const char* const kStepSection = "Error against step size";

// Plot sizes in SVG pixels: as wide as the report's page (io/document_html.cpp, 1140 px less its padding), so that
// the HTML shows them at about their own size; the error plots widen with the number of cases so their labels stay
// readable (the page then scales them down).
constexpr int kPlotWidth = 1100, kPlotHeight = 420, kPixelsPerCase = 34;
// About this many markers on a trace plot's line (its engine's, io/palette.hpp), spread over its drawn points.
constexpr std::size_t kTraceMarkers = 12;

// The trace plots' x axis runs over the motion: from the first to the last time any trace is beyond this share of the
// largest |theta1| / alpha1 of the case (1 %: 4 px of a 420 px plot, a line that is flat to the eye), with this share
// of that span either side.
constexpr double kMotionFraction = 0.01;
constexpr double kMotionMargin = 0.04;
// The trace plots' data keep only the points that a straight line between their neighbours would miss by more than
// this [px] (Douglas-Peucker on the plot's pixel grid): less than half a pixel, so the plot shows what all samples
// would; a record's long rest at zero becomes one segment.
constexpr double kTracePixelTolerance = 0.25;

// The error plots' y axis spans at least the target band times this, so that the band's dashed lines stay inside the
// frame with a little room (a fifth of the band) for a point just outside them.
constexpr double kBandRoom = 1.2;
// The band of a metric without a target (the RMS difference): the smallest target of any metric (threshold and period,
// 0.5 %: compare/targets.hpp), below which no difference is one the report asks about.
constexpr double kSmallestTarget = std::min({compare::kThresholdTarget, compare::kPeriodTarget,
                                             compare::kRestitutionTarget});

// A case whose other traces (the engines') all peak below this share of the reference's gets a
// second trace plot zoomed on them: below a third of the reference they span less than a third of its plot's height,
// and El Centro's VSSW, 0.03 alpha1 against 0.47, is a flat line there.
constexpr double kZoomRatio = 1.0 / 3.0;

// A zoomed plot's time axis runs where its traces are beyond this share of their largest value: it frames the rocking,
// not a creep (Bullet's under El Centro x 1.15 on the VSSW: up to 2e-3 alpha1 for 30 s after a 0.03 alpha1 peak), which
// the first plot's time axis still covers.
constexpr double kZoomMotionFraction = 0.1;

// The legend's words for a trace: the analytic model's names its assumption set.
std::string trace_title(const Trace& t) {
    if (t.engine != "analytic") return multibody::engine_display_name(t.engine);
    return t.assumption.empty() ? "analytic (reference)" : fmt::format("analytic, {} (reference)", t.assumption);
}

// What the error plot's points are, and how the relative error is taken: the RMS difference's is no relative error.
struct ErrorQuantity {
    const char* name;
    const char* definition;  // "" for the RMS difference
};
ErrorQuantity error_quantity(const std::string& metric) {
    if (metric == "rms_difference") return {"RMS difference / analytic peak", ""};
    return {"relative error", " (engine / reference - 1)"};
}

// The error plot's y axis, naming what its points are.
std::string error_axis_label(const std::string& metric) {
    const ErrorQuantity q = error_quantity(metric);
    return fmt::format("{} [%]{}", q.name, q.definition);
}

}  // namespace

TraceWindow trace_window(const std::vector<const Trace*>& traces, double motion_fraction) {
    TraceWindow w;
    double largest = 0.0, t_min = std::numeric_limits<double>::infinity(), t_max = -t_min;
    for (const Trace* t : traces)
        for (std::size_t i = 0; i < std::min(t->t.size(), t->theta1_over_alpha1.size()); ++i) {
            if (std::isfinite(t->theta1_over_alpha1[i])) largest = std::max(largest, std::abs(t->theta1_over_alpha1[i]));
            t_min = std::min(t_min, t->t[i]);
            t_max = std::max(t_max, t->t[i]);
        }
    if (!(t_max >= t_min)) return w;
    double first = t_max, last = t_min;
    for (const Trace* t : traces)
        for (std::size_t i = 0; i < std::min(t->t.size(), t->theta1_over_alpha1.size()); ++i)
            if (std::abs(t->theta1_over_alpha1[i]) > motion_fraction * largest) {
                first = std::min(first, t->t[i]);
                last = std::max(last, t->t[i]);
            }
    if (!(last > first)) {  // no motion: the whole time
        first = t_min;
        last = t_max;
    }
    const double margin = kMotionMargin * (last - first);
    w.t0 = std::max(t_min, first - margin);
    w.t1 = std::min(t_max, last + margin);
    if (!(w.t1 > w.t0)) w.t1 = w.t0 + 1.0;
    // y: every value inside the window, and zero.
    double lo = 0.0, hi = 0.0;
    for (const Trace* t : traces)
        for (std::size_t i = 0; i < std::min(t->t.size(), t->theta1_over_alpha1.size()); ++i)
            if (t->t[i] >= w.t0 && t->t[i] <= w.t1 && std::isfinite(t->theta1_over_alpha1[i])) {
                lo = std::min(lo, t->theta1_over_alpha1[i]);
                hi = std::max(hi, t->theta1_over_alpha1[i]);
            }
    const double pad = 0.05 * std::max(hi - lo, 1e-9);
    w.y0 = lo - pad;
    w.y1 = hi + pad;
    return w;
}

std::vector<std::size_t> simplify_polyline(const std::vector<double>& x, const std::vector<double>& y, double tol) {
    const std::size_t n = std::min(x.size(), y.size());
    if (n <= 2) {
        std::vector<std::size_t> all(n);
        for (std::size_t i = 0; i < n; ++i) all[i] = i;
        return all;
    }
    std::vector<bool> keep(n, false);
    keep[0] = keep[n - 1] = true;
    std::vector<std::pair<std::size_t, std::size_t>> stack = {{0, n - 1}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        if (b <= a + 1) continue;
        if (!std::isfinite(y[a]) || !std::isfinite(y[b])) {
            // A non-finite end (a gap) gives no segment to measure from: its neighbour is kept, and the rest measured
            // from there.
            const std::size_t next = std::isfinite(y[a]) ? b - 1 : a + 1;
            keep[next] = true;
            stack.push_back({a, next});
            stack.push_back({next, b});
            continue;
        }
        const double dx = x[b] - x[a], dy = y[b] - y[a], len = std::hypot(dx, dy);
        double worst = -1.0;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i) {
            // Distance from the segment a-b (to the nearer end beyond it), NaN points always kept.
            double d;
            if (!std::isfinite(y[i])) d = std::numeric_limits<double>::infinity();
            else if (len == 0.0) d = std::hypot(x[i] - x[a], y[i] - y[a]);
            else {
                const double u = std::clamp(((x[i] - x[a]) * dx + (y[i] - y[a]) * dy) / (len * len), 0.0, 1.0);
                d = std::hypot(x[i] - (x[a] + u * dx), y[i] - (y[a] + u * dy));
            }
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst > tol) {
            keep[at] = true;
            stack.push_back({a, at});
            stack.push_back({at, b});
        }
    }
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) kept.push_back(i);
    return kept;
}

namespace {

// One trace plot: the traces inside the window, each simplified on the plot's pixel grid.
io::PlotScript trace_script(const std::string& id, const std::string& name, const std::string& title,
                        const std::vector<const Trace*>& traces, const TraceWindow& w) {
    io::PlotScript s;
    s.plot = {kTraceSection, name, title, false};
    std::string plot_cmd;
    int index = 0;
    for (const Trace* t : traces) {
        s.dat += fmt::format("# {} {}{}\n# t theta1_over_alpha1\n", io::gp_comment(id), io::gp_comment(t->engine),
                             t->assumption.empty() ? "" : " " + io::gp_comment(t->assumption));
        // The samples inside the window and one either side (the line runs to the edge).
        const std::size_t n = std::min(t->t.size(), t->theta1_over_alpha1.size());
        std::vector<double> px, py;
        std::vector<std::size_t> at;
        for (std::size_t i = 0; i < n; ++i) {
            const bool inside = t->t[i] >= w.t0 && t->t[i] <= w.t1;
            const bool edge = (i + 1 < n && t->t[i + 1] >= w.t0 && t->t[i] < w.t0) ||
                              (i > 0 && t->t[i - 1] <= w.t1 && t->t[i] > w.t1);
            if (!inside && !edge) continue;
            px.push_back((t->t[i] - w.t0) / (w.t1 - w.t0) * kPlotWidth);
            py.push_back((t->theta1_over_alpha1[i] - w.y0) / (w.y1 - w.y0) * kPlotHeight);
            at.push_back(i);
        }
        const std::vector<std::size_t> kept = simplify_polyline(px, py, kTracePixelTolerance);
        for (std::size_t k : kept)
            s.dat += trace_number(t->t[at[k]], kTraceTimeDigits) + ' ' +
                     trace_number(t->theta1_over_alpha1[at[k]], kTraceValueDigits) + '\n';
        s.dat += "\n\n";  // the next gnuplot index
        const bool analytic = t->engine == "analytic";
        // The engine's marker (io/palette.hpp) on a few of the line's points: the line reads without its colour.
        // No hover layer (gnuplot.hpp, gp_hover_layer): a trace has up to thousands of points, each a group with its
        // text in the SVG, which the page inlines: several times its size for values the .dat holds anyway.
        const std::size_t every = std::max<std::size_t>(1, kept.size() / kTraceMarkers);
        plot_cmd += fmt::format(
            "{}'{}.dat' index {} using 1:2 with linespoints lw {} dt {} pt {} ps 0.8 pi {} lc rgb '{}' title {}",
            index == 0 ? "plot " : ", \\\n     ", s.plot.name, index, analytic ? 2.2 : 1.4, 1,
            io::engine_point(t->engine, true), every, io::engine_colour(t->engine), io::gp_string(trace_title(*t)));
        ++index;
    }
    s.gp = io::gp_preamble("vssw report", s.plot.name, kPlotWidth, kPlotHeight) +
           // clip two: a line between two points outside the frame is drawn across it (a zoomed plot's reference).
           fmt::format("set title {}\n{}set ylabel 'theta1 / alpha1'\nset clip two\n"
                       "set xrange [{}:{}]\nset yrange [{}:{}]\n",
                       io::gp_string(s.plot.title), io::gp_xlabel("t [s]"), io::gp_number(w.t0), io::gp_number(w.t1),
                       io::gp_number(w.y0), io::gp_number(w.y1)) +
           plot_cmd + "\n";
    return s;
}

double largest_value(const Trace& t) {
    double m = 0.0;
    for (double v : t.theta1_over_alpha1)
        if (std::isfinite(v)) m = std::max(m, std::abs(v));
    return m;
}

std::vector<io::PlotScript> trace_scripts(const ReportInput& in) {
    std::vector<std::string> cases;  // in the order of the traces
    for (const Trace& t : in.results.traces)
        if (std::find(cases.begin(), cases.end(), t.case_id) == cases.end()) cases.push_back(t.case_id);
    std::vector<io::PlotScript> scripts;
    for (const std::string& id : cases) {
        std::vector<const Trace*> traces;  // the analytic model's first (the reference), then the engines'
        for (const Trace& t : in.results.traces)
            if (t.case_id == id && t.engine == "analytic") traces.push_back(&t);
        const std::size_t references = traces.size();
        for (const Trace& t : in.results.traces)
            if (t.case_id == id && t.engine != "analytic") traces.push_back(&t);
        if (traces.empty()) continue;
        scripts.push_back(trace_script(id, "trace_" + io::file_stem(id),
                                       fmt::format("{}: theta1 / alpha1, the analytic model and engines", id), traces,
                                       trace_window(traces, kMotionFraction)));
        // When every engine rocks far less than the reference, a second plot zooms on them (the reference then
        // leaves the frame): an engine's small response seen at its own scale.
        if (references == 0 || references == traces.size()) continue;
        double reference = 0.0, others = 0.0;
        for (std::size_t i = 0; i < traces.size(); ++i) {
            double& largest = i < references ? reference : others;
            largest = std::max(largest, largest_value(*traces[i]));
        }
        if (!(others > 0.0 && others < kZoomRatio * reference)) continue;
        const std::vector<const Trace*> small(traces.begin() + static_cast<std::ptrdiff_t>(references),
                                                       traces.end());
        scripts.push_back(trace_script(
            id, "trace_" + io::file_stem(id) + "_zoom",
            fmt::format("{}: zoomed on the engines (the reference, up to {:.3g} alpha1, is in the plot above)", id,
                        reference),
            small, trace_window(small, kZoomMotionFraction)));
    }
    return scripts;
}

std::vector<io::PlotScript> error_scripts(const ReportInput& in) {
    std::vector<io::PlotScript> scripts;
    for (const MetricTable& table : metric_tables(in)) {
        // Overturning is yes/no (its "error" is 0 or +-1): its table says it all.
        if (table.engines.empty() || table.metric == "overturned") continue;
        io::PlotScript s;
        s.plot = {kErrorSection, "error_" + io::file_stem(table.metric),
                  table.metric == "rms_difference"
                      ? std::string("RMS difference of theta1 / alpha1 over the analytic peak, per case and engine")
                      : fmt::format("Relative error of the {} per case and engine", metric_title(table.metric)),
                  false};
        // Per case: the engines' errors, then each one's hover text (gnuplot.hpp, gp_hover_layer) in that order.
        const std::size_t engines = table.engines.size();
        s.dat = "# index case_id";
        for (const std::string& e : table.engines) s.dat += ' ' + io::gp_comment(e);
        s.dat += fmt::format("   ({} in %), then the hover text of each\n", error_quantity(table.metric).name);
        for (std::size_t i = 0; i < table.rows.size(); ++i) {
            const MetricTableRow& row = table.rows[i];
            s.dat += fmt::format("{} {}", i, io::gp_data_string(row.case_id));
            for (const MetricCell& c : row.cells) s.dat += ' ' + io::gp_number(c.present ? 100.0 * c.rel_error : NAN);
            for (std::size_t e = 0; e < row.cells.size() && e < engines; ++e)
                s.dat += ' ' + io::gp_hover_text(multibody::engine_display_name(table.engines[e]), row.case_id,
                                             row.cells[e].present ? 100.0 * row.cells[e].rel_error : NAN, "%");
            s.dat += '\n';
        }
        const int width = std::max(kPlotWidth, 260 + kPixelsPerCase * static_cast<int>(table.rows.size()));
        // The case ids as tics from the script, quoted by gp_string: a data file's strings are read another way
        // (gnuplot.hpp).
        std::string tics;
        for (std::size_t i = 0; i < table.rows.size(); ++i)
            tics += fmt::format("{}{} {}", i == 0 ? "set xtics (" : ", \\\n    ", io::gp_string(table.rows[i].case_id), i);
        if (!tics.empty()) tics += ")\n";
        std::string cmd;
        // Each engine's own marker and colour (io/palette.hpp: the same whatever the engine list), slightly offset
        // along x so that equal values stay visible; its values on hover over the same markers.
        const double spread = 0.12;
        for (std::size_t e = 0; e < engines; ++e) {
            const double offset = spread * (static_cast<double>(e) - 0.5 * static_cast<double>(engines - 1));
            const std::string style = fmt::format("pt {} ps 1.3 lc rgb '{}'", io::engine_point(table.engines[e]),
                                                  io::engine_colour(table.engines[e]));
            const std::string using_xy = fmt::format("'{}.dat' using ($1+({:g})):{}", s.plot.name, offset, e + 3);
            cmd += fmt::format("{}{} with points {} title {}, \\\n     {}", e == 0 ? "plot " : ", \\\n     ", using_xy,
                               style, io::gp_string(multibody::engine_display_name(table.engines[e])),
                               io::gp_hover_layer(fmt::format("{}:(stringcolumn({}))", using_xy, e + 3 + engines), style));
        }
        // The y axis spans at least the target band with room around it (or, without a target, the smallest target),
        // so that errors far inside it stay near zero instead of filling the plot (1e-7 % read as large).
        const double band = 100.0 * table.target.value_or(kSmallestTarget);
        if (table.target)
            cmd += fmt::format(", \\\n     {0:g} with lines dt 2 lc rgb '#888888' title 'target +/-{0:g} %', \\\n"
                               "     -{0:g} with lines dt 2 lc rgb '#888888' notitle",
                               band);
        s.gp = io::gp_preamble("vssw report", s.plot.name, width, kPlotHeight + 80) +
               fmt::format("set title {}\nset ylabel {}\n"
                           "set xrange [-0.6:{}]\nset yrange [*<{}:{}<*]\nset xtics rotate by -35 left\n{}",
                           io::gp_string(s.plot.title), io::gp_string(error_axis_label(table.metric)),
                           static_cast<double>(table.rows.size()) - 0.4,
                           io::gp_number(-kBandRoom * band), io::gp_number(kBandRoom * band), tics) +
               cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

std::vector<io::PlotScript> step_scripts(const ReportInput& in) {
    const std::vector<StepSeries> all = step_series(in);
    std::vector<std::string> metrics;
    for (const StepSeries& s : all)
        if (std::find(metrics.begin(), metrics.end(), s.metric) == metrics.end()) metrics.push_back(s.metric);
    std::vector<io::PlotScript> scripts;
    for (const std::string& metric : metrics) {
        io::PlotScript s;
        s.plot = {kStepSection, "step_" + io::file_stem(metric),
                  fmt::format("|Relative error| of the {} against the engine step", metric_title(metric)), false};
        std::string cmd;
        int index = 0;
        std::vector<const StepSeries*> drawn;  // nothing to draw on a log axis without a nonzero error
        for (const StepSeries& series : all) {
            if (series.metric != metric) continue;
            bool any = false;
            for (double e : series.rel_error) any = any || (std::isfinite(e) && e != 0.0);
            if (any) drawn.push_back(&series);
        }
        std::vector<std::string> engines;
        for (const StepSeries* series : drawn) engines.push_back(series->engine);
        const std::vector<std::size_t> variants = io::series_variants(engines);
        for (const StepSeries* drawn_series : drawn) {
            const StepSeries& series = *drawn_series;
            s.dat += fmt::format("# {} {} {}\n# dt_ms abs_rel_error_percent hover_text\n", io::gp_comment(series.engine),
                                 io::gp_comment(series.base_case), io::gp_comment(metric));
            const std::string label = multibody::engine_display_name(series.engine) + " " + series.base_case;
            for (std::size_t i = 0; i < series.dt.size(); ++i)
                s.dat += io::gp_number(1e3 * series.dt[i], true) + ' ' +
                         io::gp_number(100.0 * std::abs(series.rel_error[i]), true) + ' ' +
                         io::gp_hover_text(label, fmt::format("dt {:g} ms", 1e3 * series.dt[i]),
                                       100.0 * std::abs(series.rel_error[i]), "%") +
                         '\n';
            s.dat += "\n\n";
            const std::string style = io::series_style(series.engine, variants[static_cast<std::size_t>(index)]);
            cmd += fmt::format("{0}'{1}.dat' index {2} using 1:2 with linespoints {3} title {4}, \\\n     {5}",
                               index == 0 ? "plot " : ", \\\n     ", s.plot.name, index, style, io::gp_string(label),
                               io::gp_hover_layer(fmt::format("'{}.dat' index {} using 1:2:(stringcolumn(3))",
                                                          s.plot.name, index),
                                              style));
            ++index;
        }
        if (index == 0) continue;
        if (const auto target = target_of(metric))
            cmd += fmt::format(", \\\n     {0:g} with lines dt 2 lc rgb '#888888' title 'target {0:g} %'", 100.0 * *target);
        s.gp = io::gp_preamble("vssw report", s.plot.name, kPlotWidth, kPlotHeight) +
               fmt::format("set title {}\nset logscale xy\nset format y '%g'\n{}set ylabel '|relative error| [%]'\n",
                           io::gp_string(s.plot.title), io::gp_xlabel("engine step dt [ms]")) +
               cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

}  // namespace

std::vector<io::PlotScript> report_plot_scripts(const ReportInput& in) {
    std::vector<io::PlotScript> scripts = trace_scripts(in);
    for (auto* more : {&error_scripts, &step_scripts})
        for (io::PlotScript& s : (*more)(in)) scripts.push_back(std::move(s));
    return scripts;
}

io::PlotResult write_plots(const ReportInput& in, const fs::path& plots_dir, const PlotOptions& options) {
    return io::draw_plots(report_plot_scripts(in), plots_dir, options.gnuplot);
}

}  // namespace vssw::validation

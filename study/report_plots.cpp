#include "study/report_plots.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace vssw::study {
namespace fs = std::filesystem;
namespace {

// The report's plot sections, in the order it shows them.
const char* const kTraceSection = "Time histories: theta1 / alpha, the analytic model and each engine";
const char* const kErrorSection = "Relative error per metric, case and engine";
const char* const kStepSection = "Error against step size";

// Plot sizes in SVG pixels; the error plots widen with the number of cases so their labels stay readable.
constexpr int kPlotWidth = 820, kPlotHeight = 420, kPixelsPerCase = 34;

std::vector<PlotScript> trace_scripts(const ReportInput& in) {
    std::vector<std::string> cases;  // in the order of the traces
    for (const compare::Trace& t : in.results.traces)
        if (std::find(cases.begin(), cases.end(), t.case_id) == cases.end()) cases.push_back(t.case_id);
    std::vector<PlotScript> scripts;
    for (const std::string& id : cases) {
        std::vector<const compare::Trace*> traces;  // analytic first
        for (const compare::Trace& t : in.results.traces)
            if (t.case_id == id && t.engine == "analytic") traces.push_back(&t);
        for (const compare::Trace& t : in.results.traces)
            if (t.case_id == id && t.engine != "analytic") traces.push_back(&t);
        PlotScript s;
        s.plot = {kTraceSection, "trace_" + file_stem(id),
                  fmt::format("{}: theta1 / alpha, analytic model and engines", id), false};
        std::string plot_cmd;
        int index = 0;
        for (const compare::Trace* t : traces) {
            s.dat += fmt::format("# {} {}\n# t theta1_over_alpha\n", id, t->engine);
            const std::size_t n = std::min(t->t.size(), t->theta1_over_alpha.size());
            for (std::size_t i = 0; i < n; ++i)
                s.dat += gp_number(t->t[i]) + ' ' + gp_number(t->theta1_over_alpha[i]) + '\n';
            s.dat += "\n\n";  // the next gnuplot index
            const bool analytic = t->engine == "analytic";
            plot_cmd += fmt::format("{}'{}.dat' index {} using 1:2 with lines lw {} {}title {}",
                                    index == 0 ? "plot " : ", \\\n     ", s.plot.name, index, analytic ? 2.5 : 1.2,
                                    analytic ? "lc rgb 'black' " : "",
                                    gp_string(analytic ? "analytic model" : engine_display_name(t->engine)));
            ++index;
        }
        if (index == 0) continue;
        s.gp = gp_preamble("vssw report", s.plot.name, kPlotWidth, kPlotHeight) +
               fmt::format("set title {}\nset xlabel 't [s]'\nset ylabel 'theta1 / alpha'\n", gp_string(s.plot.title)) +
               plot_cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

std::vector<PlotScript> error_scripts(const ReportInput& in) {
    std::vector<PlotScript> scripts;
    for (const MetricTable& table : metric_tables(in)) {
        // Overturning is yes/no (its "error" is 0 or +-1): its table says it all.
        if (table.engines.empty() || table.metric == "overturned") continue;
        PlotScript s;
        s.plot = {kErrorSection, "error_" + file_stem(table.metric),
                  table.metric == "rms_difference"
                      ? std::string("RMS difference of theta1 / alpha over the analytic peak, per case and engine")
                      : fmt::format("Relative error of the {} per case and engine", metric_title(table.metric)),
                  false};
        s.dat = "# index case_id";
        for (const std::string& e : table.engines) s.dat += ' ' + e;
        s.dat += "   (relative error in %)\n";
        for (std::size_t i = 0; i < table.rows.size(); ++i) {
            const MetricTableRow& row = table.rows[i];
            s.dat += fmt::format("{} {}", i, gp_string(row.case_id));
            for (const MetricCell& c : row.cells) s.dat += ' ' + gp_number(c.present ? 100.0 * c.rel_error : NAN);
            s.dat += '\n';
        }
        const int width = std::max(kPlotWidth, 260 + kPixelsPerCase * static_cast<int>(table.rows.size()));
        std::string cmd = fmt::format("plot '{}.dat' using 1:({}):xtic(2) notitle with points ps 0", s.plot.name,
                                      "NaN");
        // A distinct point type per engine, slightly offset along x so that equal values stay visible.
        const double spread = 0.12;
        for (std::size_t e = 0; e < table.engines.size(); ++e) {
            const double offset =
                spread * (static_cast<double>(e) - 0.5 * static_cast<double>(table.engines.size() - 1));
            cmd += fmt::format(", \\\n     '{}.dat' using ($1+({:g})):{} with points pt {} ps 1.3 title {}",
                               s.plot.name, offset, e + 3, 5 + 2 * static_cast<int>(e),
                               gp_string(engine_display_name(table.engines[e])));
        }
        if (table.target)
            cmd += fmt::format(", \\\n     {0:g} with lines dt 2 lc rgb '#888888' title 'target +/-{0:g} %', \\\n"
                               "     -{0:g} with lines dt 2 lc rgb '#888888' notitle",
                               100.0 * *table.target);
        s.gp = gp_preamble("vssw report", s.plot.name, width, kPlotHeight + 80) +
               fmt::format("set title {}\nset ylabel 'relative error [%] (engine / reference - 1)'\n"
                           "set xrange [-0.6:{}]\nset xtics rotate by -35 left\nset bmargin 9\n",
                           gp_string(s.plot.title), static_cast<double>(table.rows.size()) - 0.4) +
               cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

std::vector<PlotScript> step_scripts(const ReportInput& in) {
    const std::vector<StepSeries> all = step_series(in);
    std::vector<std::string> metrics;
    for (const StepSeries& s : all)
        if (std::find(metrics.begin(), metrics.end(), s.metric) == metrics.end()) metrics.push_back(s.metric);
    std::vector<PlotScript> scripts;
    for (const std::string& metric : metrics) {
        PlotScript s;
        s.plot = {kStepSection, "step_" + file_stem(metric),
                  fmt::format("|Relative error| of the {} against the engine step", metric_title(metric)), false};
        std::string cmd;
        int index = 0;
        for (const StepSeries& series : all) {
            if (series.metric != metric) continue;
            bool any = false;
            for (double e : series.rel_error) any = any || (std::isfinite(e) && e != 0.0);
            if (!any) continue;  // nothing to draw on a log axis
            s.dat += fmt::format("# {} {} {}\n# dt_ms abs_rel_error_percent\n", series.engine, series.base_case, metric);
            for (std::size_t i = 0; i < series.dt.size(); ++i)
                s.dat += gp_number(1e3 * series.dt[i], true) + ' ' +
                         gp_number(100.0 * std::abs(series.rel_error[i]), true) + '\n';
            s.dat += "\n\n";
            cmd += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints title {}", index == 0 ? "plot " : ", \\\n     ",
                               s.plot.name, index,
                               gp_string(engine_display_name(series.engine) + " " + series.base_case));
            ++index;
        }
        if (index == 0) continue;
        if (const auto target = target_of(metric))
            cmd += fmt::format(", \\\n     {0:g} with lines dt 2 lc rgb '#888888' title 'target {0:g} %'", 100.0 * *target);
        s.gp = gp_preamble("vssw report", s.plot.name, kPlotWidth, kPlotHeight) +
               fmt::format("set title {}\nset logscale xy\nset format y '%g'\nset xlabel 'engine step dt [ms]'\n"
                           "set ylabel '|relative error| [%]'\n",
                           gp_string(s.plot.title)) +
               cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

}  // namespace

std::vector<PlotScript> report_plot_scripts(const ReportInput& in) {
    std::vector<PlotScript> scripts = trace_scripts(in);
    for (auto* more : {&error_scripts, &step_scripts})
        for (PlotScript& s : (*more)(in)) scripts.push_back(std::move(s));
    return scripts;
}

PlotResult write_plots(const ReportInput& in, const fs::path& plots_dir, const PlotOptions& options) {
    return draw_plots(report_plot_scripts(in), plots_dir, options.gnuplot);
}

}  // namespace vssw::study

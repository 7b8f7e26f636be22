#include "apps/report_suite_plots.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <map>
#include <system_error>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "study/atomic_file.hpp"

namespace vssw::cli {
namespace fs = std::filesystem;
namespace {

// Exit status of a program that could not be started (the shell's convention).
constexpr int kNotFound = 127;

// Plot sizes in SVG pixels; the error plots widen with the number of cases so their labels stay readable.
constexpr int kPlotWidth = 820, kPlotHeight = 420, kPixelsPerCase = 34;

std::string gp_string(const std::string& text) {
    std::string s = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') s += '\\';
        s += c;
    }
    return s + '"';
}

// A number for a gnuplot data file; '?' (declared missing) for NaN, infinity and, on log axes, what is not positive.
std::string gp_number(double v, bool positive_only = false) {
    if (!std::isfinite(v) || (positive_only && v <= 0.0)) return "?";
    return fmt::format("{:.10g}", v);
}

std::string preamble(const std::string& name, int width, int height) {
    return fmt::format(
        "# Drawn by `vssw report`; re-draw with: gnuplot {0}.gp\n"
        "set encoding utf8\n"
        "set terminal svg size {1},{2} noenhanced font 'sans,11' background rgb 'white'\n"
        "set output '{0}.svg'\n"
        "set datafile missing '?'\n"
        "set grid lc rgb '#dddddd'\n"
        "set key outside right top\n",
        name, width, height);
}

// Runs `program script` in dir with stdin from /dev/null and stdout/stderr into log. The exit status; kNotFound when
// the program could not be started; -1 when fork failed.
int run_program(const std::string& program, const std::string& script, const fs::path& dir, const fs::path& log) {
    const pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        if (chdir(dir.c_str()) != 0) _exit(kNotFound - 1);
        const int in = open("/dev/null", O_RDONLY);
        if (in >= 0) dup2(in, 0);
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        execlp(program.c_str(), program.c_str(), script.c_str(), static_cast<char*>(nullptr));
        _exit(kNotFound);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

struct Script {
    Plot plot;
    std::string gp, dat;  // contents
};

std::vector<Script> trace_scripts(const ReportInput& in) {
    std::vector<std::string> cases;  // in the order of the traces
    for (const compare::Trace& t : in.results.traces)
        if (std::find(cases.begin(), cases.end(), t.case_id) == cases.end()) cases.push_back(t.case_id);
    std::vector<Script> scripts;
    for (const std::string& id : cases) {
        std::vector<const compare::Trace*> traces;  // analytic first
        for (const compare::Trace& t : in.results.traces)
            if (t.case_id == id && t.engine == "analytic") traces.push_back(&t);
        for (const compare::Trace& t : in.results.traces)
            if (t.case_id == id && t.engine != "analytic") traces.push_back(&t);
        Script s;
        s.plot = {PlotSection::traces, "trace_" + file_stem(id),
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
        s.gp = preamble(s.plot.name, kPlotWidth, kPlotHeight) +
               fmt::format("set title {}\nset xlabel 't [s]'\nset ylabel 'theta1 / alpha'\n", gp_string(s.plot.title)) +
               plot_cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

std::vector<Script> error_scripts(const ReportInput& in) {
    std::vector<Script> scripts;
    for (const MetricTable& table : metric_tables(in)) {
        // Overturning is yes/no (its "error" is 0 or +-1): its table says it all.
        if (table.engines.empty() || table.metric == "overturned") continue;
        Script s;
        s.plot = {PlotSection::errors, "error_" + file_stem(table.metric),
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
        s.gp = preamble(s.plot.name, width, kPlotHeight + 80) +
               fmt::format("set title {}\nset ylabel 'relative error [%] (engine / reference - 1)'\n"
                           "set xrange [-0.6:{}]\nset xtics rotate by -35 left\nset bmargin 9\n",
                           gp_string(s.plot.title), static_cast<double>(table.rows.size()) - 0.4) +
               cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

std::vector<Script> step_scripts(const ReportInput& in) {
    const std::vector<StepSeries> all = step_series(in);
    std::vector<std::string> metrics;
    for (const StepSeries& s : all)
        if (std::find(metrics.begin(), metrics.end(), s.metric) == metrics.end()) metrics.push_back(s.metric);
    std::vector<Script> scripts;
    for (const std::string& metric : metrics) {
        Script s;
        s.plot = {PlotSection::steps, "step_" + file_stem(metric),
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
        s.gp = preamble(s.plot.name, kPlotWidth, kPlotHeight) +
               fmt::format("set title {}\nset logscale xy\nset format y '%g'\nset xlabel 'engine step dt [ms]'\n"
                           "set ylabel '|relative error| [%]'\n",
                           gp_string(s.plot.title)) +
               cmd + "\n";
        scripts.push_back(std::move(s));
    }
    return scripts;
}

// Through a temporary file renamed on success (atomic_file.hpp); false when it cannot be written.
bool write_text(const fs::path& path, const std::string& text) {
    try {
        study::AtomicFile f(path);
        f.stream() << text;
        f.commit();
        return true;
    } catch (const InputError&) {
        return false;
    }
}

}  // namespace

PlotResult write_plots(const ReportInput& in, const fs::path& plots_dir, const PlotOptions& options) {
    PlotResult result;
    std::error_code ec;
    fs::create_directories(plots_dir, ec);
    if (ec) {
        result.note = fmt::format("cannot create {}: {}", plots_dir.string(), ec.message());
        return result;
    }
    std::vector<Script> scripts = trace_scripts(in);
    for (auto* more : {&error_scripts, &step_scripts})
        for (Script& s : (*more)(in)) scripts.push_back(std::move(s));

    // A program named with a '/' is a path: make it absolute, gnuplot runs in plots_dir.
    std::string program = options.gnuplot;
    if (program.find('/') != std::string::npos) program = fs::absolute(program, ec).string();

    bool gnuplot_missing = false;
    std::vector<std::string> failed;
    for (Script& s : scripts) {
        const fs::path gp = plots_dir / (s.plot.name + ".gp"), svg = plots_dir / (s.plot.name + ".svg"),
                       log = plots_dir / (s.plot.name + ".log");
        if (!write_text(gp, s.gp) || !write_text(plots_dir / (s.plot.name + ".dat"), s.dat)) {
            failed.push_back(s.plot.name + " (cannot write its script or data)");
            continue;
        }
        fs::remove(svg, ec);
        if (!gnuplot_missing) {
            const int status = run_program(program, s.plot.name + ".gp", plots_dir, log);
            if (status == kNotFound) gnuplot_missing = true;
            s.plot.made = status == 0 && fs::exists(svg, ec) && fs::file_size(svg, ec) > 0;
            if (s.plot.made) fs::remove(log, ec);
            else if (!gnuplot_missing) failed.push_back(fmt::format("{} (gnuplot exit {}, see {}.log)", s.plot.name,
                                                                    status, s.plot.name));
        }
        result.plots.push_back(s.plot);
    }
    if (gnuplot_missing) {
        for (const Script& s : scripts) fs::remove(plots_dir / (s.plot.name + ".log"), ec);
        result.note = fmt::format("gnuplot ('{}') could not be run: no plots were drawn (their scripts and data are "
                                  "in plots/; install gnuplot, Debian package gnuplot-nox, and run them)",
                                  options.gnuplot);
    } else if (!failed.empty()) {
        result.note = fmt::format("{} plot{} failed: {}", failed.size(), failed.size() == 1 ? "" : "s",
                                  fmt::join(failed, "; "));
    }
    result.all_made = !gnuplot_missing && failed.empty();
    return result;
}

}  // namespace vssw::cli

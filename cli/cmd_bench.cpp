// `vssw bench`: work-precision. Each backend swept over the settings that trade cost for accuracy on the reference
// problems (validation/work_precision.hpp), CPU time against error; the files and plots written into a folder
// (validation/bench_files.hpp), the cheapest settings within the targets printed.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "cli/build_commit.hpp"
#include "cli/message_line.hpp"
#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "cli/simulation_failure.hpp"
#include "compare/targets.hpp"
#include "io/json.hpp"
#include "validation/work_precision.hpp"
#include "multibody/engine.hpp"
#include "validation/bench_files.hpp"
#include "io/clock.hpp"
#include "io/folder_swap.hpp"

namespace vssw::cli {
namespace {

// --repeats: each repeat re-runs the whole experiment; 100 is far more than a median needs.
constexpr int kMaxRepeats = 100;
// The default: three repeats give a median that one descheduled run cannot move.
constexpr int kDefaultRepeats = 3;

struct BenchCommandOptions {
    std::string out;
    std::vector<std::string> engines, problems;
    std::string repeats = std::to_string(kDefaultRepeats);
    bool quick = false, json = false, no_plots = false;
    std::string gnuplot = "gnuplot";
    std::string data = shipped_data_dir();
};

// Without --engines: every backend in this build, the analytic model first.
std::vector<std::string> bench_engines(const std::vector<std::string>& asked) {
    return asked.empty() ? multibody::available_engines() : parse_engine_list("--engines", asked);
}

std::vector<std::string> bench_problems(const std::vector<std::string>& asked, bool quick) {
    if (asked.empty()) return validation::default_bench_problems(quick);
    for (const std::string& name : asked) validation::check_bench_problem(name);
    return asked;  // each named once (list_items)
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "";
    return one + " " + five + " " + fifteen;
}

}  // namespace

Command add_bench_command(CLI::App& root) {
    auto o = std::make_shared<BenchCommandOptions>();
    CLI::App* cmd = root.add_subcommand(
        "bench", "Work-precision: CPU time against error per backend and setting; files and plots into a folder");
    cmd->add_option("--out", o->out, "folder to write into (created if missing) (required)")->required();
    add_list_option(*cmd, "--engines", o->engines,
                    fmt::format("backends, comma-separated ('all': {}; default: every one in this build: {})",
                                fmt::join(multibody::default_compared_engines(), ", "),
                                fmt::join(multibody::available_engines(), ", ")));
    add_list_option(*cmd, "--problems", o->problems,
                    fmt::format("reference problems, comma-separated (default: all: {}; --quick: {})",
                                fmt::join(validation::bench_problem_names(), ", "),
                                fmt::join(validation::default_bench_problems(true), ", ")));
    cmd->add_option("--repeats", o->repeats,
                    fmt::format("runs per point, the CPU time their median, 1 to {} (default {})", kMaxRepeats,
                                kDefaultRepeats));
    cmd->add_flag("--quick", o->quick,
                  "a small sweep (two analytic tolerances, each engine at its defaults; seconds): the CTest's");
    cmd->add_flag("--json", o->json, "print bench.json instead of the table");
    cmd->add_flag("--no-plots", o->no_plots, "write no plots (no gnuplot run)");
    cmd->add_option("--gnuplot", o->gnuplot, "the gnuplot program (default: gnuplot from PATH)");
    cmd->add_option("--data", o->data, "folder of the shipped records (default: $VSSW_DATA_DIR, else <prefix>/share/vssw/data beside an installed vssw, else the source tree's data/)");
    cmd->footer(
        "Problems: threshold (Fig. 6 VSSW, against Eq. 12), fig6-free, t1-free (Table 1 #1, xi 0.5), pw-free (Fig. 6\n"
        "PW) free vibrations from 0.5 alpha (period against the analytic model, exact kinematics; restitution against\n"
        "the whole-mechanism impact for an engine, Eq. 19 / Housner for the analytic model), record (peak rotation of\n"
        "the Fig. 6 VSSW under Rinaldi 228 x 0.45 against the analytic model). Errors are relative, |value/ref - 1|.\n"
        "Writes bench.json, bench.csv (engine, problem, metric, setting, dt, iterations, knobs, cpu_s, noise, repeats,\n"
        "cpu_repeats, value, reference, error, pareto, failure), bench.md (the cheapest settings within the targets)\n"
        "and plots/wp_<problem>_<metric>.svg. A failed run is a row with its failure and no error (exit 0).\n"
        "Exit 2 on bad input (unknown engine or problem, --repeats out of range, unwritable --out); exit 3 when a\n"
        "problem's converged analytic reference cannot be measured (then no point of it could be), nothing written.");
    return {cmd, {}, [o](std::ostream& out, std::ostream& err) {
                validation::BenchOptions options;
                options.engines = bench_engines(o->engines);
                options.problems = bench_problems(o->problems, o->quick);
                options.repeats = parse_bounded_int("--repeats", o->repeats, 1, kMaxRepeats);
                options.quick = o->quick;
                options.record_path = (std::filesystem::path(o->data) / "NGA_no_1063_RRS228.AT2").string();
                if (std::find(options.problems.begin(), options.problems.end(), "record") != options.problems.end() &&
                    !std::filesystem::is_regular_file(options.record_path))
                    throw InputError(fmt::format("--data: no record {} (the problem 'record' needs it)",
                                                 options.record_path));
                for (const std::string& name : options.engines)
                    (void)validation::bench_sweep(*multibody::make_engine(name), options.quick);  // settings checked
                // An unwritable --out fails before the sweep, not after it; nothing is made in it until the files
                // are complete (a staging folder then replaces it whole: io/folder_swap.hpp).
                const io::FolderLock lock = io::check_out_folder(o->out, io::OutKind::bench);
                io::check_inputs_not_outputs(o->out, io::OutKind::bench, {{"the record", options.record_path}});

                validation::BenchMeta meta{io::utc_now(), build_commit(), load_average(), options.repeats, o->quick,
                                      options.engines, options.problems};
                std::vector<validation::BenchPoint> points;
                try {
                    points = validation::run_bench(options, [&err](const validation::BenchPoint& p) {
                        err << fmt::format("vssw bench: {} {} {} {}: {:.4g} s, error {}\n", p.engine, p.problem,
                                           p.metric, p.setting, p.cpu.median,
                                           p.failure.empty() ? fmt::format("{:.3g}", p.error) : "failed: " + p.failure);
                    });
                } catch (const multibody::EngineFailure& e) {
                    // A point's failure is a row of the bench; what escapes is the reference's own: no result (exit 3).
                    throw SimulationFailure(e.what());
                }
                const validation::BenchData data = validation::bench_data(meta, std::move(points));
                io::StagedFolder staged(o->out, io::OutKind::bench);
                staged.create();
                const io::PlotResult plots =
                    validation::write_bench(data, staged.path(), o->no_plots ? std::string() : o->gnuplot);
                staged.commit();
                if (!o->no_plots && !plots.note.empty()) print_message_line(err, "warning", plots.note);
                if (o->json) {
                    out << io::dump_json(validation::bench_json(data), 2) << '\n';
                    return;
                }
                out << fmt::format("vssw bench: {} point{}, {} repeat{} each; files in {}\n", data.points.size(),
                                   data.points.size() == 1 ? "" : "s", options.repeats,
                                   options.repeats == 1 ? "" : "s", o->out)
                    << fmt::format("Cheapest settings within the targets (threshold {:g} %, period {:g} %, "
                                   "restitution {:g} %):\n",
                                   100.0 * compare::kThresholdTarget, 100.0 * compare::kPeriodTarget,
                                   100.0 * compare::kRestitutionTarget)
                    << validation::cheapest_markdown(data);
            }};
}

}  // namespace vssw::cli

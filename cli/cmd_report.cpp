// `vssw report`: the validation suite (validation/suite.hpp) run for the analytic model and every engine, written as a
// report (Markdown, HTML with inline plots), machine-readable results (JSON, CSV) and gnuplot plots in one folder.
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/assumption_sets.hpp"
#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "cli/build_commit.hpp"
#include "cli/message_line.hpp"
#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "cli/progress.hpp"
#include "cli/run_budget_option.hpp"
#include "compare/targets.hpp"
#include "validation/assumptions_part.hpp"
#include "validation/earthquake.hpp"
#include "validation/suite.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/engine_names.hpp"
#include "validation/bench_files.hpp"
#include "io/clock.hpp"
#include "io/folder_swap.hpp"
#include "validation/report_write.hpp"
#include "validation/suite_file.hpp"

namespace vssw::cli {
namespace {


struct ReportCommandOptions {
    std::string suite = "default";
    std::vector<std::string> engines;
    std::vector<std::string> cases;
    std::string threads_text = "0";  // --threads as typed, checked by parse_bounded_int
    int threads = 0;
    bool no_plots = false;
    std::string bench;  // a finished `vssw bench` folder to include
    std::string gnuplot = "gnuplot";
    std::string data = shipped_data_dir();
    std::string out;
    // --earthquake: the record ensemble the report judges the engines on (validation/earthquake.hpp); "default" is
    // the shipped one, "none" runs none. Not given with --cases: none (a case subset is a quick run).
    std::string earthquake = "default";
    CLI::Option* earthquake_option = nullptr;
    // --relaxations: the study that relaxes the paper's physical assumptions (validation/assumptions_part.hpp).
    std::string relaxations = "default";
    CLI::Option* relaxations_option = nullptr;
    // --assumptions: the reference's set (analytic/assumption_sets.hpp); the other set gets its own row.
    std::string assumptions = to_string(kDefaultAssumptionSet);
    CLI::Option* assumptions_option = nullptr;
};

// The suite's reference: --assumptions, else the suite file's set, else the default. A suite file that names one set
// and an --assumptions that names the other are refused: the engines are measured against one model.
void choose_reference(const ReportCommandOptions& o, validation::Suite& suite) {
    AssumptionSet set = kDefaultAssumptionSet;
    try {
        set = parse_assumption_set(o.assumptions);
    } catch (const InputError& e) {
        throw InputError(fmt::format("--assumptions {}: {}", o.assumptions, e.what()));
    }
    if (o.assumptions_option->count() == 0) return;  // the file's set, or the default
    if (suite.reference_named && suite.reference != set)
        throw InputError(fmt::format("--assumptions {}: the suite file {} names the reference {} ([assumptions]); "
                                     "give one",
                                     o.assumptions, o.suite, to_string(suite.reference)));
    suite.reference = set;
}

// Without --engines: multibody::default_compared_engines() (all but the analytic model, which always runs as the
// reference, and simbody-rigid). "analytic" is the reference anyway; a name given twice is refused (list_items).
std::vector<std::string> checked_engines(const std::vector<std::string>& asked) {
    if (asked.empty()) return multibody::default_compared_engines();
    const std::vector<std::string> available = multibody::available_engines();
    std::vector<std::string> engines;
    for (const std::string& given : asked) {
        const std::optional<std::string> name = multibody::canonical_engine(given);  // "ODE" is ode
        if (!name)
            throw InputError(fmt::format("--engines: no engine '{}' in this build{} (available: {})", given,
                                         multibody::engine_name_hint(given), fmt::join(available, ", ")));
        if (std::find(engines.begin(), engines.end(), *name) != engines.end())
            throw InputError(fmt::format("--engines names '{}' more than once", *name));
        if (*name != "analytic") engines.push_back(*name);
    }
    return engines;
}


// --data must be an existing folder: a mistyped path is refused before anything is created.
void require_data_folder(const std::string& data) {
    std::error_code ec;
    if (!std::filesystem::is_directory(data, ec))
        throw InputError(fmt::format("--data: '{}' is not an existing folder (it should hold the ground-motion "
                                     "records)",
                                     data));
}

// Every record the selected cases need is read once here, before the output folder is made, so that a missing or
// malformed record is refused (exit 2) without leaving a folder behind; run_suite uses them (RunOptions::records_read).
std::map<std::string, GroundMotion> read_records_up_front(const validation::Suite& suite) {
    std::map<std::string, GroundMotion> read;
    for (const validation::SuiteRecord& r : suite.records)
        if (!read.count(r.path)) read.emplace(r.path, read_record(r.path));
    return read;
}

// The files the report reads that could live where it writes: a suite file, and the records it names.
std::vector<std::pair<std::string, std::filesystem::path>> report_inputs(const std::string& suite_arg,
                                                                         const validation::Suite& suite) {
    std::vector<std::pair<std::string, std::filesystem::path>> inputs;
    std::error_code ec;
    if (std::filesystem::is_regular_file(suite_arg, ec)) inputs.emplace_back("the suite file", suite_arg);
    for (const validation::SuiteRecord& r : suite.records) inputs.emplace_back("the record", r.path);
    return inputs;
}

// A part's study (the earthquake's, the relaxations') run by `run` with the report's options, its progress shown as
// "<label>: ..."; none when no file is asked for.
template <class Options, class Run>
auto run_part(const ReportCommandOptions& o, const std::string& file, const std::string& label, Options options,
              Progress& progress, const Run& run) -> std::optional<decltype(run(options))> {
    if (file.empty()) return std::nullopt;
    options.threads = o.threads;
    options.plots = !o.no_plots;
    options.gnuplot = o.gnuplot;
    options.commit = build_commit();
    if (progress.on())
        options.progress = [&progress, label](long done, long total, const std::string& what) {
            progress.show(done, total, label + ": " + what);
        };
    auto part = run(options);
    progress.clear();
    return part;
}

// The earthquake part (validation/earthquake.hpp) into the staging folder's `dir`; none when no file is asked for.
std::optional<validation::EarthquakePart> run_earthquake(const ReportCommandOptions& o, const std::string& file,
                                                    const std::vector<std::string>& engines,
                                                    const std::filesystem::path& dir, Progress& progress) {
    validation::EarthquakeRunOptions eq;
    eq.paper_model = true;  // the paper's model's row under records (analytic runs only: cheap)
    return run_part(o, file, "earthquake", eq, progress, [&](const validation::EarthquakeRunOptions& run) {
        return validation::run_earthquake_part(file, engines, dir, run);
    });
}

// The study file of the relaxations: --relaxations, else the suite's default; none with --cases unless asked.
std::string relaxations_study_file(const ReportCommandOptions& o, const std::vector<std::string>& engines) {
    const bool given = o.relaxations_option->count() > 0;
    if (!given && !o.cases.empty()) return "";
    return validation::assumptions_study_file(
        given ? o.relaxations : validation::default_assumptions_for_suite(o.suite), engines);
}

// The relaxations of the paper's assumptions (validation/assumptions_part.hpp) into `dir`; none when no file is asked.
std::optional<validation::AssumptionsPart> run_relaxations(const ReportCommandOptions& o, const std::string& file,
                                                           const std::vector<std::string>& engines,
                                                           const std::filesystem::path& dir, Progress& progress) {
    return run_part(o, file, "relaxations", validation::PartRunOptions(), progress,
                    [&](const validation::PartRunOptions& run) {
                        return validation::run_assumptions_part(file, engines, dir, run);
                    });
}

// What --help says after the options: the files, the targets (formatted from the constants the report judges by:
// compare/targets.hpp, validation/earthquake.hpp), the JSON keys and CSV columns, the exit codes.
std::string report_footer() {
    return
        "Writes into --out: report.md and report.html (the same content; the HTML is self-contained, plots inline),\n"
        "results.json, metrics.csv, failures.csv, traces.csv and plots/ (gnuplot .svg, with the .gp script and .dat\n"
        "data beside each: trace_<case>, error_<metric>, step_<metric>). error: engine / reference - 1\n"
        "(rms_difference: the RMS difference over the analytic peak; overturned: engine - reference, 0 or +-1); "
        "targets:\n" +
        fmt::format("threshold {:g} %, period {:g} %, restitution {:g} %; under records (earthquake/), run by run\n"
                    "against the reference: the median ln(peak / reference's) where both stand within +-{:g}, and\n"
                    "overturning with McNemar's p >= {:g} and agreement >= {:g} (the fragility median is information).\n",
                    100.0 * compare::kThresholdTarget, 100.0 * compare::kPeriodTarget,
                    100.0 * compare::kRestitutionTarget, validation::kPeakLogRatioTarget, validation::kMcNemarAlpha,
                    validation::kOverturningAgreementTarget) +
        "results.json keys: vssw {commit, report_format}, date, suite {name, walls, records, cases [{id, kind, wall,\n"
        "r, record, dt}]}, engines [{name, version, contact_scheme, settings {dt, iterations (where set), knobs}}],\n"
        "targets, rows [{case_id, engine, metric, unit, reference, analytic, engine_value, error, target,\n"
        "within_target}],\n"
        "failures [{case_id, engine, message}], summary [{engine, line, within, with_target, not_measured, failures,\n"
        "max_error}], matrix [{engine, metric, worst_error, case_id, target, pass, rows, not_measured, failed}],\n"
        "reference_assumptions, other_set {engine, assumptions, label, finding, matrix (no pass), rows, failures},\n"
        "findings, step_study [{engine, case_id, metric, dt, rel_error, order}], traces [{case_id, engine,\n"
        "assumption, samples}], earthquake {study, folder, reference, reference_median_g, reference_median_note,\n"
        "targets, records, levels, rows, failed_rows, engines [{engine, settings, pass, overturning_agreement {value,\n"
        "lo, hi, n, pass, failed_runs}, overturning_mcnemar {overturned_alone, stood_alone, failed_runs, p, pass},\n"
        "peak_log_ratio {value, lo, hi, n, median_ratio, runs, records, note, pass, target,\n"
        "band_half_width}, fragility_median_ratio {..., note, verdict, failed_replicates}, peak_ratio, inside_band}],\n"
        "stand_ins [the same, with restitution_error], detection_limit_restitution_error, paper_model [the same keys,\n"
        "for the analytic model under the set paper: no verdict in the report; null when it did not run]}\n"
        "(null when none ran), plots {made, note}, wall_time_s, threads; NaN is null. earthquake/ is the ensemble's\n"
        "study folder (results.csv, agreement.csv, fragility.csv, plots).\n"
        "CSV columns: metrics.csv case_id,engine,metric,unit,reference,analytic,engine_value,error;\n"
        "failures.csv case_id,engine,message; traces.csv case_id,engine,t,theta1_over_alpha1,assumption (t to 6,\n"
        "theta1/alpha1 to 4 significant digits; assumption: the analytic model's set, mechanism or paper).\n"
        "An engine failing on a case is reported (exit 0). Exit 2 on bad input (unknown suite, engine or case, an\n"
        "--out that is not a writable folder). Without gnuplot the report is written without plots (a warning).";
}

}  // namespace

// --assumptions (the reference's set), --earthquake and --relaxations (the two studies the report runs beside the
// suite).
void add_part_options(CLI::App& cmd, ReportCommandOptions& o) {
    o.assumptions_option = cmd.add_option(
        "--assumptions", o.assumptions,
        fmt::format("the free-vibration cases' reference: the analytic model under the set {} or {} (default {}); "
                    "the analytic model under the other set is measured like an engine in a row of its own, with no "
                    "verdict. Under records the reference is always the set mechanism (what the engines realise), "
                    "and the paper's model is the row of its own",
                    describe(AssumptionSet::mechanism), describe(AssumptionSet::paper),
                    to_string(kDefaultAssumptionSet)));
    o.earthquake_option = cmd.add_option(
        "--earthquake", o.earthquake,
        "the record ensemble judged under \"Under earthquake records\": default (studies/ensemble-report.toml: 4 "
        "records x 4 PGAs on the Fig. 6 VSSW), full (studies/ensemble-report-full.toml: the 26 shipped records x the "
        "same PGAs), a study file of kind \"ensemble\" with levels, or none (default: full with --suite full, else "
        "default; none with --cases)");
    o.relaxations_option = cmd.add_option(
        "--relaxations", o.relaxations,
        "the study under \"What the paper's assumptions cost\": default (studies/assumptions-report.toml: the Fig. 6 "
        "VSSW's threshold and free vibration with each physical assumption relaxed alone, a pulse for the diaphragm), "
        "full (studies/assumptions-physical.toml: Table 1 walls, rocking curves and fragility too; minutes), a study "
        "file that varies one of them, or none (default: full with --suite full, else default; none with --cases)");
}

Command add_report_command(CLI::App& root) {
    auto o = std::make_shared<ReportCommandOptions>();
    CLI::App* cmd = root.add_subcommand(
        "report", "Run the validation suite for the analytic model and the engines; write a report into a folder");
    cmd->add_option("--suite", o->suite,
                    "default (about 40 s on 2 cores with the default engines, the earthquake part included), "
                    "full (233 cases), or a suite file (a study file whose parts name their walls: "
                    "studies/validation-default.toml is one)");
    add_list_option(*cmd, "--engines", o->engines,
                    fmt::format("engines to compare, comma-separated (default: {}; simbody-rigid on request)",
                                fmt::join(multibody::default_compared_engines(), ", ")));
    add_list_option(*cmd, "--cases", o->cases, "only these case ids, comma-separated (e.g. fig6-vssw,fig6-vssw/r0.5)");
    cmd->add_option("--threads", o->threads_text,
                    fmt::format("worker threads, 0 to {} (default 0: the available cores)", kMaxThreads));
    cmd->add_flag("--no-plots", o->no_plots, "write no plots (no gnuplot run)");
    add_run_budget_option(*cmd);
    cmd->add_option("--bench", o->bench,
                    "a finished `vssw bench --out DIR` folder: its cheapest settings and work-precision plots end the "
                    "report (the report does not run the sweep)");
    add_part_options(*cmd, *o);
    cmd->add_option("--gnuplot", o->gnuplot, "the gnuplot program (default: gnuplot from PATH)");
    cmd->add_option("--data", o->data, "folder of the ground-motion records (default: $VSSW_DATA_DIR, else <prefix>/share/vssw/data beside an installed vssw, else the source tree's data/)");
    cmd->add_option("--out", o->out, "folder to write into (created if missing) (required)")->required();
    cmd->footer(report_footer());
    return {cmd, {}, [o](std::ostream& out, std::ostream& err) {
                const std::vector<std::string> engines = checked_engines(o->engines);
                o->threads = parse_threads(o->threads_text);
                require_data_folder(o->data);
                if (!o->bench.empty()) validation::check_bench_dir(o->bench);
                validation::Suite suite = validation::read_suite(o->suite, o->data);
                if (!o->cases.empty()) suite = validation::select_cases(suite, o->cases);
                choose_reference(*o, suite);
                const std::map<std::string, GroundMotion> records = read_records_up_front(suite);
                const bool earthquake_asked = o->earthquake_option->count() > 0 || o->cases.empty();
                const std::string earthquake_name = o->earthquake_option->count() > 0
                                                        ? o->earthquake
                                                        : validation::default_earthquake_for_suite(o->suite);
                const std::string earthquake_file =
                    earthquake_asked ? validation::earthquake_study_file(earthquake_name, engines) : std::string();
                const std::string relaxations_file = relaxations_study_file(*o, engines);
                const std::filesystem::path dir = o->out;
                // After every other check, before the suite runs. Nothing is made in --out until the report is
                // complete: it is written into a staging folder that then replaces --out whole (a failed run leaves
                // --out as it was, or leaves none).
                const io::FolderLock lock = io::check_out_folder(dir, io::OutKind::report);
                io::check_inputs_not_outputs(dir, io::OutKind::report, report_inputs(o->suite, suite));

                Progress progress(err);
                validation::RunOptions run;
                run.threads = o->threads;
                run.other_set = true;
                run.records_read = &records;
                if (progress.on())
                    run.progress = [&progress](int done, int total, const std::string& what) {
                        progress.show(done, total, what);
                    };
                validation::SuiteResults results;
                try {
                    results = validation::run_suite(suite, engines, run);
                } catch (...) {
                    progress.clear();
                    throw;
                }
                progress.clear();

                validation::ReportMeta meta;
                meta.date = io::utc_now();
                meta.commit = build_commit();
                validation::ReportOptions options;
                options.plots = !o->no_plots;
                options.plot.gnuplot = o->gnuplot;
                options.bench_dir = o->bench;
                io::StagedFolder staged(dir, io::OutKind::report);
                staged.create();
                const std::optional<validation::EarthquakePart> earthquake =
                    run_earthquake(*o, earthquake_file, engines, staged.path() / "earthquake", progress);
                if (earthquake) options.earthquake = &*earthquake;
                const std::optional<validation::AssumptionsPart> relaxations =
                    run_relaxations(*o, relaxations_file, engines, staged.path() / "relaxations", progress);
                if (relaxations) options.relaxations = &*relaxations;
                validation::ReportFiles files = validation::write_suite_report(staged.path(), suite, results, meta, options);
                staged.commit();
                for (std::filesystem::path* p : {&files.dir, &files.markdown, &files.html, &files.json})
                    *p = staged.final_path(*p);
                for (const std::string& w : files.warnings) print_message_line(err, "warning", w);

                // The count of cases report.html states (a step case of an engine not asked for did not run).
                out << fmt::format("vssw report: suite {}, {}, {} engine{} besides the analytic model, "
                                   "{:.1f} s on {} thread{}\n",
                                   results.suite, validation::case_count_text(suite, results), engines.size(),
                                   engines.size() == 1 ? "" : "s", results.wall_time_s, results.threads,
                                   results.threads == 1 ? "" : "s");
                out << "  report.md     " << files.markdown.string() << '\n'
                    << "  report.html   " << files.html.string() << '\n'
                    << "  results.json  " << files.json.string() << '\n';
                for (const std::string& line : files.summary_lines) out << line << '\n';
                if (earthquake)
                    for (const std::string& line : validation::earthquake_summary_lines(*earthquake)) out << line << '\n';
                if (relaxations)
                    for (const std::string& line : validation::assumptions_summary_lines(*relaxations)) out << line << '\n';
                if (!results.failures.empty())
                    out << fmt::format("{} engine failure{}: see the report's Failures section\n",
                                       results.failures.size(), results.failures.size() == 1 ? "" : "s");
            }};
}

}  // namespace vssw::cli

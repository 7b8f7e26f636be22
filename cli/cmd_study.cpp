// `vssw study FILE --out DIR`: a grid of walls x assumptions x excitations x engines (study/spec.hpp), run on every
// core, in shards or across MPI processes, written as tidy results, plots and a summary in plain words.
// `vssw study merge DIR1 DIR2 ... --out DIR` joins shards.
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/assumption_sets.hpp"
#include "analytic/error.hpp"
#include "cli/build_commit.hpp"
#include "cli/message_line.hpp"
#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "io/json.hpp"
#include "cli/option_values.hpp"
#include "cli/progress.hpp"
#include "cli/quiet_exit.hpp"
#include "cli/run_budget_option.hpp"
#include "cli/simulation_failure.hpp"
#include "io/folder_lock.hpp"
#include "io/folder_swap.hpp"
#include "study/grid.hpp"
#include "study/measure.hpp"
#include "study/merge.hpp"
#include "study/metric_catalog.hpp"
#include "study/mpi.hpp"
#include "study/outputs.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"

namespace vssw::cli {
namespace {

// A study of more tasks (cases x runs) than this needs --force: a list typed with one zero too many would otherwise
// start days of work. 10,000 analytic tasks take about a minute on 2 cores; 10,000 engine tasks, hours.
constexpr long kMaxTasksWithoutForce = 10000;

struct StudyOptions {
    std::string file;
    std::string out;
    std::string threads_text = "0";
    std::string shard_text = "1/1";
    bool resume = false, force = false, json = false, no_plots = false, strict = false;
    std::string gnuplot = "gnuplot";
    std::vector<std::string> merge_dirs;
};

study::Shard parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    const auto whole = [&](const std::string& part) {
        char* end = nullptr;
        const long v = std::strtol(part.c_str(), &end, 10);
        return !part.empty() && *end == '\0' ? v : -1;
    };
    const long k = slash == std::string::npos ? -1 : whole(text.substr(0, slash));
    const long n = slash == std::string::npos ? -1 : whole(text.substr(slash + 1));
    if (k < 1 || n < 1 || k > n || n > 100000)
        throw InputError(fmt::format("--shard must be K/N with 1 <= K <= N <= 100000 (shard K of N), got '{}'", text));
    return {static_cast<int>(k), static_cast<int>(n)};
}

// The study's tasks at most (cases x runs of every part, before repeats are left out), from the file alone: so that a
// grid too large is refused before its cases are built.
double tasks_at_most(const study::StudySpec& spec) {
    double total = 0.0;
    for (const study::PartSpec& part : spec.parts) {
        const double cases = study::case_count(part);
        double runs = 0.0;
        for (const study::EngineSpec& e : part.engines) {
            double r = 1.0;
            for (const study::Axis& a : e.settings) r *= static_cast<double>(a.levels.size());
            if (e.name == "analytic")
                for (const study::Axis& a : spec.assumptions) r *= static_cast<double>(a.levels.size());
            runs += r;
        }
        total += cases * runs;
    }
    return total;
}


void print_outputs(std::ostream& out, const std::string& dir, const study::OutputFiles& files) {
    out << "  " << dir << "/results.csv\n";
    for (const auto& f : files.written) out << "  " << f.string() << '\n';
}

// The files a study reads that live where it writes: the study file, and every record the grid names.
std::vector<std::pair<std::string, std::filesystem::path>> study_inputs(const std::string& file,
                                                                        const study::Grid& grid) {
    std::vector<std::pair<std::string, std::filesystem::path>> inputs = {{"the study file", file}};
    for (const study::PartSpec& part : grid.spec().parts)
        for (const study::Axis& a : part.excitation)
            if (a.key == "file")
                for (const study::Level& level : a.levels)
                    if (const auto* name = std::get_if<std::string>(&level))
                        inputs.emplace_back("the record", grid.record_path(*name));
    return inputs;
}

// The paths of files written into the staging folder, as they are named once it has replaced --out.
study::OutputFiles as_committed(study::OutputFiles files, const io::StagedFolder& staged) {
    for (auto& f : files.written) f = staged.final_path(f);
    return files;
}

void run_merge(const StudyOptions& o, std::ostream& out, std::ostream& err) {
    std::vector<std::filesystem::path> dirs(o.merge_dirs.begin(), o.merge_dirs.end());
    // A study still running in --out, or one killed there that --resume would finish, is not replaced by a merge:
    // the same lock and the same refusal as a study's own.
    const io::FolderLock lock = io::check_out_folder(o.out, io::OutKind::study);
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::path(o.out) / study::kJournalFile, ec))
        throw InputError(fmt::format("--out '{}' holds an unfinished study ({}): finish it with vssw study --resume, "
                                     "or give study merge another --out",
                                     o.out, study::kJournalFile));
    io::StagedFolder staged(o.out, io::OutKind::study);
    staged.create();
    const study::MergeResult merged = study::merge_studies(dirs, o.out, staged.path());
    study::OutputOptions options;
    options.plots = !o.no_plots;
    options.gnuplot = o.gnuplot;
    const study::OutputFiles files = as_committed(study::write_study_outputs(staged.path(), options), staged);
    staged.commit();
    for (const std::string& w : files.warnings) print_message_line(err, "warning", w);
    if (o.json) {
        io::Json files_json = io::Json::array();
        for (const auto& f : files.written) files_json.push_back(f.string());
        out << io::dump_json(io::Json{{"out", o.out}, {"shards", merged.shards}, {"rows", merged.rows},
                                     {"failed_rows", merged.failed_rows}, {"files", files_json}},
                                2)
            << '\n';
        return;
    }
    out << fmt::format("vssw study merge: {} shards, {} rows ({} failed) into {}\n", merged.shards, merged.rows,
                       merged.failed_rows, o.out);
    print_outputs(out, o.out, files);
}

void run_study_command(const StudyOptions& o, std::ostream& out, std::ostream& err) {
    // Under mpirun every process reads the file and builds the grid; they agree that all could before any runs.
    const std::unique_ptr<study::MpiSession> mpi = study::start_mpi_if_launched();
    const bool leader = !mpi || mpi->rank() == 0;

    std::optional<study::Grid> grid;
    study::StudyRunOptions run;
    io::FolderLock lock;  // rank 0's, held until the study's folder is replaced
    const auto prepare = [&] {
        if (o.file.empty()) throw InputError("a study file is required (vssw study FILE --out DIR)");
        if (o.out.empty()) throw InputError("--out DIR is required");
        run.threads = parse_threads(o.threads_text);
        run.shard = parse_shard(o.shard_text);
        run.resume = o.resume;
        run.commit = build_commit();
        study::StudySpec spec = study::read_study_file(o.file);
        const double tasks = tasks_at_most(spec) / run.shard.n;
        if (tasks > kMaxTasksWithoutForce && !o.force)
            throw InputError(fmt::format("study file {}: {:.0f} tasks (cases x runs{}), more than {}: add --force to "
                                         "run them all",
                                         o.file, tasks, run.shard.n > 1 ? " in this shard" : "",
                                         kMaxTasksWithoutForce));
        grid.emplace(spec);
        // A shard may be empty (more shards than cases): it writes empty results, which merge as such.
        if (grid->case_ids().empty()) throw InputError(fmt::format("study file {}: the grid has no case to run", o.file));
        // An engine step too coarse for a case's wall or ground motion: refused here, before any folder is made.
        study::require_runs_resolve(*grid, grid->shard_case_ids(run.shard.k, run.shard.n));
        if (leader) {
            io::check_inputs_not_outputs(o.out, io::OutKind::study, study_inputs(o.file, *grid));
            lock = study::prepare_study_dir(*grid, o.out, run);
        }
    };
    try {
        study::prepare_on_every_process(mpi.get(), prepare, err);
    } catch (const study::RefusedOnEveryProcess&) {
        throw QuietExit(kExitBadInput);  // the reason is printed already (study/mpi.hpp)
    }
    for (const std::string& s : grid->skipped_runs())
        if (leader) err << "vssw: note: " << s << '\n';

    Progress progress(err);
    if (leader && progress.on())
        run.progress = [&progress](long done, long total, const std::string& what) { progress.show(done, total, what); };
    run.mpi = mpi.get();
    // The results are written into a staging folder that replaces --out whole once everything is written; until
    // then --out keeps the journal (a run killed before the swap is resumed from it) and any older results as they
    // were (io/folder_swap.hpp).
    std::optional<io::StagedFolder> staged;
    if (leader) {
        staged.emplace(o.out, io::OutKind::study);
        run.results_dir = staged->path();
    }
    study::StudyRunResult result;
    try {
        result = study::run_study(*grid, o.out, run);
    } catch (...) {
        progress.clear();
        throw;
    }
    progress.clear();
    if (!leader) return;

    study::OutputOptions options;
    options.plots = !o.no_plots;
    options.gnuplot = o.gnuplot;
    // From the rows this run has just written, when it wrote them; read back from the folder otherwise.
    const study::OutputFiles files = as_committed(
        study::write_study_outputs(staged->path(), options, study::take_study_data(result, staged->path())), *staged);
    staged->commit();
    for (const std::string& w : files.warnings) print_message_line(err, "warning", w);

    const study::StudySpec& spec = grid->spec();
    const std::size_t cases = grid->shard_case_ids(run.shard.k, run.shard.n).size();
    if (o.json) {
        io::Json files_json = io::Json::array();
        files_json.push_back(o.out + "/results.csv");
        for (const auto& f : files.written) files_json.push_back(f.string());
        const io::Json summary{{"study", spec.name},
                           {"file", o.file},
                           {"out", o.out},
                           {"identity", grid->identity()},
                           {"shard", {{"k", run.shard.k}, {"n", run.shard.n}}},
                           {"cases", cases},
                           {"runs", grid->runs().size()},
                           {"tasks_run", result.meta.tasks_run},
                           {"tasks_resumed", result.meta.tasks_resumed},
                           {"rows", result.rows},
                           {"failed_rows", result.failed_rows},
                           {"wall_time_s", result.meta.wall_time_s},
                           {"threads", result.meta.threads},
                           {"processes", result.meta.processes},
                           {"files", files_json}};
        out << io::dump_json(summary, 2) << '\n';
    } else {
        out << fmt::format("vssw study {}: {} case{} x {} run{}{}, {} task{} run{} in {:.1f} s ({} thread{}{})\n",
                           spec.name, cases, cases == 1 ? "" : "s", grid->runs().size(),
                           grid->runs().size() == 1 ? "" : "s",
                           run.shard.n > 1 ? fmt::format(" (shard {}/{})", run.shard.k, run.shard.n) : "",
                           result.meta.tasks_run, result.meta.tasks_run == 1 ? "" : "s",
                           result.meta.tasks_resumed > 0 ? fmt::format(" ({} resumed)", result.meta.tasks_resumed) : "",
                           result.meta.wall_time_s, result.meta.threads, result.meta.threads == 1 ? "" : "s",
                           result.meta.processes > 1 ? fmt::format(" x {} processes", result.meta.processes) : "");
        out << fmt::format("  {} rows, {} failed (status column)\n", result.rows, result.failed_rows);
        print_outputs(out, o.out, files);
    }
    if (o.strict && result.failed_rows > 0)
        throw SimulationFailure(fmt::format("--strict: {} row{} failed (see the status column of {}/results.csv)",
                                            result.failed_rows, result.failed_rows == 1 ? "" : "s", o.out));
}

std::string metrics_help() {
    std::string text;
    for (const compare::MetricInfo& m : study::metric_catalog())
        text += fmt::format("  {:<28} {}{}\n", m.name, m.analytic_only ? "(analytic) " : "", m.description);
    return text;
}

}  // namespace

Command add_study_command(CLI::App& root) {
    auto o = std::make_shared<StudyOptions>();
    CLI::App* cmd = root.add_subcommand(
        "study", "Run a study file: walls x assumptions x excitations x engines, on every core, in shards or with MPI");
    cmd->add_option("FILE", o->file, "the study file (.toml or .json; see docs/guide/studies.md)");
    cmd->add_option("--out", o->out, "folder to write into (created if missing) (required)");
    cmd->add_option("--threads", o->threads_text,
                    fmt::format("worker threads, 0 to {} (default 0: the available cores; one per process under "
                                "mpirun)",
                                kMaxThreads));
    cmd->add_option("--shard", o->shard_text,
                    "run only shard K of N (every N-th case from the K-th): K/N, default 1/1; join the shards' folders "
                    "with 'vssw study merge'");
    cmd->add_flag("--resume", o->resume, "finish an interrupted study in --out (its finished tasks are not run again)");
    cmd->add_flag("--force", o->force,
                  fmt::format("run a study of more than {} tasks (cases x runs)", kMaxTasksWithoutForce));
    cmd->add_flag("--strict", o->strict, "exit 3 when any row failed (for CI)");
    cmd->add_flag("--no-plots", o->no_plots, "write no plots (no gnuplot run)");
    cmd->add_option("--gnuplot", o->gnuplot, "the gnuplot program (default: gnuplot from PATH)");
    cmd->add_flag("--json", o->json, "print a JSON summary instead of a table");
    add_run_budget_option(*cmd);
    cmd->footer(
        "Writes into --out: results.csv (case_id, engine, the parameters as columns named as in the file, metric,\n"
        "value, unit, status 'ok' or 'failed: reason', warnings), results.json (the same rows, the study as read, the\n"
        "commit, the engines' versions, the wall time), manifest.json, plots/ and study.md / study.html.\n"
        "Case ids are positions in the grid: rows and their order do not depend on threads, shards or processes.\n"
        "A failing run is a row with its reason and the study goes on (exit 0; --strict: exit 3). Exit 2 on bad\n"
        "input, before anything runs: an unknown key, a wrong type, an empty list, a record that does not read, an\n"
        "engine not built, a metric the excitation cannot measure, too many tasks without --force.\n"
        "Under 'mpirun -n P' the processes share the tasks (one at a time each) and rank 0 writes one result.\n"
        "The analytic model's assumptions: [assumptions] set = \"paper\" | \"mechanism\" (default mechanism, as in\n"
        "every command: what the engines are compared against), one set a study; kinematics, impact and roller\n"
        "override one part each (a value, or a list that varies):\n  " +
        describe(AssumptionSet::paper) + "\n  " + describe(AssumptionSet::mechanism) + "\n"
        "Metrics:\n" +
        metrics_help());

    CLI::App* merge = cmd->add_subcommand("merge", "Join the folders of a study's shards into one study folder");
    merge->add_option("DIRS", o->merge_dirs, "the shards' folders (every shard 1..N of one study)")->required();
    merge->add_option("--out", o->out, "folder to write into (created if missing) (required)")->required();
    merge->add_flag("--no-plots", o->no_plots, "write no plots (no gnuplot run)");
    merge->add_option("--gnuplot", o->gnuplot, "the gnuplot program (default: gnuplot from PATH)");
    merge->add_flag("--json", o->json, "print a JSON summary instead of a table");
    merge->footer("Writes the same files as one run of the whole study: the same rows in the same order.");

    return {cmd, {}, [o, merge](std::ostream& out, std::ostream& err) {
                if (merge->parsed()) run_merge(*o, out, err);
                else run_study_command(*o, out, err);
            }};
}

}  // namespace vssw::cli

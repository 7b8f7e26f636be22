#include "study/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "compare/case_runner.hpp"
#include "compare/task_pool.hpp"
#include "io/json.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/run_budget.hpp"
#include "io/atomic_file.hpp"
#include "io/clock.hpp"
#include "io/folder_swap.hpp"
#include "study/ida_curves.hpp"
#include "study/measure.hpp"
#include "study/mpi.hpp"

namespace vssw::study {
namespace fs = std::filesystem;
namespace {

// The identity and shard an existing manifest records ("" when there is none or it does not read).
std::string recorded_study(const fs::path& manifest) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(manifest, ec))) return "";
    std::ifstream in = open_input_file(manifest, "the study's manifest", kMaxTextFileBytes);  // a FIFO: refused
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        return fmt::format("{} {}/{}", j.at("study").at("identity").get<std::string>(), j.at("shard").at("k").get<int>(),
                           j.at("shard").at("n").get<int>());
    } catch (const std::exception&) {
        return "";
    }
}

// A case's run, or the threshold of a wall for a run. A threshold task carries the first case of its wall in the
// shard, and is journaled under that case id negated (its rows are copied to every case of the wall at the end).
// Its engine and cost are the matching compare::CaseTask's (the same index in StudyTasks).
struct Task {
    int case_id;  // < 0: the threshold task of the wall of case -case_id
    std::size_t run;
};

struct StudyTasks {
    std::vector<Task> tasks;
    std::vector<compare::CaseTask> plan;  // per task: case_index is the task's own index, engine and cost
};

// The wall a case belongs to, for a run: one threshold per key.
using WallRun = std::tuple<std::size_t, std::size_t, std::size_t>;  // part, wall index, run

// The threshold tasks' rows (case ids negated) given to every case of their wall in the shard, in their place.
std::vector<ResultRow> with_thresholds(const Grid& grid, Shard shard, std::vector<ResultRow> rows) {
    std::map<WallRun, ResultRow> thresholds;
    std::vector<ResultRow> out;
    out.reserve(rows.size());
    for (ResultRow& row : rows) {
        if (row.case_id >= 0) {
            out.push_back(std::move(row));
            continue;
        }
        const CaseSpec c = grid.make_case(-row.case_id);
        thresholds.emplace(WallRun{c.part, c.wall_index, row.run}, std::move(row));
    }
    if (thresholds.empty()) return out;
    for (const int id : grid.shard_case_ids(shard.k, shard.n)) {
        const CaseSpec c = grid.make_case(id);
        for (std::size_t r = 0; r < grid.runs().size(); ++r) {
            const auto it = thresholds.find(WallRun{c.part, c.wall_index, r});
            if (it == thresholds.end() || !grid.run_applies(grid.runs()[r], c)) continue;
            ResultRow row = it->second;
            row.case_id = id;
            out.push_back(std::move(row));
        }
    }
    return out;
}

}  // namespace

io::FolderLock prepare_study_dir(const Grid& grid, const fs::path& dir, const StudyRunOptions& options) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(fmt::format("--out '{}' is not a folder", dir.string()));
    // Locked before the journal is looked at: a run still going there is named, not read half-written.
    io::FolderLock lock = io::check_out_folder(dir, io::OutKind::study);
    // A refused study leaves no folder behind: one made here is removed again (empty) when it is refused below.
    const bool existed = fs::exists(dir, ec);
    if (options.resume && !existed)
        throw InputError(fmt::format("--resume: '{}' does not exist: there is no study there to resume", dir.string()));
    fs::create_directories(dir, ec);
    if (ec) throw InputError(fmt::format("cannot create the output folder '{}': {}", dir.string(), ec.message()));
    struct RemoveIfRefused {
        const fs::path& dir;
        bool keep = false;
        ~RemoveIfRefused() {
            std::error_code ignored;
            if (!keep) fs::remove_all(dir, ignored);
        }
    } made{dir, existed};
    const bool journal = fs::exists(dir / kJournalFile, ec);
    const std::string this_study =
        fmt::format("{} {}/{}", grid.identity(), options.shard.k, options.shard.n);
    if (options.resume) {
        if (journal) check_journal(dir / kJournalFile, grid.identity(), options.shard);
        if (!journal && recorded_study(dir / kManifestFile) != this_study)
            throw InputError(fmt::format("--resume: '{}' holds no journal of this study to resume (and no finished "
                                         "results of it)",
                                         dir.string()));
    } else if (journal) {
        throw InputError(fmt::format("'{}' holds an unfinished study ({}): add --resume to finish it, or give another "
                                     "--out",
                                     dir.string(), kJournalFile));
    }
    io::AtomicFile probe(dir / ".vssw-write-test");  // InputError naming the folder when nothing can be written there
    made.keep = true;
    return lock;
}

namespace {

// One engine object per study engine, shared by every task (simulate() is const; ODE's runs are kept apart by the
// pool or by worker processes, run_tasks).
struct StudyEngines {
    std::vector<std::unique_ptr<multibody::Engine>> owned;
    std::vector<const multibody::Engine*> list;

    std::size_t index(const std::string& name) const {
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list[i]->name() == name) return i;
        throw InputError(fmt::format("study: no engine '{}'", name));
    }
};

StudyEngines open_engines(const Grid& grid, StudyMeta& meta) {
    StudyEngines engines;
    for (const EngineSpec& e : grid.spec().engines) {
        engines.owned.push_back(multibody::make_engine(e.name));
        engines.list.push_back(engines.owned.back().get());
        meta.engines.push_back({e.name, engines.owned.back()->version()});
    }
    return engines;
}

struct JournalState {
    std::set<TaskKey> done;            // tasks a resumed journal holds already
    std::unique_ptr<Journal> journal;  // rank 0 only; none when the results are complete already
    bool finished_already = false;     // --resume of a study whose results are complete: its files stand
};

// The journal: a new one, or the one to resume (its finished tasks are skipped). Under MPI only rank 0 reads and
// writes it, and tells the others which tasks are done, so that every process holds the same list of tasks (rank 0
// hands them out by their place in it). A failure here on rank 0 ends every process rather than leave the others
// waiting.
JournalState open_journal(const Grid& grid, const fs::path& dir, const StudyRunOptions& options, bool writer) {
    JournalState state;
    const fs::path journal_path = dir / kJournalFile;
    try {
        if (writer) {
            std::error_code ec;
            if (options.resume && fs::exists(journal_path, ec))
                state.journal = std::make_unique<Journal>(journal_path, grid.identity(), options.shard, state.done);
            else if (!options.resume || !fs::exists(dir / kResultsCsv, ec))
                state.journal = std::make_unique<Journal>(journal_path, grid.identity(), options.shard);
            else
                state.finished_already = true;
        }
        if (options.mpi) options.mpi->share_done(state.done, state.finished_already);
    } catch (const std::exception& e) {
        if (options.mpi) options.mpi->abort(e.what());
        throw;
    }
    return state;
}

// The shard's tasks not done yet, in case order, with their costs (compare/case_runner.hpp's model); those done are
// counted in meta.tasks_resumed.
StudyTasks plan_tasks(const Grid& grid, Shard shard, const StudyEngines& engines, const JournalState& journal,
                      StudyMeta& meta) {
    StudyTasks out;
    const auto add = [&](int case_id, std::size_t r, double seconds) {
        const RunSpec& run = grid.runs()[r];
        const std::size_t engine = engines.index(run.engine);
        out.plan.push_back({out.tasks.size(), engine, compare::task_cost(*engines.list[engine], seconds,
                                                                         run.settings.dt)});
        out.tasks.push_back({case_id, r});
    };
    std::map<WallRun, int> wall_case;  // the first case of each wall in the shard: its threshold task's id
    for (const int id : grid.shard_case_ids(shard.k, shard.n)) {
        const CaseSpec c = grid.make_case(id);
        for (std::size_t r = 0; r < grid.runs().size(); ++r) {
            if (!grid.run_applies(grid.runs()[r], c)) continue;
            if (measures_threshold(grid, c) && wall_case.emplace(WallRun{c.part, c.wall_index, r}, id).second) {
                if (journal.done.count({-id, r})) ++meta.tasks_resumed;
                else add(-id, r, compare::threshold_seconds(c.scene));
            }
            if (journal.done.count({id, r})) ++meta.tasks_resumed;
            else add(id, r, simulated_seconds(grid, c));
        }
    }
    if (journal.finished_already) {
        meta.tasks_resumed = static_cast<long>(out.tasks.size());
        out = {};
    }
    return out;
}

// Runs every task, each finished one's rows appended to the journal at once: handed out to the MPI processes, or on
// this process's threads. Sets the threads and processes in meta.
void run_tasks(const Grid& grid, const StudyEngines& engines, const StudyTasks& planned, Journal* journal,
               const StudyRunOptions& options, StudyMeta& meta) {
    const auto run_task = [&](std::size_t i) {
        const Task& t = planned.tasks[i];
        const multibody::Engine& engine = *engines.list[planned.plan[i].engine];
        if (t.case_id < 0) {
            const CaseSpec c = grid.make_case(-t.case_id);
            return journal_text(t.case_id, t.run, {measure_threshold(grid, c, t.run, engine)});
        }
        const CaseSpec c = grid.make_case(t.case_id);
        std::vector<IdaPoint> ida;
        const std::vector<Measurement> rows = measure(grid, c, t.run, engine, &ida);
        return journal_text(t.case_id, t.run, rows, ida);
    };
    if (options.mpi) {
        std::mutex progress_mutex;
        long finished = 0;
        const long total = static_cast<long>(planned.tasks.size());
        std::vector<compare::PoolTask> pool;
        for (const compare::CaseTask& t : planned.plan) pool.push_back({t.cost, t.engine});
        run_tasks_mpi(*options.mpi, pool, run_task, [&](const std::string& text) {
            journal->append_text(text);
            if (!options.progress) return;
            const std::lock_guard<std::mutex> lock(progress_mutex);
            options.progress(++finished, total, "task");
        });
        meta.threads = 1;
        meta.processes = options.mpi->size();
        return;
    }
    // Each engine library's run is a child process of its own (multibody/host/isolated_engine.hpp): a library that
    // crashes or passes its budget fails that run's rows, and every engine's tasks run side by side. An engine whose
    // runs cannot share a process takes turns (run_cases).
    compare::CaseRunOptions run_options;
    run_options.threads = options.threads;
    run_options.progress = options.progress;
    if (options.task_cpu)
        run_options.task_cpu = [&](std::size_t i, double cpu_s) {
            options.task_cpu(grid.runs()[planned.tasks[i].run].engine, cpu_s);
        };
    meta.threads = compare::run_cases(planned.plan, engines.list, run_options, [&](std::size_t i) {
        journal->append_text(run_task(i));
        const Task& t = planned.tasks[i];
        const std::string& engine = grid.runs()[t.run].engine;
        return t.case_id < 0 ? fmt::format("threshold of case {} {}", -t.case_id, engine)
                             : fmt::format("case {} {}", t.case_id, engine);
    });
}

// The journal's rows, checked against the study, the thresholds given to every case of their wall, sorted into
// results.csv in `results_dir` and given to `data` as they are written; counts the rows into `result`.
void write_results(const Grid& grid, const fs::path& journal_path, const fs::path& results_dir,
                   const StudyRunOptions& options, StudyDataBuilder& data, StudyRunResult& result) {
    std::vector<IdaRow> ida;
    std::vector<ResultRow> rows = read_journal(journal_path, &ida);
    for (const ResultRow& row : rows)
        if (row.run >= grid.runs().size() || row.metric >= grid.spec().metrics.size())
            throw InputError(fmt::format("journal {}: a row of run {} and metric {}, which the study does not have",
                                         journal_path.string(), row.run, row.metric));
    rows = with_thresholds(grid, options.shard, std::move(rows));
    std::stable_sort(rows.begin(), rows.end(), [](const ResultRow& a, const ResultRow& b) {
        return std::tie(a.case_id, a.run, a.metric) < std::tie(b.case_id, b.run, b.metric);
    });
    for (const ResultRow& r : rows) result.failed_rows += r.status == "ok" ? 0 : 1;
    result.rows = static_cast<long>(rows.size());
    io::AtomicFile csv(results_dir / kResultsCsv);
    result.meta.results_hash = write_results_csv(csv.stream(), grid, rows, &data);
    csv.commit();
    if (!ida.empty()) {
        io::AtomicFile curves(results_dir / kIdaCsv);
        write_ida_csv(curves.stream(), grid, std::move(ida));
        curves.commit();
    }
    result.meta.result_rows = result.rows;
}

// A resumed study whose results were complete: their rows are counted as they are (a --strict resume judges them
// too), and its files are copied into the new results folder when that is not DIR.
void keep_finished_results(const fs::path& dir, const fs::path& results_dir, StudyRunResult& result) {
    const ResultsTable t = read_results_csv(dir / kResultsCsv);
    const std::size_t status = t.column("status");
    result.rows = static_cast<long>(t.rows.size());
    for (const auto& row : t.rows) result.failed_rows += row[status] == "ok" ? 0 : 1;
    if (results_dir == dir) return;
    for (const char* name : {kResultsCsv, kManifestFile, kIdaCsv}) {
        std::error_code ec;
        if (name == kIdaCsv && !fs::exists(dir / name)) continue;  // a study without searches has none
        fs::copy_file(dir / name, results_dir / name, fs::copy_options::overwrite_existing, ec);
        if (ec)
            throw InputError(
                fmt::format("cannot copy '{}' into the new results: {}", (dir / name).string(), ec.message()));
    }
}

}  // namespace

StudyRunResult run_study(const Grid& grid, const fs::path& dir, const StudyRunOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    require(options.shard.n >= 1 && options.shard.k >= 1 && options.shard.k <= options.shard.n, "shard",
            "k/n with 1 <= k <= n", options.shard.k);
    StudyRunResult result;
    result.writer = options.mpi == nullptr || options.mpi->rank() == 0;

    const StudyEngines engines = open_engines(grid, result.meta);
    JournalState journal = open_journal(grid, dir, options, result.writer);
    const StudyTasks planned = plan_tasks(grid, options.shard, engines, journal, result.meta);
    run_tasks(grid, engines, planned, journal.journal.get(), options, result.meta);
    result.meta.tasks_run = static_cast<long>(planned.tasks.size());
    if (!result.writer) return result;

    // results.csv and manifest.json go into the staging folder that replaces DIR whole (the journal stays in DIR
    // until then: a run killed before the swap is resumed from it), or into DIR itself.
    const fs::path results_dir = options.results_dir.empty() ? dir : options.results_dir;
    std::error_code ec;
    fs::create_directories(results_dir, ec);
    if (ec) throw InputError(fmt::format("cannot create the folder '{}': {}", results_dir.string(), ec.message()));
    const fs::path journal_path = dir / kJournalFile;
    std::optional<StudyDataBuilder> data;  // the study's data, built from the rows as results.csv is written
    if (journal.journal) {
        journal.journal->close();
        data.emplace(results_header(grid), grid.spec().metrics);
        write_results(grid, journal_path, results_dir, options, *data, result);
    }
    if (journal.finished_already) keep_finished_results(dir, results_dir, result);

    result.meta.commit = options.commit;
    result.meta.run_budget_s = multibody::RunBudget::given();
    result.meta.date = io::utc_now();
    result.meta.shard = options.shard;
    result.meta.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (journal.journal) {
        // The manifest last; the journal goes once the results are in place.
        io::Json manifest_data = manifest_json(grid, result.meta);
        io::AtomicFile manifest(results_dir / kManifestFile);
        manifest.stream() << io::dump_json(manifest_data, 2) << '\n';
        manifest.commit();
        result.data = data->finish(std::move(manifest_data));
        if (results_dir == dir) fs::remove(journal_path, ec);
    }
    return result;
}

StudyData take_study_data(StudyRunResult& result, const fs::path& dir) {
    if (!result.data) return read_study_data(dir);
    StudyData d = std::move(*result.data);
    result.data.reset();
    return d;
}

}  // namespace vssw::study

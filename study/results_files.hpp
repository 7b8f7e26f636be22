#pragma once
// The machine-readable files of a study, in its output folder:
//   results.csv    tidy, one row per case x run x metric:
//                  case_id, engine, <the parameter columns of Grid::columns()>, metric, value, unit, status,
//                  warnings (the analytic model's own assumptions failing along the run, "; "-joined)
//                  in case, run, metric order (the file's, never the threads'); value empty when there is none;
//                  status "ok" or "failed: <reason>"
//   manifest.json  the study as read, its identity, the shard, the engines' versions, the commit, the wall time,
//                  results.csv's rows and hash ("results"): what `vssw study merge` and `--resume` check, and what
//                  results.json starts with
//   results.json   the manifest's keys and the rows of results.csv as objects (numbers as numbers, empty as null)
// Each is written to a temporary file and renamed into place (io/atomic_file.hpp).
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/grid.hpp"
#include "study/journal.hpp"
#include "study/study_data.hpp"

namespace vssw::study {

// Bumped when a key or a column is renamed or changes meaning (never for an added one). 2: ida.csv's peak_over_alpha
// became peak_over_alpha1, and the unit "alpha" of peak_rotation, rms_difference and theta0 "alpha1".
constexpr int kStudyFormat = 2;

struct EngineVersion {
    std::string name, version;
};

struct StudyMeta {
    std::string commit;  // vssw's git commit, "" when unknown
    std::string date;    // ISO 8601 UTC, when the study ended
    Shard shard;
    std::vector<EngineVersion> engines;
    double wall_time_s = 0.0;
    int threads = 1;    // worker threads per process
    int processes = 1;  // MPI processes (1 without MPI)
    // --run-budget as given (seconds of CPU per engine run); none: the default, 30 s + 1 ms per step (a row failed
    // for its budget depends on it; multibody/host/run_budget.hpp)
    std::optional<double> run_budget_s;
    long tasks_run = 0, tasks_resumed = 0;  // this run's tasks, and those a --resume found done
    // results.csv as written: its rows and the FNV-1a 64 of its bytes (manifest "results"), so that `study merge`
    // can tell a shard's file cut short, given a row twice or edited. rows < 0: not recorded.
    long result_rows = -1;
    std::string results_hash;
};

// The header line's fields: case_id, engine, the grid's columns, metric, value, unit, status.
std::vector<std::string> results_header(const Grid& grid);
// rows sorted by (case_id, run, metric). Returns the FNV-1a 64 of the bytes written (as file_fnv1a gives it), and
// gives each row's fields to `data` when one is given: the study's data built from what was written, not read back.
std::string write_results_csv(std::ostream& out, const Grid& grid, const std::vector<ResultRow>& rows,
                              StudyDataBuilder* data = nullptr);
nlohmann::ordered_json manifest_json(const Grid& grid, const StudyMeta& meta);

// A results.csv read back (by the merge and by the writers of plots and prose, so that a merged study and a single
// run are written by the same code). InputError naming the file on a malformed one.
struct ResultsTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    // Index of a column; InputError naming it when absent.
    std::size_t column(const std::string& name) const;
};
ResultsTable read_results_csv(const std::filesystem::path& path);

// FNV-1a 64 of a file's bytes, as 16 hex digits (InputError naming the file when it cannot be read).
std::string file_fnv1a(const std::filesystem::path& path);

// results.json from the study's data: its manifest's keys, then its rows as results.csv gives them (streamed row by
// row).
void write_results_json(std::ostream& out, const StudyData& data);


}  // namespace vssw::study

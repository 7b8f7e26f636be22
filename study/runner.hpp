#pragma once
// Running a study: the shard's tasks (case x run) that are not done yet, longest first, on threads in this process
// (compare/task_pool.hpp) or handed out to MPI processes (study/mpi.hpp); every finished task's rows go to the journal
// at once (study/journal.hpp). At the end the rows are sorted into results.csv and the manifest is written (into
// StudyRunOptions::results_dir); the journal is removed, or left to go with the folder the results replace. Rows and
// their order depend on the study file and the shard only.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "io/folder_lock.hpp"
#include "study/grid.hpp"
#include "study/journal.hpp"
#include "study/results_files.hpp"
#include "study/study_data.hpp"

namespace vssw::study {

struct StudyRunOptions {
    int threads = 0;     // 0: the available cores (one per process under MPI)
    Shard shard;
    bool resume = false;  // continue DIR/journal.csv: its finished tasks are not run again
    std::string commit;
    // Under mpirun: the session whose processes share the tasks (nullptr: this process alone, on `threads` threads).
    const class MpiSession* mpi = nullptr;
    // Called after each task (serialised): tasks done (this run), tasks to do (this run), what.
    std::function<void(long done, long total, const std::string& what)> progress;
    // Called after each task run on this process's threads (from its worker thread, not serialised; not under MPI)
    // with the task's engine and CPU time, its own and its engine runs' children's (compare::task_cpu_seconds).
    std::function<void(const std::string& engine, double cpu_s)> task_cpu;
    // Where results.csv and manifest.json are written: empty for DIR itself (the journal then removed at the end);
    // the program gives the staging folder that then replaces DIR whole (io/folder_swap.hpp), and DIR's journal
    // goes with the old folder.
    std::filesystem::path results_dir;
};

struct StudyRunResult {
    StudyMeta meta;
    long rows = 0, failed_rows = 0;
    bool writer = true;  // this process wrote the outputs (false on MPI ranks other than 0)
    // The study's data (study/study_data.hpp) built from the rows this run wrote into results.csv, so that its other
    // files are written without reading that file back; none when this run wrote none (a resumed study whose results
    // were complete, MPI ranks other than 0): read_study_data reads them.
    std::optional<StudyData> data;
};

// Checks DIR before anything runs (InputError): it must be a folder this process can write (it is created if
// missing) and that check_out_folder accepts (io/folder_swap.hpp); no other vssw run may be working in it (the
// lock returned, to be held while the study runs); without --resume it must hold no journal of an unfinished study
// (resume it or choose another folder); with --resume it must hold this study's journal, or results of this study
// already complete.
io::FolderLock prepare_study_dir(const Grid& grid, const std::filesystem::path& dir, const StudyRunOptions& options);

// Runs the study into DIR (results.csv, manifest.json). InputError on bad input (nothing runs); a failing task is rows
// with their reasons.
StudyRunResult run_study(const Grid& grid, const std::filesystem::path& dir, const StudyRunOptions& options);

// The study's data: the rows this run wrote (moved out of `result`), or DIR's results read back when it wrote none
// (InputError naming the file when they cannot be read).
StudyData take_study_data(StudyRunResult& result, const std::filesystem::path& dir);

// The file names in DIR.
constexpr const char* kJournalFile = "journal.csv";
constexpr const char* kResultsCsv = "results.csv";
constexpr const char* kResultsJson = "results.json";
constexpr const char* kManifestFile = "manifest.json";

}  // namespace vssw::study

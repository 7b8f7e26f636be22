#pragma once
// The journal of a study being run (DIR/journal.csv): every finished task's rows, appended and flushed as the task
// ends, whatever order the threads or processes finish in. It is what makes a study resumable (`--resume`: the
// finished tasks are not run again) and what keeps memory flat (rows go to disk, not into a growing vector). When the
// study ends, its rows are sorted into results.csv and the journal is removed (with the old folder, when the results
// are written into a staging folder that replaces the study's folder: io/folder_swap.hpp).
//
// Format: a first line "#vssw-study-journal,<identity>,<k>/<n>" (the study's identity and shard), then per task its
// rows "case_id,run,metric,value,status,warnings" (run and metric are indices into the grid's runs and the study's metrics;
// value with 17 significant digits, empty for NaN), a scale-to-collapse search's runs as lines
// "#ida,case_id,run,scale,peak,overturned" (study/measure.hpp, IdaPoint), and a closing line "#done,case_id,run". A task whose closing line
// is missing (the study was killed while writing it) is dropped on resume and run again.
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "study/measure.hpp"

namespace vssw::study {

struct ResultRow {
    int case_id = 0;
    std::size_t run = 0;
    std::size_t metric = 0;
    double value = 0.0;  // NaN: empty
    std::string status;
    std::string warnings;
};

// A scale-to-collapse search's run as the journal holds it: its task and the point.
struct IdaRow {
    int case_id = 0;
    std::size_t run = 0;
    IdaPoint point;
};

struct Shard {
    int k = 1, n = 1;  // this is shard k of n (1/1: the whole study)
};

using TaskKey = std::pair<int, std::size_t>;  // (case id, run index)

class Journal {
public:
    // A new journal at `path` (an existing one is replaced).
    Journal(std::filesystem::path path, const std::string& identity, Shard shard);
    // Continues the journal at `path`: InputError unless it is this study's and shard's. Fills `done` with the tasks it
    // holds whole and cuts off a task left half-written.
    Journal(std::filesystem::path path, const std::string& identity, Shard shard, std::set<TaskKey>& done);

    // Appends whole tasks' rows already formatted as journal text (journal_text; from this process or another), and
    // flushes (thread-safe).
    void append_text(const std::string& text);
    void close() { out_.close(); }

private:
    std::filesystem::path path_;
    std::ofstream out_;
    std::mutex mutex_;
};

// One task's rows as journal text (what a worker process sends to the one that writes).
std::string journal_text(int case_id, std::size_t run, const std::vector<Measurement>& rows,
                         const std::vector<IdaPoint>& ida = {});
// The whole tasks' rows of a journal, in file order; a task written twice (two runs on one folder) counts once. With
// `ida`, their IDA points too, in file order.
std::vector<ResultRow> read_journal(const std::filesystem::path& path, std::vector<IdaRow>* ida = nullptr);
// InputError unless the journal at `path` is this study's and shard's and reads (what --resume will continue).
void check_journal(const std::filesystem::path& path, const std::string& identity, Shard shard);

}  // namespace vssw::study

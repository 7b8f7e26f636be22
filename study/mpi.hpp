#pragma once
// Studies across processes with MPI (OpenMPI; optional at build time: VSSW_HAVE_MPI). `mpirun -n P vssw study ...`
// starts P copies; each reads the study file and builds the same grid, and rank 0 hands the tasks out one at a time,
// longest first, to whichever process asks, runs tasks itself on a second thread, and writes every row it gets back
// into the journal: one result, the same as a single process's. Each process runs one task at a time (run one process
// per core).
#include <cstddef>
#include <functional>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "compare/task_pool.hpp"

namespace vssw::study {

// Whether this build has MPI, and whether this process was started by mpirun with more than one process (read from
// the launcher's environment, so that a plain `vssw` never initialises MPI).
bool mpi_built();
bool launched_by_mpirun();

// One MPI session: MPI_Init_thread on construction, MPI_Finalize on destruction (both only when built with MPI).
class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    // Whether every process says ok (a collective: every process must call it). Lets all processes stop together
    // when any of them found bad input, instead of waiting on each other for ever.
    bool all_ok(bool ok) const;
    // Rank 0's finished tasks (a resumed journal) and whether the study is finished already, given to every process
    // (a collective), so that all hold the same list of tasks.
    void share_done(std::set<std::pair<int, std::size_t>>& done, bool& finished) const;
    // Ends every process (exit code 3) after printing why: a process that cannot go on must not leave the others
    // waiting for its messages.
    [[noreturn]] void abort(const std::string& why) const;

private:
    int rank_ = 0, size_ = 1;
};

// Rank 0: hands out `tasks` longest first and calls `sink(text)` with each finished task's text (from any process,
// serialised); others: run what rank 0 sends. `run(i)` runs task i and returns its text. Returns on every process when
// all tasks are done. An exception out of a task (not a failed run, which is a row: a defect or no memory) ends every
// process with exit code 3 (MPI_Abort, after printing the reason): a study that cannot go on must not hang.
void run_tasks_mpi(const MpiSession& session, const std::vector<compare::PoolTask>& tasks,
                   const std::function<std::string(std::size_t)>& run,
                   const std::function<void(const std::string&)>& sink);

}  // namespace vssw::study

#pragma once
// Studies across processes with MPI (OpenMPI; optional at build time: VSSW_HAVE_MPI). `mpirun -n P vssw study ...`
// starts P copies; each reads the study file and builds the same grid, and rank 0 hands the tasks out one at a time,
// longest first, to whichever process asks, runs tasks itself on a second thread, and writes every row it gets back
// into the journal: one result, the same as a single process's. Each process runs one task at a time (run one process
// per core).
//
// MPI itself is a module of its own, vssw_mpi.so (study/mpi_module.hpp), opened only by a process that mpirun started:
// every other process of the program runs without libmpi loaded.
#include <cstddef>
#include <functional>
#include <memory>
#include <ostream>
#include <set>
#include <stdexcept>
#include <utility>
#include <string>
#include <vector>

#include "compare/task_pool.hpp"

namespace vssw::study {

struct MpiModule;

// Whether this build has MPI (its module), and whether this process was started by mpirun with more than one process
// (read from the launcher's environment, so that a plain `vssw` never loads MPI).
bool mpi_built();
bool launched_by_mpirun();
// Where the MPI module would be opened from; "" when this build has none or it is not found. Opens nothing (vssw
// --version).
std::string mpi_module_path();

// One MPI session: the module opened and MPI_Init_thread on construction, MPI_Finalize on destruction.
class MpiSession {
public:
    // Throws InputError when this build has no MPI or its module cannot be opened.
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    const MpiModule& module() const { return *mpi_; }  // the MPI calls (study/mpi_module.hpp)
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
    const MpiModule* mpi_ = nullptr;
    int rank_ = 0, size_ = 1;
};

// Under mpirun (launched_by_mpirun()) this process's session; otherwise none. Throws InputError when started by
// mpirun but MPI cannot be used (a build without it, its module missing): each process would run the whole study.
std::unique_ptr<MpiSession> start_mpi_if_launched();

// Thrown on an MPI process other than rank 0 when the study is refused: the reason was printed already (by rank 0, or
// by this process before it threw), and the program ends with the exit code of bad input without printing more.
struct RefusedOnEveryProcess : std::runtime_error {
    RefusedOnEveryProcess() : std::runtime_error("the study was refused (the reason is printed above)") {}
};

// Runs `prepare` (reading the study file, building the grid, preparing the folder) and, under MPI, makes every
// process agree that all could before any of them runs a task: every process must call it (a collective). Without MPI
// (mpi null) an InputError out of `prepare` is the caller's. Under MPI, when any process refused (an InputError out
// of its `prepare`): rank 0 throws InputError with its own reason, or saying that another process refused; every
// other process prints its own reason, if it has one, on `err` ("vssw: error on MPI process N: ...") and throws
// RefusedOnEveryProcess. So all stop together instead of waiting on each other for ever, and the reason is printed
// where it arose.
void prepare_on_every_process(const MpiSession* mpi, const std::function<void()>& prepare, std::ostream& err);

// Rank 0: hands out `tasks` longest first and calls `sink(text)` with each finished task's text (from any process,
// serialised); others: run what rank 0 sends. `run(i)` runs task i and returns its text. Returns on every process when
// all tasks are done. An exception out of a task (not a failed run, which is a row: a defect or no memory) ends every
// process with exit code 3 (MPI_Abort, after printing the reason): a study that cannot go on must not hang.
void run_tasks_mpi(const MpiSession& session, const std::vector<compare::PoolTask>& tasks,
                   const std::function<std::string(std::size_t)>& run,
                   const std::function<void(const std::string&)>& sink);

}  // namespace vssw::study

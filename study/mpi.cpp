#include "study/mpi.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/host/plugin_loader.hpp"
#include "study/mpi_module.hpp"

namespace vssw::study {

bool launched_by_mpirun() {
    // OpenMPI's launcher sets OMPI_COMM_WORLD_SIZE; MPICH's and Slurm's PMI set PMI_SIZE.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* v = std::getenv(name)) return std::atoi(v) > 1;
    return false;
}

// VSSW_HAVE_MPI: the module is built (study/CMakeLists.txt).
#ifdef VSSW_HAVE_MPI
bool mpi_built() { return true; }
#else
bool mpi_built() { return false; }
#endif

std::string mpi_module_path() {
    return mpi_built() ? multibody::find_plugin(multibody::plugin_file(kMpiModuleStem)) : "";
}

namespace {

// Messages: a worker asks for a task (kRequest, empty) and returns each finished task's text (kResult); rank 0
// answers a request with a task index (kTask) or, once none is left, with -1.
constexpr int kRequest = 1, kResult = 2, kTask = 3;
// Requests each worker keeps outstanding: with two, the next task is already on its way while one runs, so a worker
// does not wait on rank 0's polling between tasks.
constexpr int kRequestsInFlight = 2;
// Rank 0's main thread polls for messages and sleeps this long when there are none: it must not spin on a core that
// its own worker thread (and on a small machine, other processes) need.
constexpr std::chrono::microseconds kPollPause{200};

void send_text(const MpiModule& mpi, const std::string& text, int tag) {
    mpi.send_text(text.data(), static_cast<int>(text.size()), 0, tag);
}

void worker(const MpiModule& mpi, const std::function<std::string(std::size_t)>& run) {
    for (int i = 0; i < kRequestsInFlight; ++i) send_text(mpi, "", kRequest);
    int stops = 0;
    while (stops < kRequestsInFlight) {
        const long task = mpi.receive_long(0, kTask);
        if (task < 0) {
            ++stops;
            continue;
        }
        send_text(mpi, run(static_cast<std::size_t>(task)), kResult);
        send_text(mpi, "", kRequest);
    }
}

void leader(const MpiSession& session, const std::vector<compare::PoolTask>& tasks,
            const std::function<std::string(std::size_t)>& run, const std::function<void(const std::string&)>& sink) {
    const MpiModule& mpi = session.module();
    std::deque<std::size_t> queue(tasks.size());
    for (std::size_t i = 0; i < queue.size(); ++i) queue[i] = i;
    std::stable_sort(queue.begin(), queue.end(), [&](std::size_t a, std::size_t b) { return tasks[a].cost > tasks[b].cost; });
    std::mutex mutex;  // the queue and the sink, shared with this process's worker thread
    const auto take = [&]() -> long {
        const std::lock_guard<std::mutex> lock(mutex);
        if (queue.empty()) return -1;
        const std::size_t t = queue.front();
        queue.pop_front();
        return static_cast<long>(t);
    };

    // This process's own worker, on a thread that makes no MPI call (MPI_THREAD_FUNNELED).
    std::exception_ptr local_error;
    std::thread local([&] {
        try {
            for (long t = take(); t >= 0; t = take()) {
                const std::string text = run(static_cast<std::size_t>(t));
                const std::lock_guard<std::mutex> lock(mutex);
                sink(text);
            }
        } catch (...) {
            local_error = std::current_exception();
        }
    });

    // This thread's failure (the journal cannot be written) must not leave `local` joinable: stop handing out, wait
    // for it, then rethrow (run_tasks_mpi ends every process).
    struct JoinOnExit {
        std::thread& t;
        std::mutex& m;
        std::deque<std::size_t>& q;
        ~JoinOnExit() {
            {
                const std::lock_guard<std::mutex> lock(m);
                q.clear();
            }
            if (t.joinable()) t.join();
        }
    } join_on_exit{local, mutex, queue};
    int stops_left = (session.size() - 1) * kRequestsInFlight;
    while (stops_left > 0) {
        int from = 0, tag = 0, size = 0;
        if (!mpi.poll(&from, &tag, &size)) {
            std::this_thread::sleep_for(kPollPause);
            continue;
        }
        std::string text(static_cast<std::size_t>(size), '\0');
        mpi.receive_text(text.data(), size, from, tag);
        if (tag == kResult) {
            const std::lock_guard<std::mutex> lock(mutex);
            sink(text);
            continue;
        }
        const long t = take();
        mpi.send_long(t, from, kTask);
        if (t < 0) --stops_left;
    }
    local.join();
    if (local_error) std::rethrow_exception(local_error);
}

// The module, opened once per process and checked to be of this build.
const MpiModule& open_module() {
    const std::string what = "MPI";
    const multibody::OpenedPlugin plugin =
        multibody::open_plugin(multibody::plugin_file(kMpiModuleStem), kMpiModuleEntry, what);
    const MpiModule& module = multibody::plugin_description<MpiModule>(plugin, what, kMpiModuleEntry);
    multibody::check_plugin_build(plugin, what, module.abi, kMpiModuleAbi, module.build_id);
    return module;
}

}  // namespace

MpiSession::MpiSession() {
    if (!mpi_built())
        throw InputError("started by mpirun, but this vssw was built without MPI (install libopenmpi-dev and build "
                         "again): each process would run the whole study");
    mpi_ = &open_module();
    mpi_->start(&rank_, &size_);
}

MpiSession::~MpiSession() { mpi_->finish(); }

bool MpiSession::all_ok(bool ok) const { return mpi_->all_min(ok ? 1 : 0) == 1; }

void MpiSession::share_done(std::set<std::pair<int, std::size_t>>& done, bool& finished) const {
    // As a flat list: finished, then case id and run per task.
    std::vector<long> flat;
    if (rank_ == 0) {
        flat.push_back(finished ? 1 : 0);
        for (const auto& [id, run] : done) {
            flat.push_back(id);
            flat.push_back(static_cast<long>(run));
        }
    }
    long n = static_cast<long>(flat.size());
    mpi_->broadcast_longs(&n, 1);
    flat.resize(static_cast<std::size_t>(n));
    mpi_->broadcast_longs(flat.data(), static_cast<int>(n));
    if (rank_ == 0) return;
    finished = flat.at(0) == 1;
    for (std::size_t i = 1; i + 1 < flat.size(); i += 2)
        done.insert({static_cast<int>(flat[i]), static_cast<std::size_t>(flat[i + 1])});
}

void MpiSession::abort(const std::string& why) const {
    std::fprintf(stderr, "vssw: error on MPI process %d: %s\n", rank_, why.c_str());
    mpi_->abort_all(3);
    std::abort();  // MPI_Abort does not return
}

std::unique_ptr<MpiSession> start_mpi_if_launched() {
    if (!launched_by_mpirun()) return nullptr;
    return std::make_unique<MpiSession>();
}

void prepare_on_every_process(const MpiSession* mpi, const std::function<void()>& prepare, std::ostream& err) {
    if (!mpi) {
        prepare();
        return;
    }
    std::string refusal;
    try {
        prepare();
    } catch (const InputError& e) {
        refusal = e.what();
    }
    if (mpi->all_ok(refusal.empty())) return;
    const bool leader = mpi->rank() == 0;
    if (leader) throw InputError(refusal.empty() ? "another MPI process refused the study (its message is above)"
                                                 : refusal);
    if (!refusal.empty()) err << fmt::format("vssw: error on MPI process {}: {}\n", mpi->rank(), refusal);
    throw RefusedOnEveryProcess();
}

void run_tasks_mpi(const MpiSession& session, const std::vector<compare::PoolTask>& tasks,
                   const std::function<std::string(std::size_t)>& run,
                   const std::function<void(const std::string&)>& sink) {
    try {
        if (session.rank() == 0) leader(session, tasks, run, sink);
        else worker(session.module(), run);
    } catch (const std::exception& e) {
        session.abort(e.what());  // the others would wait for this process's messages for ever
    } catch (...) {
        session.abort("an unknown failure");
    }
}

}  // namespace vssw::study

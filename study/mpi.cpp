#include "study/mpi.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>

#ifdef VSSW_HAVE_MPI
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <mutex>
#include <thread>
#endif

namespace vssw::study {

bool launched_by_mpirun() {
    // OpenMPI's launcher sets OMPI_COMM_WORLD_SIZE; MPICH's and Slurm's PMI set PMI_SIZE.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* v = std::getenv(name)) return std::atoi(v) > 1;
    return false;
}

#ifndef VSSW_HAVE_MPI

bool mpi_built() { return false; }
MpiSession::MpiSession() = default;
MpiSession::~MpiSession() = default;
bool MpiSession::all_ok(bool ok) const { return ok; }
void MpiSession::share_done(std::set<std::pair<int, std::size_t>>&, bool&) const {}
void MpiSession::abort(const std::string& why) const { throw std::logic_error("MpiSession::abort without MPI: " + why); }
void run_tasks_mpi(const MpiSession&, const std::vector<compare::PoolTask>&, const std::function<std::string(std::size_t)>&,
                   const std::function<void(const std::string&)>&) {
    throw std::logic_error("run_tasks_mpi: this build has no MPI");
}

#else

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

void send_text(const std::string& text, int tag) {
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag, MPI_COMM_WORLD);
}

std::string receive_text(const MPI_Status& probed) {
    int count = 0;
    MPI_Get_count(&probed, MPI_CHAR, &count);
    std::string text(static_cast<std::size_t>(count), '\0');
    MPI_Recv(text.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return text;
}

void worker(const std::function<std::string(std::size_t)>& run) {
    for (int i = 0; i < kRequestsInFlight; ++i) send_text("", kRequest);
    int stops = 0;
    while (stops < kRequestsInFlight) {
        long task = -1;
        MPI_Recv(&task, 1, MPI_LONG, 0, kTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (task < 0) {
            ++stops;
            continue;
        }
        send_text(run(static_cast<std::size_t>(task)), kResult);
        send_text("", kRequest);
    }
}

void leader(const MpiSession& session, const std::vector<compare::PoolTask>& tasks,
            const std::function<std::string(std::size_t)>& run, const std::function<void(const std::string&)>& sink) {
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
        int flag = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
        if (!flag) {
            std::this_thread::sleep_for(kPollPause);
            continue;
        }
        const std::string text = receive_text(status);
        if (status.MPI_TAG == kResult) {
            const std::lock_guard<std::mutex> lock(mutex);
            sink(text);
            continue;
        }
        const long t = take();
        MPI_Send(&t, 1, MPI_LONG, status.MPI_SOURCE, kTask, MPI_COMM_WORLD);
        if (t < 0) --stops_left;
    }
    local.join();
    if (local_error) std::rethrow_exception(local_error);
}

}  // namespace

bool mpi_built() { return true; }

MpiSession::MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

bool MpiSession::all_ok(bool ok) const {
    int mine = ok ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return all == 1;
}

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
    MPI_Bcast(&n, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    flat.resize(static_cast<std::size_t>(n));
    MPI_Bcast(flat.data(), static_cast<int>(n), MPI_LONG, 0, MPI_COMM_WORLD);
    if (rank_ == 0) return;
    finished = flat.at(0) == 1;
    for (std::size_t i = 1; i + 1 < flat.size(); i += 2)
        done.insert({static_cast<int>(flat[i]), static_cast<std::size_t>(flat[i + 1])});
}

void MpiSession::abort(const std::string& why) const {
    std::fprintf(stderr, "vssw: error on MPI process %d: %s\n", rank_, why.c_str());
    MPI_Abort(MPI_COMM_WORLD, 3);
    std::abort();  // MPI_Abort does not return
}

void run_tasks_mpi(const MpiSession& session, const std::vector<compare::PoolTask>& tasks,
                   const std::function<std::string(std::size_t)>& run,
                   const std::function<void(const std::string&)>& sink) {
    try {
        if (session.rank() == 0) leader(session, tasks, run, sink);
        else worker(run);
    } catch (const std::exception& e) {
        session.abort(e.what());  // the others would wait for this process's messages for ever
    } catch (...) {
        session.abort("an unknown failure");
    }
}

#endif

}  // namespace vssw::study

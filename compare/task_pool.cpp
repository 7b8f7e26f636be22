#include "compare/task_pool.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "analytic/error.hpp"

namespace vssw::compare {

int pool_threads(int threads, std::size_t tasks) {
    require(threads >= 0, "threads", ">= 0 (0: the available cores)", threads);
    unsigned int want = threads > 0 ? static_cast<unsigned int>(threads) : std::max(1u, std::thread::hardware_concurrency());
    want = std::max(1u, std::min(want, static_cast<unsigned int>(std::max<std::size_t>(1, tasks))));
    return static_cast<int>(want);
}

int run_pool(const std::vector<PoolTask>& tasks, const std::vector<bool>& exclusive, int threads,
             const std::function<void(std::size_t task)>& run) {
    for (const PoolTask& t : tasks)
        if (t.group >= exclusive.size()) throw InputError("run_pool: a task's group has no exclusive flag");

    std::vector<std::size_t> pending(tasks.size());
    for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = i;
    std::stable_sort(pending.begin(), pending.end(),
                     [&](std::size_t a, std::size_t b) { return tasks[a].cost > tasks[b].cost; });
    std::vector<char> busy(exclusive.size(), 0);

    std::mutex mutex;
    std::condition_variable changed;
    bool stop = false;
    std::exception_ptr error;

    auto fail = [&](std::exception_ptr e) {
        {
            const std::lock_guard<std::mutex> lock(mutex);
            if (!error) error = e;
            stop = true;
            pending.clear();
        }
        changed.notify_all();
    };
    auto worker = [&]() {
        for (;;) {
            std::size_t ti = 0;
            {
                std::unique_lock<std::mutex> lock(mutex);
                for (;;) {
                    if (stop || pending.empty()) return;
                    const auto it = std::find_if(pending.begin(), pending.end(), [&](std::size_t t) {
                        const std::size_t g = tasks[t].group;
                        return !(exclusive[g] && busy[g]);
                    });
                    if (it != pending.end()) {
                        ti = *it;
                        pending.erase(it);
                        busy[tasks[ti].group] = 1;
                        break;
                    }
                    changed.wait(lock);
                }
            }
            bool ok = true;
            try {
                run(ti);
            } catch (...) {
                ok = false;
                fail(std::current_exception());
            }
            {
                const std::lock_guard<std::mutex> lock(mutex);
                busy[tasks[ti].group] = 0;
            }
            changed.notify_all();
            if (!ok) return;
        }
    };

    const auto want = static_cast<unsigned int>(pool_threads(threads, tasks.size()));
    if (want == 1) {
        worker();
    } else {
        std::vector<std::thread> pool;
        pool.reserve(want);
        try {
            for (unsigned int i = 0; i < want; ++i) pool.emplace_back(worker);
        } catch (...) {
            fail(std::current_exception());
        }
        for (std::thread& t : pool) t.join();
    }
    if (error) std::rethrow_exception(error);
    return static_cast<int>(want);
}

}  // namespace vssw::compare

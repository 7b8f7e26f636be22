#pragma once
// Runs independent tasks on a pool of threads, longest first, with one rule for engines whose library is not
// re-entrant: tasks of an exclusive group (an engine whose runs_concurrently() is false, e.g. ODE) never run at the same
// time as each other, while other groups' tasks run beside them. The validation suite and studies run their
// simulations through it by way of compare/case_runner.hpp (its cost model gives the tasks' costs).
#include <cstddef>
#include <functional>
#include <vector>

namespace vssw::compare {

struct PoolTask {
    double cost = 0.0;      // estimated [s]: only the order depends on it (longest first; ties keep their order)
    std::size_t group = 0;  // the engine, for the exclusive rule
};

// The number of threads run_pool uses for `tasks` tasks: min(threads, tasks), at least 1 (threads 0: the available
// cores). A caller that runs a non-re-entrant engine in worker processes (study/runner.cpp) asks this first: with
// one thread nothing forks.
int pool_threads(int threads, std::size_t tasks);

// Calls run(i) once for every task i (in no promised order) on min(threads, tasks) threads (threads 0: the available
// cores). A group g with exclusive[g] true has at most one task running at a time: a free worker takes the longest
// task it may run and waits only when every remaining task belongs to a busy exclusive group. The first exception
// thrown by run stops the pool (tasks not yet started are not started) and is rethrown here once every running task
// has returned. Returns the number of threads used.
int run_pool(const std::vector<PoolTask>& tasks, const std::vector<bool>& exclusive, int threads,
             const std::function<void(std::size_t task)>& run);

}  // namespace vssw::compare

#pragma once
// The one way the project runs "each case on each backend, measured": the validation suite (validation/suite.hpp,
// behind `vssw report`, `vssw check` and `vssw bench`'s suite) and studies (study/runner.hpp, behind `vssw study`)
// both plan their (case, backend) tasks with the cost model below and run them here. What a task measures stays
// with its caller (the suite's rows against the analytic model, a study's rows per run); what is shared is how
// tasks are estimated, ordered, kept apart per engine, counted and reported.
//
// The cost model: a task costs the seconds it simulates, times its engine's measured cost per simulated second
// (multibody::Engine::cost_per_simulated_second, at the engine's default step), times default step / the step it
// runs at. Only the order of the tasks depends on it (longest first, compare/task_pool.hpp): results are placed by
// task, never by when a task finished.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "analytic/ground_motion.hpp"
#include "multibody/engine.hpp"

namespace vssw::compare {


// Simulated seconds of a run from rest under `motion` that goes on `response_tail` seconds after it [s]
// (compare/experiments.hpp: kResponseTail, kSuiteResponseTail).
double response_seconds(const GroundMotion& motion, double response_tail);
// Simulated seconds of find_threshold on the wall [s]: ~10 trials, those below the threshold run the ramp and the
// whole hold, those above stop once the wall lifts (about half of it on average).
double threshold_seconds(const multibody::WallScene& scene);
// The cost model above [s]: `simulated_seconds` on `engine` at step `dt` (dt <= 0, or an engine whose dt is only a
// reporting interval: its default step's cost).
double task_cost(const multibody::Engine& engine, double simulated_seconds, double dt);

// One (case, backend) task: which of the caller's cases, which of the engines given to run_cases, and its cost.
struct CaseTask {
    std::size_t case_index = 0;
    std::size_t engine = 0;
    double cost = 0.0;  // task_cost
};

struct CaseRunOptions {
    int threads = 0;  // 0: the available cores
    // Called after each task (serialised, from the worker threads): tasks done, tasks in all, what the task said.
    std::function<void(long done, long total, const std::string& what)> progress;
    // Called after each task (from its worker thread, not serialised) with the task's CPU time, task_cpu_seconds
    // around it: where a run's time went, by the caller's parts and engines (bench/suite_profile.cpp).
    std::function<void(std::size_t task, double cpu_s)> task_cpu;
};

// CPU time of the calling thread and of the children it has reaped [s] (POSIX): a task runs on one thread from start
// to end, and its engine runs in children that thread forks and waits for (analytic/child_fork.hpp).
double task_cpu_seconds();

// Runs run(i) once for every task i on the task pool, longest first; an engine whose runs_concurrently() is false
// has one task running at a time (other engines' tasks run beside it). run returns the task's progress text. The
// first exception thrown by run stops the pool and is rethrown (a caller turns an engine's failure into rows
// before that). Returns the number of threads used.
int run_cases(const std::vector<CaseTask>& tasks, const std::vector<const multibody::Engine*>& engines,
              const CaseRunOptions& options, const std::function<std::string(std::size_t task)>& run);

}  // namespace vssw::compare

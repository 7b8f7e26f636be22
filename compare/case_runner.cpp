#include "compare/case_runner.hpp"

#include <time.h>

#include <mutex>

#include "analytic/child_fork.hpp"
#include "analytic/error.hpp"
#include "compare/experiments.hpp"
#include "compare/task_pool.hpp"

namespace vssw::compare {
namespace {

// find_threshold's trials, bracketed around the closed form (compare/experiments.cpp).
constexpr double kThresholdTrials = 10.0;
// Simulated seconds of a trial when the wall's hold cannot be estimated: a few seconds' hold, about half of it run.
constexpr double kTypicalTrialSeconds = 2.5;

}  // namespace

double task_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec) + reaped_children_cpu_seconds();
}

double response_seconds(const GroundMotion& motion, double response_tail) { return motion.duration() + response_tail; }

double threshold_seconds(const multibody::WallScene& scene) {
    const ThresholdOptions o;
    try {
        return kThresholdTrials * (o.ramp_time + 0.5 * threshold_hold_time(scene, o));
    } catch (const InputError&) {
        // A wall the analytic model cannot hold: the task's own run reports it; the estimate only orders tasks.
        return kThresholdTrials * kTypicalTrialSeconds;
    }
}

double task_cost(const multibody::Engine& engine, double simulated_seconds, double dt) {
    double cost = simulated_seconds * engine.cost_per_simulated_second();
    if (dt > 0.0 && !engine.dt_is_a_reporting_interval()) cost *= engine.default_settings().dt / dt;
    return cost;
}

int run_cases(const std::vector<CaseTask>& tasks, const std::vector<const multibody::Engine*>& engines,
              const CaseRunOptions& options, const std::function<std::string(std::size_t task)>& run) {
    std::vector<PoolTask> pool;
    pool.reserve(tasks.size());
    for (const CaseTask& t : tasks) {
        if (t.engine >= engines.size()) throw InputError("run_cases: a task names no engine given");
        pool.push_back({t.cost, t.engine});
    }
    std::vector<bool> exclusive;
    for (const multibody::Engine* e : engines) exclusive.push_back(!e->runs_concurrently());

    std::mutex progress_mutex;
    long done = 0;
    const long total = static_cast<long>(tasks.size());
    return run_pool(pool, exclusive, options.threads, [&](std::size_t i) {
        const double cpu_start = options.task_cpu ? task_cpu_seconds() : 0.0;
        const std::string what = run(i);
        if (options.task_cpu) options.task_cpu(i, task_cpu_seconds() - cpu_start);
        if (!options.progress) return;
        const std::lock_guard<std::mutex> lock(progress_mutex);
        options.progress(++done, total, what);
    });
}

}  // namespace vssw::compare

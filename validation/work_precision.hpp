#pragma once
// Work-precision (`vssw bench`, docs/measurements/work-precision.md): each backend swept over the settings that trade
// cost for accuracy on a few reference problems, every point's CPU time (median of repeats) against its error on the
// converged reference of the same physics, as the DiffEq and SimBenchmark work-precision diagrams show them. The
// experiments and the metrics are compare/experiments.hpp's and compare/metrics.hpp's: nothing here measures a
// trajectory in its own way.
//
// References (relative error |value / reference - 1|):
//  - threshold [g]: Eq. (12) (VSSW) / Eq. (17) (PW) — exact and linearised kinematics agree at rest;
//  - period (4 x release to first impact): the analytic model, exact kinematics, at kReferenceRtol;
//  - restitution (theta1_dot ratio of the first impact): the whole mechanism's plastic impact for an engine (what its
//    contacts realise), Eq. (19) / Housner for the analytic model (the law it applies);
//  - peak rotation under a record: the analytic model at kReferenceRtol with the whole-mechanism impact for an
//    engine, with Eq. (19) for the analytic model itself.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "multibody/engine.hpp"

namespace vssw::validation {

// The analytic reference's relative tolerance: two decades below the tightest point of the analytic sweep, so that
// the sweep's own error is what is measured, not the reference's.
constexpr double kReferenceRtol = 1e-13;

// CPU time of this process so far [s] (std::clock: every thread's, but the bench runs on one).
double process_cpu_seconds();

struct CpuTiming {
    std::vector<double> repeats;  // [s] each run's CPU time
    double median = 0.0;          // [s]
    double noise = 0.0;           // (max - min) / median of the repeats: the run-to-run spread
};
double median_of(std::vector<double> values);
// Runs `run` `repeats` (>= 1) times, each timed in process CPU time.
CpuTiming time_cpu(const std::function<void()>& run, int repeats);

// The Pareto front of (cost, error) points: true where no other point is at most as costly and at most as wrong
// with one of the two strictly less. Points with a non-finite cost or error are never on it.
std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error);

// One point of an engine's sweep: a label ("dt=2e-04 it=20") and the settings it stands for.
struct BenchSetting {
    std::string label;
    multibody::EngineSettings settings;
};
// The sweep of an engine (by name): analytic rtol 1e-4..1e-12; every other engine what the BENCH lines of its folder's
// engine.cmake state (validation/bench_spec.hpp), its step when they state none. `quick`: one or two cheap points
// (CTest).
std::vector<BenchSetting> bench_sweep(const multibody::Engine& engine, bool quick);

// The reference problems by name, and those run when none is named.
std::vector<std::string> bench_problem_names();
std::vector<std::string> default_bench_problems(bool quick);
// InputError naming the value and the known names.
void check_bench_problem(const std::string& name);
// The metrics a problem yields ("threshold"; "period", "restitution"; "peak").
std::vector<std::string> bench_problem_metrics(const std::string& problem);
// The target on a metric (compare/targets.hpp), none for the peak.
std::optional<double> bench_target(const std::string& metric);

struct BenchPoint {
    std::string engine, problem, metric, setting;
    multibody::EngineSettings settings;
    CpuTiming cpu;          // of the whole experiment (a free vibration yields period and restitution from one run)
    double value = 0.0;     // NaN when the run failed
    double reference = 0.0;
    double error = 0.0;     // |value / reference - 1|; NaN when the run failed
    std::string failure;    // why value is NaN (empty otherwise)
};

struct BenchOptions {
    std::vector<std::string> engines;   // checked names
    std::vector<std::string> problems;  // checked names
    int repeats = 3;
    bool quick = false;
    std::string record_path;  // the shipped Rinaldi record (data/)
};

// A problem's converged references by metric must all be measured: one that is not (NaN: the analytic run found no
// impact) would leave every point of the problem without an error while the bench still exited 0. Throws
// multibody::EngineFailure naming the problem and the metric.
void require_measured_references(const std::string& problem, const std::map<std::string, double>& by_metric);

// Runs the sweep, one point after another on this thread (so that process CPU time is the point's). `progress`,
// when set, is told of each point as it ends.
std::vector<BenchPoint> run_bench(const BenchOptions& options,
                                  const std::function<void(const BenchPoint&)>& progress = {});

// Per engine: the cheapest setting (least CPU summed over the problems run) whose every metric with a target is
// within it on every problem; nullopt when none is. And per engine and metric-with-target: the cheapest point within
// the target.
struct Cheapest {
    std::string engine;
    std::optional<std::string> setting;  // label
    double cpu_s = 0.0;                  // summed medians over the problems
    // (problem/metric, index in the points) of the cheapest point meeting its target, or nullopt
    std::vector<std::pair<std::string, std::optional<std::size_t>>> per_metric;
};
std::vector<Cheapest> cheapest_within_targets(const std::vector<BenchPoint>& points,
                                              const std::vector<std::string>& engines);

}  // namespace vssw::validation

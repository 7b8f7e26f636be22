#pragma once
// One run of one case, measured: every metric of the study that applies to the run, by the project's one metric code
// (compare/experiments.hpp and compare/metrics.hpp) whatever the backend, beside the closed forms of the paper.
//
// What each excitation runs:
//  - threshold_g: find_threshold on the case's wall (a property of the wall and the run: computed once per wall and
//    run in a process, whatever the excitation's levels; ThresholdCache);
//  - free: run_free_vibration released at theta0 alpha (the analytic model sampled every 1e-4 s, as vssw compare
//    measures it, so that its period and restitution are measured like an engine's);
//  - pulse, record: a run from rest until the motion's end + kResponseTail, or rest, or overturning;
//  - scale-to-collapse: such runs on a rising scale (see collapse_scale in measure.cpp).
// Peaks, overturning, the energy balance and the roller's tension come from the analytic model's located events
// (multibody::LocatedEvents) when it is the backend, from the samples otherwise.
//
// A run that fails (an engine blows up, an integration fails, the case is not a model the run can hold) gives its
// metrics the status "failed: <reason>"; the study goes on.
#include <cstddef>
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "multibody/engine.hpp"
#include "study/grid.hpp"

namespace vssw::study {

// After a pulse or a record the run goes on this long (or until the wall is at rest, or overturns) [s]: the wall may
// keep rocking after the shaking; `vssw history`'s default (kDefaultExtraTime), so both give the same peaks.
constexpr double kResponseTail = 10.0;

struct Measurement {
    std::size_t metric = 0;  // index in StudySpec::metrics
    double value = 0.0;      // NaN: nothing to report (the event did not happen, or the metric failed)
    std::string status;      // "ok" or "failed: <reason>" (one line)
    // The analytic model's own assumptions failing along the run (analytic/validity.hpp), "; "-joined: the values
    // stand, but the model may not hold there. The same for every row of a task; empty for the engines.
    std::string warnings;
};

// Thresholds computed once per (wall, run) in a process, shared by the threads (a second asker waits for the first).
struct ThresholdOutcome {
    double value_g = 0.0;
    std::string failure;  // empty: measured
};
class ThresholdCache {
public:
    ThresholdOutcome get(std::size_t wall, std::size_t run, const std::function<ThresholdOutcome()>& compute);

private:
    std::mutex mutex_;
    std::map<std::pair<std::size_t, std::size_t>, std::shared_future<ThresholdOutcome>> outcomes_;
};

// The metrics of the study that apply to this run on this case, in StudySpec::metrics order (the analytic model's
// own metrics are left out for an engine). `run_index` is the run's index in Grid::runs().
std::vector<Measurement> measure(const Grid& grid, const CaseSpec& c, std::size_t run_index,
                                 const multibody::Engine& engine, ThresholdCache& thresholds);

// A rough cost of the run [s], for ordering tasks longest first (compare/task_pool.hpp).
double estimated_cost(const Grid& grid, const CaseSpec& c, const RunSpec& run);

}  // namespace vssw::study

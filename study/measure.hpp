#pragma once
// One run of one case, measured: every metric of the study that applies to the run, by the project's one metric code
// (compare/experiments.hpp and compare/metrics.hpp) whatever the backend, beside the closed forms of the paper.
//
// What each excitation runs:
//  - threshold_g: find_threshold on the case's wall (measure_threshold: a task of its own per wall and run);
//  - free: run_free_vibration released at theta0 alpha (the analytic model sampled every 1e-4 s, as vssw compare
//    measures it, so that its period and restitution are measured like an engine's);
//  - pulse, record: a run from rest until the motion's end + the case's response_tail, or rest, or overturning;
//  - scale-to-collapse: such runs on a rising scale (see collapse_scale in measure.cpp).
// Peaks, overturning, the energy balance and the roller's tension come from the analytic model's located events
// (multibody::LocatedEvents) when it is the backend, from the samples otherwise.
//
// A run that fails (an engine blows up, an integration fails, the case is not a model the run can hold, a worker
// process dies) gives its metrics the status "failed: <reason>"; the study goes on.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "compare/experiments.hpp"
#include "multibody/engine.hpp"
#include "study/grid.hpp"

namespace vssw::study {

// After a pulse or a record a study's run goes on this long (CaseSpec::response_tail; compare/experiments.hpp), as
// `vssw history`'s does by default: both give the same peaks.

struct Measurement {
    std::size_t metric = 0;  // index in StudySpec::metrics
    double value = 0.0;      // NaN: nothing to report (the event did not happen, or the metric failed)
    std::string status;      // "ok" or "failed: <reason>" (one line)
    // The analytic model's own assumptions failing along the run (analytic/validity.hpp), "; "-joined: the values
    // stand, but the model may not hold there. The same for every row of a task; empty for the engines.
    std::string warnings;
};

// One run of a scale-to-collapse search (incremental dynamic analysis): the scale on the record, the peak |theta1| /
// alpha1 (|theta| / alpha of a parapet; the collapse angle's when it overturned, as peak_rotation), and whether it
// overturned. A record's points sorted by scale are its IDA curve (Vamvatsikos & Cornell 2002), a resurrection (a
// larger scale that stands after one that overturned) kept.
struct IdaPoint {
    double scale = 0.0, peak = 0.0;
    bool overturned = false;
};

// The metrics of the study that apply to this run on this case, in StudySpec::metrics order, but threshold_g (the
// analytic model's own metrics are left out for an engine). `run_index` is the run's index in Grid::runs(). With
// `ida`, a scale-to-collapse search's runs in the order run (nothing else leaves it empty).
std::vector<Measurement> measure(const Grid& grid, const CaseSpec& c, std::size_t run_index,
                                 const multibody::Engine& engine, std::vector<IdaPoint>* ida = nullptr);

// threshold_g of the case's wall for the run: a property of the wall, not of the excitation, so a study runs it as a
// task of its own, once per wall and run, and gives it to every case of that wall (study/runner.cpp).
Measurement measure_threshold(const Grid& grid, const CaseSpec& c, std::size_t run_index,
                              const multibody::Engine& engine);
// Whether the case's part measures threshold_g.
bool measures_threshold(const Grid& grid, const CaseSpec& c);

// Throws InputError when an engine run cannot be made as set for the case, before anything runs: a setting for the
// other kind of wall (parapet-only on a VSSW, VSSW-only on a parapet: multibody::require_settings_fit_wall), or a
// step that would take more than 1e8 steps or cannot resolve the case's wall or its ground motion (multibody::require_step_resolves; for a free vibration and
// threshold trials compare::require_free_vibration_steps and require_threshold_steps). `vssw compare` under a record
// or pulse refuses such a run before it runs anything, and so does `vssw study` (require_runs_resolve).
void require_run_resolves(const Grid& grid, const CaseSpec& c, const RunSpec& run, const multibody::Engine& engine);
// require_run_resolves for every run of each of these cases (a study's, before anything runs): InputError naming the
// first case and run whose step cannot resolve it.
void require_runs_resolve(const Grid& grid, const std::vector<int>& case_ids);

// Roughly the seconds the run simulates (its threshold apart, a task of its own: compare::threshold_seconds), for
// the cost model that orders tasks longest first (compare/case_runner.hpp).
double simulated_seconds(const Grid& grid, const CaseSpec& c);

}  // namespace vssw::study

#pragma once
// The validation suite behind `vssw report` and `vssw check`: named cases (a wall and what is done to it), run for the
// analytic model and each engine, measured with compare/experiments.hpp, collected as rows (case, engine, metric):
// the analytic model's value, the engine's, the relative error. One data model for every output (Markdown, HTML,
// JSON, CSV, plots, bounds checks), so they cannot disagree.
//
// Case ids are stable strings (bounds files and CSV rows name them):
//   threshold  "<wall>"                        e.g. "fig6-vssw", "t1-07-xi0.1", "fig6-pw"
//   free       "<wall>/r<r>"                   e.g. "fig6-vssw/r0.5"
//   history    "<wall>/<record>"               e.g. "fig6-vssw/rinaldi-x0.25"
//   step       "<wall>/r<r>/dt<dt>/<engine>"   e.g. "fig6-vssw/r0.5/dt0.0005/ode" (error against step size; a step
//                                              case belongs to one engine, SuiteCase::engine)
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analytic/assumption_sets.hpp"
#include "analytic/ground_motion.hpp"
#include "compare/experiments.hpp"
#include "multibody/engine.hpp"

namespace vssw::validation {

// The walls ----------------------------------------------------------------------------------------------------

struct SuiteWall {
    std::string id;     // "fig6-vssw"
    std::string label;  // "Fig. 6 VSSW 4 x 0.4 m, h1/h 0.7"
    multibody::WallScene scene;
};

// The cases ----------------------------------------------------------------------------------------------------

enum class CaseKind {
    threshold,  // find_threshold: metric threshold_g
    free,       // run_free_vibration released at r alpha: period, restitution
    history,    // a ground-motion record from rest: the history metrics below (metrics_of lists them)
    step,       // free vibration at a given engine step dt (error against step size): period, restitution
};
const char* to_string(CaseKind kind);
// The metrics run_suite measures for a case of this kind (a metric marked VSSW-only only on a VSSW), as the one
// metric table says (compare/metric_catalog.hpp), in its order.
std::vector<std::string> metrics_of(CaseKind kind, bool vssw);

struct SuiteRecord {
    std::string id;        // "rinaldi-x0.25"
    std::string label;     // "Northridge 1994, Rinaldi 228, x 0.25"
    std::string path;      // the file in data/
    double scale = 1.0;    // applied to the record's accelerations
};

struct SuiteCase {
    std::string id;  // see the top of this file
    CaseKind kind;
    std::string wall_id;
    double r = 0.0;                 // free, step: release at r alpha
    std::string record_id;          // history
    std::optional<double> dt;       // step: the engine step (otherwise the engine's default)
    std::string engine;             // step: the one engine it runs for (no analytic row); empty: every engine
    // The settings an engine runs this case at, where a suite file sets them ([settings] and [part.settings]); an
    // engine not named here runs at its default_settings(). A step case's dt overrides its engine's step.
    std::map<std::string, multibody::EngineSettings> settings;
    // history: how long the run goes on after the record [s] (it stops earlier at rest or overturning): the suite's
    // answer, kSuiteResponseTail, unless the suite file's part gives response_tail; a study's is kResponseTail
    // (compare/experiments.hpp says why two).
    double response_tail = compare::kSuiteResponseTail;
};

struct Suite {
    std::string name;  // "default" or "full" (also for a selection of its cases)
    std::vector<SuiteWall> walls;
    std::vector<SuiteRecord> records;
    std::vector<SuiteCase> cases;
    // Steps of the step study per engine (the dt values of its `step` cases), for the plots' x axis.
    std::map<std::string, std::vector<double>> step_study;
    // The suite-wide settings of an engine (a suite file's top-level [settings]), reported as the engine's settings;
    // without, its default_settings(). Each case carries the settings it runs at (SuiteCase::settings).
    std::map<std::string, multibody::EngineSettings> engine_settings;
    // The reference: the analytic model under this assumption set (analytic/assumption_sets.hpp), every engine
    // measured against it. A suite file may name it ([assumptions], one set: reference_named); `vssw report
    // --assumptions` chooses it otherwise.
    AssumptionSet reference = kDefaultAssumptionSet;
    bool reference_named = false;  // the suite file named the set

    const SuiteWall& wall(const std::string& id) const;      // throws InputError on an unknown id
    const SuiteRecord& record(const std::string& id) const;  // throws InputError on an unknown id
};

// The shipped suites ("default", "full") are study files, studies/validation-<name>.toml, read by
// validation::read_suite (validation/suite_file.hpp): walls and cases are data, and a user can copy one and change it.
// The cases whose ids are listed (each must exist: InputError naming the first that does not), with the walls and
// records they need.
Suite select_cases(const Suite& suite, const std::vector<std::string>& case_ids);

// The results --------------------------------------------------------------------------------------------------

// One measured quantity of one case for one engine. For the engine "analytic" the row holds the analytic model's
// value in both `analytic` and `engine` (rel_error 0): its drift is checked against stored references (vssw check).
// Metrics, by case kind (the analytic side is AnalyticEngine under the suite's reference set, Suite::reference: by
// default the mechanism, exact kinematics; its record runs sampled every 1 ms, their peaks its located turning
// points):
//   threshold       threshold_g [g]: find_threshold on both sides
//   free, step      period [s]: 4 x release to first impact; restitution []: theta1_dot ratio at the first impact
//                   (the reference's impact law: under `mechanism` the whole mechanism's plastic impact for a VSSW,
//                   under `paper` Eq. 19; Housner's e for a PW under either);
//   history         peak_rotation [alpha1]: max |theta1| / alpha1, the collapse angle's when it overturned (one
//                   measure with a study's: compare/response.hpp); peak_time [s]: when it is reached (overturned);
//                   overturned [0/1]: rel_error = engine - analytic (0 when they agree, +-1 when not);
//                   rms_difference [alpha1]: analytic = the analytic peak_rotation, engine = RMS over the analytic
//                   run of (theta1_engine - theta1_analytic) / alpha1, rel_error = that RMS / the analytic peak
// A metric a run does not show (no impact, an unresolved impact) is NaN, never a missing row.
struct MetricRow {
    std::string case_id;
    std::string engine;
    std::string metric;     // "threshold_g", "period", "restitution", "peak_rotation", "rms_difference", ...
    double analytic;        // the reference: the analytic model (or a closed form, see `reference`)
    double engine_value;
    double rel_error;       // engine_value / analytic - 1 (NaN when either is missing)
    std::string reference;  // what `analytic` is: "analytic model"
    std::string unit;       // "g", "s", "", "alpha1"
};

// An engine that failed on a case (EngineFailure): reported, the rest of the report still written.
struct CaseFailure {
    std::string case_id;
    std::string engine;
    std::string message;
};

// The analytic model's own assumptions failing along a case's run (analytic/validity.hpp): its values stand, but
// the model may not hold there.
struct ModelWarning {
    std::string case_id;
    std::string message;
};

// A time history for the overlay plots: theta1 / alpha1 against t, decimated for plotting.
// The analytic model's traces name the assumption set they are run under, the reference's ("mechanism" or "paper");
// an engine's: empty.
struct Trace {
    std::string case_id;
    std::string engine;  // "analytic" for the reference
    std::vector<double> t, theta1_over_alpha1;
    std::string assumption;  // the analytic model's set (to_string(AssumptionSet)); "" for an engine
};

// CPU time of one (case, engine) task [s], its thread's and its engine runs' children's: where a suite's time goes
// (bench/suite_profile.cpp). The analytic model's side of a case, shared by the case's tasks, is charged to the task
// that ran it first.
struct TaskTime {
    std::string case_id;
    CaseKind kind;
    std::string engine;
    double cpu_s;
};

struct EngineRunInfo {
    std::string name, version;
    // As used: the suite's engine_settings, else the engine's defaults (a case's own settings and a step case's dt
    // are the case's: Suite, SuiteCase::settings).
    multibody::EngineSettings settings;
};

// The analytic model under the set that is not the reference, measured like an engine against it
// (validation/assumption_set_engine.hpp): its rows and failures are kept apart from the engines', so that no engine
// verdict, summary, bound or CSV line counts them.
struct OtherSetRun {
    AssumptionSet set = AssumptionSet::paper;
    std::string engine;  // its engine id in `rows`, "paper-model" or "mechanism-model"
    std::vector<MetricRow> rows;
    std::vector<CaseFailure> failures;
};

struct SuiteResults {
    std::string suite;
    AssumptionSet reference = kDefaultAssumptionSet;  // the suite's (Suite::reference)
    std::vector<EngineRunInfo> engines;  // in the order asked, "analytic" first
    std::vector<MetricRow> rows;
    std::vector<CaseFailure> failures;
    std::vector<ModelWarning> model_warnings;  // from the analytic model's own runs (free vibrations, histories)
    std::vector<Trace> traces;
    std::vector<TaskTime> task_times;  // one per task, in (case, engine) order
    std::optional<OtherSetRun> other_set;  // when RunOptions::other_set asked for it
    double wall_time_s = 0.0;
    int threads = 1;
};

// Running --------------------------------------------------------------------------------------------------------

struct RunOptions {
    int threads = 0;  // 0: the available cores
    // Called after each (case, engine) task with the number done and the total (from the worker threads, serialised).
    std::function<void(int done, int total, const std::string& what)> progress;
    bool keep_traces = true;  // history and free cases keep decimated traces for the plots
    // Also run the analytic model under the other assumption set as an engine (SuiteResults::other_set): the report's
    // row on what the set's assumptions change. Its runs cost as the analytic model's (~0.3 ms per simulated second).
    bool other_set = false;
    // The suite's records already read, by path, unscaled (the report reads them before its folder is made, to refuse
    // a bad one up front): run_suite uses them instead of reading the files again. Null: it reads them itself.
    const std::map<std::string, GroundMotion>* records_read = nullptr;
};

// Runs every case of the suite for the analytic model and each named engine (unknown names: InputError naming the
// available ones), on `threads` threads. An EngineFailure on a task becomes a CaseFailure; an InputError propagates.
// Rows, failures and traces come in the suite's case order, then the engine order ("analytic" first), whatever the
// threads did. A step case runs only for its own engine, when that engine is asked for. An engine whose
// runs_concurrently() is false has one task running at a time (other engines' tasks run beside it).
SuiteResults run_suite(const Suite& suite, const std::vector<std::string>& engines, const RunOptions& options = {});
// The same with engine objects the caller owns (alive during the call; each at its default_settings()): for engines
// make_engine does not know, e.g. a test's. The analytic model is always run first (an "analytic" given is replaced
// by it); a name given twice is an InputError.
SuiteResults run_suite_with_engines(const Suite& suite, const std::vector<const multibody::Engine*>& engines,
                                    const RunOptions& options = {});

}  // namespace vssw::validation

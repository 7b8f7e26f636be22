#include "validation/suite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <malloc.h>
#include <limits>
#include <memory>
#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/simulate.hpp"
#include "compare/case_runner.hpp"
#include "compare/experiments.hpp"
#include "compare/response.hpp"
#include "compare/metric_catalog.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_resolution.hpp"
#include "validation/assumption_set_engine.hpp"

namespace vssw::validation {
namespace {

using multibody::AnalyticEngine;
using multibody::EngineFailure;
using multibody::Excitation;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kReferenceEngine = "analytic";

// Traces: at most this many points per trace (plots), a free vibration's first seconds only.
constexpr std::size_t kMaxTracePoints = 2000;
constexpr double kFreeTraceSeconds = 10.0;
// [s] The analytic model's sampling of a record run (history cases). Its peak comes from the located turning points
// (LocatedEvents), not the samples; the samples serve the RMS difference against an engine that reports every 1 ms at
// its defaults (2 ms for Simbody) and the trace, at most kMaxTracePoints over a 20-40 s record (one per 10-20 ms).
// At the 1e-4 s of analytic_reference_settings() a record run held 16 MB for as long as its case ran, and every engine
// run's child copied the parent's page tables (docs/measurements/speed.md, "The parent's memory").
constexpr double kHistoryReferenceSampleDt = 1e-3;

// Running ----------------------------------------------------------------------------------------------------------

struct TaskOutput {
    double cpu_s = 0.0;
    std::vector<MetricRow> rows;
    std::vector<Trace> traces;
    std::optional<std::string> failure;
    std::vector<std::string> model_warnings;  // the reference task's analytic run only (no repeats per engine)
};

// The metric's unit from the one metric table (compare/metric_catalog.hpp).
const char* unit_of(const char* metric) {
    const compare::MetricInfo* m = compare::find_metric(metric);
    if (m == nullptr) throw std::logic_error(std::string("suite metric '") + metric + "' is not in the catalogue");
    return m->unit;
}

// rel_error: the relative error of engine_value against analytic, unless given (overturned, rms_difference).
MetricRow make_row(const std::string& case_id, const std::string& engine, const char* metric, double analytic,
                   double engine_value, const char* reference) {
    return {case_id, engine, metric, analytic, engine_value, compare::compare_metric(analytic, engine_value).rel_error,
            reference, unit_of(metric)};
}
MetricRow make_row(const std::string& case_id, const std::string& engine, const char* metric, double analytic,
                   double engine_value, double rel_error, const char* reference) {
    return {case_id, engine, metric, analytic, engine_value, rel_error, reference, unit_of(metric)};
}

// assumption: the analytic model's set ("mechanism", "paper"); "" for an engine's trace.
Trace make_trace(const std::string& case_id, const std::string& engine, const multibody::Trajectory& traj,
                 double alpha, double t_max, const std::string& assumption) {
    Trace tr{case_id, engine, {}, {}, assumption};
    std::size_t n = 0;
    while (n < traj.samples.size() && traj.samples[n].t <= t_max) ++n;
    if (n == 0) return tr;
    const std::size_t stride = std::max<std::size_t>(1, (n + kMaxTracePoints - 2) / (kMaxTracePoints - 1));
    auto add = [&](std::size_t i) {
        tr.t.push_back(traj.samples[i].t);
        tr.theta1_over_alpha1.push_back(traj.samples[i].theta1 / alpha);
    };
    for (std::size_t i = 0; i < n; i += stride) add(i);
    if ((n - 1) % stride != 0) add(n - 1);
    return tr;
}

// theta1 of `traj` at time t, linear between samples, held beyond its ends. `cursor` advances monotonically.
double theta_at(const multibody::Trajectory& traj, double t, std::size_t& cursor) {
    const auto& s = traj.samples;
    if (t <= s.front().t) return s.front().theta1;
    while (cursor + 1 < s.size() && s[cursor + 1].t < t) ++cursor;
    if (cursor + 1 >= s.size()) return s.back().theta1;
    const double t0 = s[cursor].t, t1 = s[cursor + 1].t;
    const double w = t1 > t0 ? (t - t0) / (t1 - t0) : 1.0;
    return s[cursor].theta1 + w * (s[cursor + 1].theta1 - s[cursor].theta1);
}

// RMS over the reference run's duration of theta1_other - theta1_reference [rad] (trapezoidal in time, the other
// trajectory interpolated onto the reference's samples).
double rms_difference(const multibody::Trajectory& reference, const multibody::Trajectory& other) {
    const auto& r = reference.samples;
    if (r.size() < 2 || other.samples.empty()) return kNaN;
    const double duration = r.back().t - r.front().t;
    if (!(duration > 0.0)) return kNaN;
    std::size_t cursor = 0;
    double integral = 0.0;
    double prev = theta_at(other, r.front().t, cursor) - r.front().theta1;
    for (std::size_t i = 1; i < r.size(); ++i) {
        const double d = theta_at(other, r[i].t, cursor) - r[i].theta1;
        integral += 0.5 * (prev * prev + d * d) * (r[i].t - r[i - 1].t);
        prev = d;
    }
    return std::sqrt(integral / duration);
}

// The analytic model's side of a case, computed once by whichever of the case's tasks (the reference's or an
// engine's) comes first and shared by the others: its reference value does not depend on the engine (the reference's
// settings, TaskContext::reference_settings, do not depend on the engine), and before this each engine's task ran it again
// (a threshold bisection, a free vibration, two record runs per engine). The history trajectory is released by the
// last task that reads it.
struct CaseReference {
    std::once_flag once;
    double free_t_end = 0.0;  // free, step: the run's end (first_impact_duration), set before the tasks run
    double threshold_g = kNaN;                  // threshold
    compare::FreeVibrationResult free;                   // free, step: the analytic run, its trajectory dropped
    std::optional<Trace> free_trace;            // free: the analytic trace when traces are kept
    multibody::Trajectory history;              // history: the analytic run (engines' RMS difference)
    std::atomic<int> users{0};                  // tasks of the case still to read `history`
};

struct TaskContext {
    const SuiteCase& c;
    const SuiteWall& wall;
    const multibody::Engine& engine;
    bool reference;  // the analytic model's own rows
    const GroundMotion* record;
    bool keep_traces;
    CaseReference& ref;
    // The reference: AnalyticEngine's settings under the suite's set (multibody::analytic_settings), and its name for
    // the traces.
    const multibody::EngineSettings& reference_settings;
    const char* reference_set;
};

compare::FreeVibrationOptions free_options(const TaskContext& x) {
    compare::FreeVibrationOptions options;
    options.r = x.c.r;
    options.t_end = x.ref.free_t_end;  // what t_end 0 would compute, computed once
    return options;
}

Excitation history_excitation(const TaskContext& x) {
    Excitation ex;
    ex.horizontal = *x.record;
    ex.theta0 = 0.0;
    ex.t_end = x.record->duration() + x.c.response_tail;
    ex.stop_at_rest = true;
    ex.motion_only = true;  // the peak and the trace are read from theta1 alone
    return ex;
}

// The analytic model's runs of the case (CaseReference), once.
void compute_reference(const TaskContext& x) {
    const AnalyticEngine analytic;
    CaseReference& ref = x.ref;
    switch (x.c.kind) {
        case CaseKind::threshold:
            ref.threshold_g = compare::find_threshold(analytic, x.reference_settings, x.wall.scene).value_g;
            return;
        case CaseKind::free:
        case CaseKind::step: {
            ref.free = compare::run_free_vibration(analytic, x.reference_settings, x.wall.scene, free_options(x));
            if (x.keep_traces && x.c.kind == CaseKind::free)
                ref.free_trace = make_trace(x.c.id, kReferenceEngine, ref.free.trajectory, x.wall.scene.alpha(),
                                            kFreeTraceSeconds, x.reference_set);
            // The rows need its metrics only (warnings kept). Swapped out: `samples = {}` is the initializer-list
            // assignment, which keeps the capacity (it held 70 MB of the report's parent this way).
            std::vector<multibody::TrajectorySample>().swap(ref.free.trajectory.samples);
            return;
        }
        case CaseKind::history: {
            const Excitation ex = history_excitation(x);
            multibody::EngineSettings sampled = x.reference_settings;
            sampled.sample_dt = kHistoryReferenceSampleDt;
            ref.history = analytic.simulate(x.wall.scene, ex, sampled);
            return;
        }
    }
}

const CaseReference& reference_of(const TaskContext& x) {
    // An exception leaves it for the next task to try. malloc_trim: the reference's runs leave their sample vectors'
    // pages in this thread's malloc arena, which glibc keeps; each engine run's child would copy them (fork).
    std::call_once(x.ref.once, [&] {
        compute_reference(x);
        ::malloc_trim(0);
    });
    return x.ref;
}

// The settings the engine runs the case at: the case's own (a suite file's), else the engine's defaults.
multibody::EngineSettings case_settings(const SuiteCase& c, const multibody::Engine& engine) {
    const auto it = c.settings.find(engine.name());
    return it != c.settings.end() ? it->second : engine.default_settings();
}

void threshold_task(const TaskContext& x, TaskOutput& out) {
    const std::string name = x.engine.name();
    const double a = reference_of(x).threshold_g;
    const double e = x.reference ? a : compare::find_threshold(x.engine, case_settings(x.c, x.engine), x.wall.scene).value_g;
    out.rows.push_back(make_row(x.c.id, name, "threshold_g", a, e, "analytic model"));
}

void free_rows(const TaskContext& x, const compare::FreeVibrationResult& a, const compare::FreeVibrationResult& e, TaskOutput& out) {
    const std::string name = x.engine.name();
    out.rows.push_back(make_row(x.c.id, name, "period", a.period.value_or(kNaN), e.period.value_or(kNaN),
                                "analytic model"));
    out.rows.push_back(make_row(x.c.id, name, "restitution", a.restitution.value_or(kNaN),
                                e.restitution.value_or(kNaN), "analytic model"));
}

void free_task(const TaskContext& x, TaskOutput& out) {
    const CaseReference& ref = reference_of(x);
    if (x.reference) {
        free_rows(x, ref.free, ref.free, out);
        out.model_warnings = ref.free.trajectory.warnings;
        if (ref.free_trace) out.traces.push_back(*ref.free_trace);
        return;
    }
    multibody::EngineSettings settings = case_settings(x.c, x.engine);
    if (x.c.dt) settings.dt = *x.c.dt;
    // Both sides run for the same time (free_vibration_with_analytic's rule), the analytic one shared.
    const compare::FreeVibrationResult e = compare::run_free_vibration(x.engine, settings, x.wall.scene, free_options(x));
    free_rows(x, ref.free, e, out);
    // A first-impact ratio outside (0, 1] is a failure of the engine's run, not a restitution: the row is NaN and
    // the report lists why.
    if (!e.restitution_note.empty()) out.failure = e.restitution_note;
    if (x.keep_traces && x.c.kind == CaseKind::free)
        out.traces.push_back(
            make_trace(x.c.id, x.engine.name(), e.trajectory, x.wall.scene.alpha(), kFreeTraceSeconds, ""));
}

void history_rows(const TaskContext& x, const multibody::Trajectory& a, const multibody::Trajectory& e,
                  TaskOutput& out) {
    const std::string name = x.engine.name();
    const double alpha = x.wall.scene.alpha();
    // The measures a study and `vssw compare --record` give the same runs (compare/response.hpp).
    const compare::Response pa = compare::response_of(a, x.wall.scene), pe = compare::response_of(e, x.wall.scene);
    const double peak_a = pa.peak / alpha;
    out.rows.push_back(
        make_row(x.c.id, name, "peak_rotation", peak_a, pe.peak / alpha, "analytic model"));
    out.rows.push_back(make_row(x.c.id, name, "peak_time", pa.peak_time, pe.peak_time, "analytic model"));
    const double over_a = a.overturned ? 1.0 : 0.0, over_e = e.overturned ? 1.0 : 0.0;
    out.rows.push_back(make_row(x.c.id, name, "overturned", over_a, over_e, over_e - over_a, "analytic model"));
    const double rms = x.reference ? 0.0 : rms_difference(a, e) / alpha;
    out.rows.push_back(make_row(x.c.id, name, "rms_difference", peak_a, rms, rms / peak_a, "analytic model"));
}

void history_task(const TaskContext& x, TaskOutput& out) {
    CaseReference& ref = x.ref;
    // The last task of the case to read the analytic trajectory releases it, however this one ends.
    struct Release {
        CaseReference& r;
        ~Release() {
            if (r.users.fetch_sub(1) == 1) {
                r.history = {};
                ::malloc_trim(0);  // as in reference_of
            }
        }
    } release{ref};
    const multibody::Trajectory& a = reference_of(x).history;
    const double all = std::numeric_limits<double>::infinity();
    if (x.reference) {
        history_rows(x, a, a, out);
        out.model_warnings = a.warnings;
        if (x.keep_traces)
            out.traces.push_back(make_trace(x.c.id, x.engine.name(), a, x.wall.scene.alpha(), all, x.reference_set));
        return;
    }
    const multibody::Trajectory e =
        x.engine.simulate(x.wall.scene, history_excitation(x), case_settings(x.c, x.engine));
    history_rows(x, a, e, out);
    if (x.keep_traces) out.traces.push_back(make_trace(x.c.id, x.engine.name(), e, x.wall.scene.alpha(), all, ""));
}

void run_task(const TaskContext& x, TaskOutput& out) {
    switch (x.c.kind) {
        case CaseKind::threshold: threshold_task(x, out); return;
        case CaseKind::free:
        case CaseKind::step: free_task(x, out); return;
        case CaseKind::history: history_task(x, out); return;
    }
}

// The task's engine settings, checked for every task before any runs: a setting for the other kind of wall
// (multibody::require_settings_fit_wall), a step that takes too many steps or is too coarse
// (compare::require_threshold_steps and require_free_vibration_steps, multibody::require_step_resolves). InputError
// naming the case; the settings are the ones the task runs at.
void require_task_steps(const TaskContext& x) {
    if (x.reference) return;
    multibody::EngineSettings settings = case_settings(x.c, x.engine);
    try {
        multibody::require_settings_fit_wall(x.engine.display_name(), settings, x.engine.setting_descriptions(),
                                             x.wall.scene);
        switch (x.c.kind) {
            case CaseKind::threshold: compare::require_threshold_steps(x.engine, settings, x.wall.scene); return;
            case CaseKind::free:
            case CaseKind::step:
                if (x.c.dt) settings.dt = *x.c.dt;  // as free_task runs it
                compare::require_free_vibration_steps(x.engine, settings, x.wall.scene, free_options(x));
                return;
            case CaseKind::history:
                multibody::require_step_resolves(x.engine.display_name(), x.wall.scene, history_excitation(x),
                                                 settings.dt, !x.engine.dt_is_a_reporting_interval());
                return;
        }
    } catch (const InputError& e) {
        throw InputError(fmt::format("case '{}': {}", x.c.id, e.what()));
    }
}

// Simulated seconds a task's engine runs (compare/case_runner.hpp's cost model). free_t_end: the case's free
// vibration end (CaseReference).
double simulated_seconds(const SuiteCase& c, const SuiteWall& w, const GroundMotion* record, double free_t_end) {
    switch (c.kind) {
        case CaseKind::threshold: return compare::threshold_seconds(w.scene);
        case CaseKind::free:
        case CaseKind::step: return free_t_end;
        case CaseKind::history: return record ? compare::response_seconds(*record, c.response_tail) : 0.0;
    }
    return 0.0;
}

}  // namespace

std::vector<std::string> metrics_of(CaseKind kind, bool vssw) {
    const compare::SuiteMeasure measure = kind == CaseKind::threshold ? compare::SuiteMeasure::threshold
                                 : kind == CaseKind::history ? compare::SuiteMeasure::history
                                                             : compare::SuiteMeasure::free;
    std::vector<std::string> out;
    for (const compare::MetricInfo* m : compare::suite_metrics())
        if (m->suite == measure && (vssw || !m->vssw_only)) out.push_back(m->name);
    return out;
}

const char* to_string(CaseKind kind) {
    switch (kind) {
        case CaseKind::threshold: return "threshold";
        case CaseKind::free: return "free";
        case CaseKind::history: return "history";
        case CaseKind::step: return "step";
    }
    return "unknown";
}

const SuiteWall& Suite::wall(const std::string& id) const {
    for (const SuiteWall& w : walls)
        if (w.id == id) return w;
    throw InputError(fmt::format("suite '{}' has no wall '{}'", name, id));
}

const SuiteRecord& Suite::record(const std::string& id) const {
    for (const SuiteRecord& r : records)
        if (r.id == id) return r;
    throw InputError(fmt::format("suite '{}' has no record '{}'", name, id));
}

Suite select_cases(const Suite& suite, const std::vector<std::string>& case_ids) {
    std::set<std::string> wanted;
    for (const std::string& id : case_ids) {
        if (std::none_of(suite.cases.begin(), suite.cases.end(), [&](const SuiteCase& c) { return c.id == id; }))
            throw InputError(fmt::format("suite '{}' has no case '{}'", suite.name, id));
        wanted.insert(id);
    }
    Suite out;
    out.name = suite.name;  // the cases keep their ids and meaning: results name the suite they come from
    out.engine_settings = suite.engine_settings;
    out.reference = suite.reference;
    out.reference_named = suite.reference_named;
    std::set<std::string> walls, records;
    for (const SuiteCase& c : suite.cases) {
        if (!wanted.count(c.id)) continue;
        out.cases.push_back(c);
        walls.insert(c.wall_id);
        if (c.kind == CaseKind::history) records.insert(c.record_id);
        if (c.kind == CaseKind::step && c.dt) {
            std::vector<double>& dts = out.step_study[c.engine];
            if (std::find(dts.begin(), dts.end(), *c.dt) == dts.end()) dts.push_back(*c.dt);
        }
    }
    for (const SuiteWall& w : suite.walls)
        if (walls.count(w.id)) out.walls.push_back(w);
    for (const SuiteRecord& r : suite.records)
        if (records.count(r.id)) out.records.push_back(r);
    // Every named wall and record must be in the suite (a hand-made suite may lack one).
    for (const std::string& w : walls) (void)suite.wall(w);
    for (const std::string& r : records) (void)suite.record(r);
    return out;
}

SuiteResults run_suite(const Suite& suite, const std::vector<std::string>& engines, const RunOptions& options) {
    // The analytic model first (the reference rows), then each named engine once, in the order given.
    std::vector<std::unique_ptr<multibody::Engine>> owned;
    owned.push_back(multibody::make_engine(kReferenceEngine));
    for (const std::string& name : engines) {
        if (name == kReferenceEngine) continue;
        if (std::any_of(owned.begin(), owned.end(), [&](const auto& e) { return e->name() == name; })) continue;
        owned.push_back(multibody::make_engine(name));  // InputError naming the available ones
    }
    std::vector<const multibody::Engine*> list;
    for (const auto& e : owned) list.push_back(e.get());
    return run_suite_with_engines(suite, list, options);
}

namespace {

// The engines of a run: the analytic model first (the reference rows), then each given engine once.
std::vector<const multibody::Engine*> suite_engines(const AnalyticEngine& reference,
                                                    const std::vector<const multibody::Engine*>& given) {
    std::vector<const multibody::Engine*> engines = {&reference};
    for (const multibody::Engine* e : given) {
        if (e == nullptr) throw InputError("run_suite: a null engine");
        const std::string name = e->name();
        if (name == kReferenceEngine) continue;
        if (std::any_of(engines.begin(), engines.end(), [&](const auto* x) { return x->name() == name; }))
            throw InputError(fmt::format("run_suite: engine '{}' given twice", name));
        engines.push_back(e);
    }
    return engines;
}

// The walls of the cases and the records they run, read up front: a bad suite is an InputError before anything runs.
struct SuiteInputs {
    std::vector<const SuiteWall*> case_walls;  // per case
    std::map<std::string, GroundMotion> records;

    const GroundMotion* record_of(const SuiteCase& c) const {
        return c.kind == CaseKind::history ? &records.at(c.record_id) : nullptr;
    }
};

// The record at `path`: the one the caller already read when it gave it, else read here.
GroundMotion record_at(const std::string& path, const std::map<std::string, GroundMotion>* records_read) {
    if (records_read)
        if (const auto it = records_read->find(path); it != records_read->end()) return it->second;
    return read_record(path);
}

SuiteInputs read_inputs(const Suite& suite, const std::map<std::string, GroundMotion>* records_read) {
    SuiteInputs in;
    for (const SuiteCase& c : suite.cases) {
        in.case_walls.push_back(&suite.wall(c.wall_id));
        if (c.kind == CaseKind::history && !in.records.count(c.record_id)) {
            const SuiteRecord& r = suite.record(c.record_id);
            in.records.emplace(r.id, record_at(r.path, records_read).scaled(r.scale));
        }
        if (c.kind == CaseKind::step && !c.dt) throw InputError(fmt::format("step case '{}' has no step dt", c.id));
    }
    return in;
}

// Tasks in (case, engine) order: their outputs are assembled in this order whatever the threads did. Each task is
// counted as a user of its case's shared analytic side (`references`, one per case).
std::vector<compare::CaseTask> plan_tasks(const Suite& suite, const SuiteInputs& in,
                                 const std::vector<const multibody::Engine*>& engines,
                                 std::vector<CaseReference>& references) {
    std::vector<compare::CaseTask> tasks;
    for (std::size_t ci = 0; ci < suite.cases.size(); ++ci) {
        const SuiteCase& c = suite.cases[ci];
        const SuiteWall& w = *in.case_walls[ci];
        if (c.kind == CaseKind::free || c.kind == CaseKind::step)
            references[ci].free_t_end =
                compare::first_impact_duration(w.scene, c.r * w.scene.alpha());  // its rows read the first impact
        const double seconds = simulated_seconds(c, w, in.record_of(c), references[ci].free_t_end);
        for (std::size_t ei = 0; ei < engines.size(); ++ei) {
            if (!c.engine.empty() && c.engine != engines[ei]->name()) continue;
            const double dt = c.dt ? *c.dt : case_settings(c, *engines[ei]).dt;
            tasks.push_back({ci, ei, compare::task_cost(*engines[ei], seconds, dt)});
            references[ci].users.fetch_add(1);
        }
    }
    return tasks;
}

// The tasks' outputs into the results, in task order; the other set's (OtherSetRun) into results.other_set.
void collect(const Suite& suite, const std::vector<const multibody::Engine*>& engines,
             const std::vector<compare::CaseTask>& tasks, std::vector<TaskOutput>& outputs, SuiteResults& results) {
    for (std::size_t ti = 0; ti < tasks.size(); ++ti) {
        TaskOutput& o = outputs[ti];
        const SuiteCase& c = suite.cases[tasks[ti].case_index];
        const std::string engine = engines[tasks[ti].engine]->name();
        results.task_times.push_back({c.id, c.kind, engine, o.cpu_s});
        if (results.other_set && engine == results.other_set->engine) {
            if (o.failure) results.other_set->failures.push_back({c.id, engine, *o.failure});
            for (MetricRow& r : o.rows) results.other_set->rows.push_back(std::move(r));
            continue;  // its traces are not drawn: the report shows its numbers only
        }
        if (o.failure) results.failures.push_back({c.id, engine, *o.failure});
        for (std::string& w : o.model_warnings) results.model_warnings.push_back({c.id, std::move(w)});
        for (MetricRow& r : o.rows) results.rows.push_back(std::move(r));
        for (Trace& t : o.traces) results.traces.push_back(std::move(t));
    }
}

}  // namespace

SuiteResults run_suite_with_engines(const Suite& suite, const std::vector<const multibody::Engine*>& given,
                                    const RunOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    require(options.threads >= 0, "threads", ">= 0 (0: the available cores)", options.threads);

    const AnalyticEngine reference_engine;
    std::vector<const multibody::Engine*> engines = suite_engines(reference_engine, given);
    SuiteResults results;
    results.suite = suite.name;
    results.reference = suite.reference;
    for (const multibody::Engine* e : engines)
        results.engines.push_back({e->name(), e->version(),
                                   suite.engine_settings.count(e->name()) ? suite.engine_settings.at(e->name())
                                                                          : e->default_settings()});
    // The reference's settings: the analytic backend's defaults with the suite's set, whatever the engine.
    const multibody::EngineSettings reference_settings = multibody::analytic_settings(assumptions_of(suite.reference));
    const char* reference_set = to_string(suite.reference);
    results.engines.front().settings = reference_settings;  // the analytic model runs as the reference
    // The other set, last: an engine to the runner, apart in the results (collect).
    const AssumptionSet other = suite.reference == AssumptionSet::paper ? AssumptionSet::mechanism
                                                                         : AssumptionSet::paper;
    const AssumptionSetEngine other_engine(other);
    if (options.other_set) {
        engines.push_back(&other_engine);
        results.other_set = OtherSetRun{other, other_engine.name(), {}, {}};
    }

    const SuiteInputs in = read_inputs(suite, options.records_read);
    std::vector<CaseReference> references(suite.cases.size());
    const std::vector<compare::CaseTask> tasks = plan_tasks(suite, in, engines, references);
    std::vector<TaskOutput> outputs(tasks.size());
    for (const compare::CaseTask& task : tasks)
        require_task_steps({suite.cases[task.case_index], *in.case_walls[task.case_index], *engines[task.engine],
                            task.engine == 0, in.record_of(suite.cases[task.case_index]), false,
                            references[task.case_index], reference_settings, reference_set});

    // Worker processes (multibody/host/worker_process.hpp), which give a study of ODE runs both cores, cost the suite more
    // than they gain: a fork per simulation of this large process, for ODE's small share of the suite at its 1 ms step
    // (idle, 2 threads: `vssw check --bounds bounds/ci.toml` 1.21 s with them against 1.15 s without,
    // docs/measurements/speed.md "Speed"). ODE's tasks take turns instead (run_cases).
    compare::CaseRunOptions run_options;
    run_options.threads = options.threads;
    if (options.progress)
        run_options.progress = [&](long done, long total, const std::string& what) {
            options.progress(static_cast<int>(done), static_cast<int>(total), what);
        };
    run_options.task_cpu = [&](std::size_t ti, double cpu_s) { outputs[ti].cpu_s = cpu_s; };
    results.threads = compare::run_cases(tasks, engines, run_options, [&](std::size_t ti) {
        const compare::CaseTask& task = tasks[ti];
        const SuiteCase& c = suite.cases[task.case_index];
        const multibody::Engine& engine = *engines[task.engine];
        try {
            const TaskContext x{c,
                                *in.case_walls[task.case_index],
                                engine,
                                task.engine == 0,
                                in.record_of(c),
                                options.keep_traces,
                                references[task.case_index],
                                reference_settings,
                                reference_set};
            run_task(x, outputs[ti]);
        } catch (const EngineFailure& e) {
            outputs[ti] = TaskOutput{};
            outputs[ti].failure = e.what();
        }
        return fmt::format("{} {}{}", c.id, engine.name(), outputs[ti].failure ? " (failed)" : "");
    });

    collect(suite, engines, tasks, outputs, results);
    results.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return results;
}

}  // namespace vssw::validation

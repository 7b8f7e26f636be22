#include "compare/suite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/simulate.hpp"
#include "analytic/specimens.hpp"
#include "compare/experiments.hpp"
#include "compare/task_pool.hpp"
#include "multibody/analytic_engine.hpp"

namespace vssw::compare {
namespace {

using multibody::AnalyticEngine;
using multibody::EngineFailure;
using multibody::Excitation;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kReferenceEngine = "analytic";

// The walls ------------------------------------------------------------------------------------------------------

// Table 1 of the paper (ABK 1981) is data/table1.csv (analytic/specimens.hpp), always the shipped one: the case ids
// name its specimens, and bounds files name the case ids (--data of report and check moves the records only).
// The default suite's specimens: hinge high (0.69), at mid-height (0.50), between (0.60), as bench/engine_accuracy.
constexpr int kDefaultSpecimens[] = {1, 7, 15};
constexpr double kOverburdens[] = {0.0, 0.1, 0.5};
constexpr double kReleases[] = {0.2, 0.5, 0.8};
constexpr double kDefaultTable1Release = 0.5;
constexpr double kStepStudyRelease = 0.5;

// Fig. 6 of the paper: b = 0.2 m, h = 2 m, h1/h = 0.7, xi = 0 (and the parapet of the same size).
constexpr double kFig6Height = 4.0, kFig6Thickness = 0.4, kFig6Hinge = 0.7;
constexpr const char* kFig6Vssw = "fig6-vssw";
constexpr const char* kFig6Pw = "fig6-pw";

// The records --------------------------------------------------------------------------------------------------
//
// Each record is scaled per wall so that the analytic model (exact kinematics) rocks clearly and stays standing, at
// a scale inside a band of scales that all leave the wall standing (the response to a record is erratic in the
// scale: peaks do not grow monotonically). Measured with `vssw history --kinematics exact` (peak |theta1| / alpha):
//  - Fig. 6 VSSW (threshold 0.286 g): Rinaldi (PGA 0.825 g) does not lift it up to x 0.36 (x 0.25 leaves it at rest);
//    x 0.40-0.50 rock it to 0.10-0.81 and leave it standing, x 0.52 overturns it: x 0.45 (peak 0.27).
//    El Centro (PGA 0.319 g): barely lifts it up to x 1.10, x 1.12-1.22 rock it to 0.12-0.92, x 1.25 overturns it:
//    x 1.15 (peak 0.47), the narrowest band of the four.
//  - Fig. 6 PW (threshold 0.1 g): Rinaldi x 0.14-0.24 rock it to 0.05-0.74, x 0.26 overturns it: x 0.17 (peak 0.40;
//    x 0.25 leaves it standing too, at 0.67, too near alpha for an engine's small differences).
//    El Centro x 0.36-0.65 rock it to 0.02-0.80, x 0.70 overturns it: x 0.5 (peak 0.45).
struct RecordSpec {
    const char* wall_id;
    const char* stem;   // id prefix
    const char* label;  // record name
    const char* file;   // in data/
    double scale;
};
constexpr const char* kRinaldiFile = "NGA_no_1063_RRS228.AT2";
constexpr const char* kRinaldiLabel = "Northridge 1994, Rinaldi 228";
constexpr const char* kElCentroFile = "elcentro_chopra.txt";
constexpr const char* kElCentroLabel = "Imperial Valley 1940, El Centro N-S";
constexpr RecordSpec kRecords[] = {
    {kFig6Vssw, "rinaldi", kRinaldiLabel, kRinaldiFile, 0.45},
    {kFig6Vssw, "elcentro", kElCentroLabel, kElCentroFile, 1.15},
    {kFig6Pw, "rinaldi", kRinaldiLabel, kRinaldiFile, 0.17},
    {kFig6Pw, "elcentro", kElCentroLabel, kElCentroFile, 0.5},
};
// A history runs on past the record's end until the wall is at rest (stop_at_rest), at most this long [s]: the
// Fig. 6 walls' free rocking from the amplitudes above dies out within a few seconds.
constexpr double kHistoryTail = 5.0;

// Step studies: four steps per engine spanning its default (Bullet 0.2 ms, ODE 0.2 ms, Simbody's rigid route
// 0.5 ms), so that the first-order error of each is seen falling. Simbody's default (compliant) route integrates with
// error control: its dt is the reporting interval (default 1 ms), so its study shows the sampling error only.
const std::map<std::string, std::vector<double>>& step_studies() {
    static const std::map<std::string, std::vector<double>> steps = {
        {"bullet", {1e-3, 5e-4, 2e-4, 1e-4}},
        {"ode", {2e-3, 1e-3, 5e-4, 2e-4}},
        {"simbody", {4e-3, 2e-3, 1e-3, 5e-4}},
        {"simbody-rigid", {2e-3, 1e-3, 5e-4, 2.5e-4}},
    };
    return steps;
}

// Traces: at most this many points per trace (plots), a free vibration's first seconds only.
constexpr std::size_t kMaxTracePoints = 2000;
constexpr double kFreeTraceSeconds = 10.0;

std::string fmt_number(double x) { return fmt::format("{}", x); }

// Whether the analytic model (exact kinematics) released from rest at r alpha rocks rather than falls: a heavy
// overburden with a high hinge puts the unstable equilibrium below 0.8 alpha1 (Table 1 #1, #10, #11 at xi 0.5 fall
// from 0.8 alpha1), and a wall that falls has no period or restitution to compare. Such free cases are left out.
bool rocks_from(const multibody::WallScene& scene, double r) {
    SimulationOptions options;
    options.keep_samples = false;
    return !free_vibration(*multibody::analytic_model(scene, Kinematics::exact), r * scene.alpha(), options).overturned;
}

SuiteWall table1_wall(const Specimen& s, double xi) {
    SuiteWall w;
    w.id = fmt::format("t1-{:02d}-xi{}", s.number, fmt_number(xi));
    w.label = fmt::format("Table 1 #{}, {:.2f} x {:.3f} m, h1/h {:.2f}, xi {}", s.number, s.height, s.thickness,
                          s.hinge_ratio, fmt_number(xi));
    w.scene = multibody::WallScene::of(make_vssw(s.height, s.thickness, s.hinge_ratio, xi));
    return w;
}

SuiteCase threshold_case(const std::string& wall) { return {wall, CaseKind::threshold, wall, 0.0, "", {}, ""}; }
SuiteCase free_case(const std::string& wall, double r) {
    return {fmt::format("{}/r{}", wall, fmt_number(r)), CaseKind::free, wall, r, "", {}, ""};
}
SuiteCase history_case(const std::string& wall, const std::string& record) {
    return {fmt::format("{}/{}", wall, record), CaseKind::history, wall, 0.0, record, {}, ""};
}
SuiteCase step_case(const std::string& wall, double r, double dt, const std::string& engine) {
    return {fmt::format("{}/r{}/dt{}/{}", wall, fmt_number(r), fmt_number(dt), engine),
            CaseKind::step, wall, r, "", dt, engine};
}

// Running ----------------------------------------------------------------------------------------------------------

struct TaskOutput {
    std::vector<MetricRow> rows;
    std::vector<Trace> traces;
    std::optional<std::string> failure;
    std::vector<std::string> model_warnings;  // the reference task's analytic run only (no repeats per engine)
};

MetricRow make_row(const std::string& case_id, const std::string& engine, const char* metric, double analytic,
                   double engine_value, const char* reference, const char* unit) {
    return {case_id, engine, metric, analytic, engine_value, compare_metric(analytic, engine_value).rel_error,
            reference, unit};
}

Trace make_trace(const std::string& case_id, const std::string& engine, const multibody::Trajectory& traj,
                 double alpha, double t_max) {
    Trace tr{case_id, engine, {}, {}};
    std::size_t n = 0;
    while (n < traj.samples.size() && traj.samples[n].t <= t_max) ++n;
    if (n == 0) return tr;
    const std::size_t stride = std::max<std::size_t>(1, (n + kMaxTracePoints - 2) / (kMaxTracePoints - 1));
    auto add = [&](std::size_t i) {
        tr.t.push_back(traj.samples[i].t);
        tr.theta1_over_alpha.push_back(traj.samples[i].theta1 / alpha);
    };
    for (std::size_t i = 0; i < n; i += stride) add(i);
    if ((n - 1) % stride != 0) add(n - 1);
    return tr;
}

struct PeakRotation {
    double value = kNaN, t = kNaN;  // max |theta1| [rad] and when
};
PeakRotation peak_rotation(const multibody::Trajectory& traj) {
    PeakRotation p;
    for (const auto& s : traj.samples)
        if (!(std::abs(s.theta1) <= p.value)) p = {std::abs(s.theta1), s.t};  // the first sample replaces NaN
    return p;
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

struct TaskContext {
    const SuiteCase& c;
    const SuiteWall& wall;
    const multibody::Engine& engine;
    bool reference;  // the analytic model's own rows
    const GroundMotion* record;
    bool keep_traces;
};

void threshold_task(const TaskContext& x, TaskOutput& out) {
    const AnalyticEngine analytic;
    const std::string name = x.engine.name();
    if (x.reference) {
        const double a = find_threshold(analytic, analytic.default_settings(), x.wall.scene).value_g;
        out.rows.push_back(make_row(x.c.id, name, "threshold_g", a, a, "analytic model", "g"));
        return;
    }
    const EngineSettings settings = x.engine.default_settings();
    const double a = find_threshold(analytic, analytic_reference_settings(settings), x.wall.scene).value_g;
    const double e = find_threshold(x.engine, settings, x.wall.scene).value_g;
    out.rows.push_back(make_row(x.c.id, name, "threshold_g", a, e, "analytic model", "g"));
}

void free_rows(const TaskContext& x, const FreeVibrationResult& a, const FreeVibrationResult& e, TaskOutput& out) {
    const std::string name = x.engine.name();
    out.rows.push_back(make_row(x.c.id, name, "period", a.period.value_or(kNaN), e.period.value_or(kNaN),
                                "analytic model", "s"));
    out.rows.push_back(make_row(x.c.id, name, "restitution", a.restitution.value_or(kNaN),
                                e.restitution.value_or(kNaN), "analytic model", ""));
    if (x.wall.scene.vssw) {
        const double whole = restitution_whole_mechanism(*x.wall.scene.vssw);
        // The analytic model's own row holds the closed form on both sides (its impact law is Eq. 19's).
        out.rows.push_back(make_row(x.c.id, name, "restitution_whole_mechanism", whole,
                                    x.reference ? whole : e.restitution.value_or(kNaN),
                                    "whole-mechanism plastic impact (roller acting)", ""));
    }
}

void free_task(const TaskContext& x, TaskOutput& out) {
    FreeVibrationOptions options;
    options.r = x.c.r;
    const double alpha = x.wall.scene.alpha();
    if (x.reference) {
        const AnalyticEngine analytic;
        const FreeVibrationResult a = run_free_vibration(analytic, analytic.default_settings(), x.wall.scene, options);
        free_rows(x, a, a, out);
        out.model_warnings = a.trajectory.warnings;
        if (x.keep_traces && x.c.kind == CaseKind::free)
            out.traces.push_back(make_trace(x.c.id, x.engine.name(), a.trajectory, alpha, kFreeTraceSeconds));
        return;
    }
    EngineSettings settings = x.engine.default_settings();
    if (x.c.dt) settings.dt = *x.c.dt;
    const FreeVibrationComparison runs =
        free_vibration_with_analytic(x.engine, settings, x.wall.scene, options, analytic_reference_settings(settings));
    free_rows(x, runs.analytic, runs.engine, out);
    // A first-impact ratio outside (0, 1] is a failure of the engine's run, not a restitution: the row is NaN and
    // the report lists why.
    if (!runs.engine.restitution_note.empty()) out.failure = runs.engine.restitution_note;
    if (x.keep_traces && x.c.kind == CaseKind::free)
        out.traces.push_back(make_trace(x.c.id, x.engine.name(), runs.engine.trajectory, alpha, kFreeTraceSeconds));
}

void history_rows(const TaskContext& x, const multibody::Trajectory& a, const multibody::Trajectory& e,
                  TaskOutput& out) {
    const std::string name = x.engine.name();
    const double alpha = x.wall.scene.alpha();
    const PeakRotation pa = peak_rotation(a), pe = peak_rotation(e);
    const double peak_a = pa.value / alpha;
    out.rows.push_back(
        make_row(x.c.id, name, "peak_rotation", peak_a, pe.value / alpha, "analytic model", "alpha"));
    out.rows.push_back(make_row(x.c.id, name, "peak_time", pa.t, pe.t, "analytic model", "s"));
    const double over_a = a.overturned ? 1.0 : 0.0, over_e = e.overturned ? 1.0 : 0.0;
    out.rows.push_back({x.c.id, name, "overturned", over_a, over_e, over_e - over_a, "analytic model", ""});
    const double rms = x.reference ? 0.0 : rms_difference(a, e) / alpha;
    out.rows.push_back({x.c.id, name, "rms_difference", peak_a, rms, rms / peak_a, "analytic model", "alpha"});
}

// A VSSW's peak rotation against the analytic model run with the whole mechanism's plastic impact in place of
// Eq. (19) (the impact the engines make: README "Engines"): does the impact law account for a difference in peaks?
void whole_mechanism_peak_row(const TaskContext& x, const Excitation& ex, const EngineSettings& analytic_settings,
                              const multibody::Trajectory& e, TaskOutput& out) {
    if (!x.wall.scene.vssw) return;
    EngineSettings s = analytic_settings;
    s.knobs["restitution"] = restitution_whole_mechanism(*x.wall.scene.vssw);
    const multibody::Trajectory w = AnalyticEngine().simulate(x.wall.scene, ex, s);
    const double alpha = x.wall.scene.alpha();
    const double peak_w = peak_rotation(w).value / alpha;
    const double peak_e = x.reference ? peak_w : peak_rotation(e).value / alpha;
    out.rows.push_back(make_row(x.c.id, x.engine.name(), "peak_rotation_whole_mechanism", peak_w, peak_e,
                                "analytic model with the whole-mechanism impact", "alpha"));
}

void history_task(const TaskContext& x, TaskOutput& out) {
    Excitation ex;
    ex.horizontal = *x.record;
    ex.theta0 = 0.0;
    ex.t_end = x.record->duration() + kHistoryTail;
    ex.stop_at_rest = true;
    const double alpha = x.wall.scene.alpha();
    const double all = std::numeric_limits<double>::infinity();
    const AnalyticEngine analytic;
    if (x.reference) {
        const multibody::Trajectory a = analytic.simulate(x.wall.scene, ex, analytic.default_settings());
        history_rows(x, a, a, out);
        out.model_warnings = a.warnings;
        whole_mechanism_peak_row(x, ex, analytic.default_settings(), a, out);
        if (x.keep_traces) out.traces.push_back(make_trace(x.c.id, x.engine.name(), a, alpha, all));
        return;
    }
    const EngineSettings settings = x.engine.default_settings();
    const multibody::Trajectory a = analytic.simulate(x.wall.scene, ex, analytic_reference_settings(settings));
    const multibody::Trajectory e = x.engine.simulate(x.wall.scene, ex, settings);
    history_rows(x, a, e, out);
    whole_mechanism_peak_row(x, ex, analytic_reference_settings(settings), e, out);
    if (x.keep_traces) out.traces.push_back(make_trace(x.c.id, x.engine.name(), e, alpha, all));
}

void run_task(const TaskContext& x, TaskOutput& out) {
    switch (x.c.kind) {
        case CaseKind::threshold: threshold_task(x, out); return;
        case CaseKind::free:
        case CaseKind::step: free_task(x, out); return;
        case CaseKind::history: history_task(x, out); return;
    }
}

struct Task {
    std::size_t case_index, engine_index;
    double cost;  // estimated [s], for the queue's order only
};

// Simulated seconds a task's engine runs, at its default step (the threshold: ~17 trials, those below the threshold
// run the whole hold, those above stop once the wall lifts: about half of it on average).
double simulated_seconds(const SuiteCase& c, const SuiteWall& w, const GroundMotion* record) {
    switch (c.kind) {
        case CaseKind::threshold: {
            const ThresholdOptions o;
            return 17.0 * (o.ramp_time + 0.5 * threshold_hold_time(w.scene, o));
        }
        case CaseKind::free:
        case CaseKind::step: return free_vibration_duration(w.scene, c.r * w.scene.alpha(), FreeVibrationOptions{}.impacts);
        case CaseKind::history: return record ? record->duration() + kHistoryTail : 0.0;
    }
    return 0.0;
}

}  // namespace

std::vector<std::string> metrics_of(CaseKind kind, bool vssw) {
    switch (kind) {
        case CaseKind::threshold:
            return {"threshold_g"};
        case CaseKind::free:
        case CaseKind::step:
            if (vssw) return {"period", "restitution", "restitution_whole_mechanism"};
            return {"period", "restitution"};
        case CaseKind::history:
            if (vssw) return {"peak_rotation", "peak_time", "overturned", "rms_difference",
                              "peak_rotation_whole_mechanism"};
            return {"peak_rotation", "peak_time", "overturned", "rms_difference"};
    }
    return {};
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

Suite make_suite(const std::string& name, const std::string& data_dir) {
    if (name != "default" && name != "full")
        throw InputError(fmt::format("unknown suite '{}' (valid: default, full)", name));
    const bool full = name == "full";
    Suite s;
    s.name = name;

    s.walls.push_back({kFig6Vssw, "Fig. 6 VSSW 4 x 0.4 m, h1/h 0.7",
                       multibody::WallScene::of(make_vssw(kFig6Height, kFig6Thickness, kFig6Hinge))});
    s.walls.push_back({kFig6Pw, "Fig. 6 PW 4 x 0.4 m", multibody::WallScene::of(make_parapet(kFig6Height, kFig6Thickness))});
    const std::vector<Specimen> table1 = read_table1(default_table1_path());
    std::vector<Specimen> specimens = table1;  // full: all, in the table's order
    if (!full) {
        specimens.clear();
        for (int number : kDefaultSpecimens) specimens.push_back(table1_specimen(table1, number));
    }
    for (const Specimen& sp : specimens)
        for (double xi : kOverburdens) s.walls.push_back(table1_wall(sp, xi));

    const std::string dir = data_dir.empty() ? std::string(".") : data_dir;
    for (const RecordSpec& r : kRecords) {
        const std::string id = fmt::format("{}-x{}", r.stem, fmt_number(r.scale));
        if (std::none_of(s.records.begin(), s.records.end(), [&](const SuiteRecord& x) { return x.id == id; }))
            s.records.push_back({id, fmt::format("{}, x {}", r.label, fmt_number(r.scale)), dir + "/" + r.file,
                                 r.scale});
    }

    for (const SuiteWall& w : s.walls) s.cases.push_back(threshold_case(w.id));
    for (const SuiteWall& w : s.walls) {
        const bool fig6 = w.id == kFig6Vssw || w.id == kFig6Pw;
        std::vector<double> releases(std::begin(kReleases), std::end(kReleases));
        if (!fig6 && !full) releases = {kDefaultTable1Release};
        for (double r : releases)
            if (rocks_from(w.scene, r)) s.cases.push_back(free_case(w.id, r));
    }
    for (const RecordSpec& r : kRecords)
        s.cases.push_back(history_case(r.wall_id, fmt::format("{}-x{}", r.stem, fmt_number(r.scale))));

    std::vector<std::string> step_walls = {kFig6Vssw};
    if (full) step_walls.push_back(kFig6Pw);
    for (const auto& [engine, dts] : step_studies()) {
        s.step_study[engine] = dts;
        for (const std::string& w : step_walls)
            for (double dt : dts) s.cases.push_back(step_case(w, kStepStudyRelease, dt, engine));
    }
    return s;
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

SuiteResults run_suite_with_engines(const Suite& suite, const std::vector<const multibody::Engine*>& given,
                                    const RunOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    require(options.threads >= 0, "threads", ">= 0 (0: the available cores)", options.threads);

    const AnalyticEngine reference_engine;
    std::vector<const multibody::Engine*> engines = {&reference_engine};
    for (const multibody::Engine* e : given) {
        if (e == nullptr) throw InputError("run_suite: a null engine");
        const std::string name = e->name();
        if (name == kReferenceEngine) continue;
        if (std::any_of(engines.begin(), engines.end(), [&](const auto* x) { return x->name() == name; }))
            throw InputError(fmt::format("run_suite: engine '{}' given twice", name));
        engines.push_back(e);
    }

    SuiteResults results;
    results.suite = suite.name;
    for (const multibody::Engine* e : engines)
        results.engines.push_back({e->name(), e->version(), e->default_settings()});

    // Walls and records up front: a bad suite is an InputError before anything runs.
    std::vector<const SuiteWall*> case_walls;
    std::map<std::string, GroundMotion> records;
    for (const SuiteCase& c : suite.cases) {
        case_walls.push_back(&suite.wall(c.wall_id));
        if (c.kind == CaseKind::history && !records.count(c.record_id)) {
            const SuiteRecord& r = suite.record(c.record_id);
            records.emplace(r.id, read_record(r.path).scaled(r.scale));
        }
        if (c.kind == CaseKind::step && !c.dt)
            throw InputError(fmt::format("step case '{}' has no step dt", c.id));
    }

    // Tasks in (case, engine) order: their outputs are assembled in this order whatever the threads did.
    std::vector<Task> tasks;
    for (std::size_t ci = 0; ci < suite.cases.size(); ++ci) {
        const SuiteCase& c = suite.cases[ci];
        const GroundMotion* record = c.kind == CaseKind::history ? &records.at(c.record_id) : nullptr;
        const double seconds = simulated_seconds(c, *case_walls[ci], record);
        for (std::size_t ei = 0; ei < engines.size(); ++ei) {
            const std::string name = engines[ei]->name();
            if (!c.engine.empty() && c.engine != name) continue;
            double cost = seconds * cost_per_simulated_second(name);
            if (c.dt && *c.dt > 0.0) cost *= engines[ei]->default_settings().dt / *c.dt;
            tasks.push_back({ci, ei, cost});
        }
    }
    std::vector<TaskOutput> outputs(tasks.size());

    std::vector<PoolTask> pool_tasks;
    for (const Task& t : tasks) pool_tasks.push_back({t.cost, t.engine_index});
    std::vector<bool> exclusive;
    for (const multibody::Engine* e : engines) exclusive.push_back(!e->runs_concurrently());

    std::mutex progress_mutex;
    int done = 0;
    const int total = static_cast<int>(tasks.size());
    results.threads = run_pool(pool_tasks, exclusive, options.threads, [&](std::size_t ti) {
        const Task& task = tasks[ti];
        const SuiteCase& c = suite.cases[task.case_index];
        const multibody::Engine& engine = *engines[task.engine_index];
        try {
            const TaskContext x{c, *case_walls[task.case_index], engine, task.engine_index == 0,
                                c.kind == CaseKind::history ? &records.at(c.record_id) : nullptr, options.keep_traces};
            run_task(x, outputs[ti]);
        } catch (const EngineFailure& e) {
            outputs[ti] = TaskOutput{};
            outputs[ti].failure = e.what();
        }
        if (options.progress) {
            const std::lock_guard<std::mutex> lock(progress_mutex);
            ++done;
            options.progress(done, total,
                             fmt::format("{} {}{}", c.id, engine.name(), outputs[ti].failure ? " (failed)" : ""));
        }
    });

    for (std::size_t ti = 0; ti < tasks.size(); ++ti) {
        TaskOutput& o = outputs[ti];
        const std::string& case_id = suite.cases[tasks[ti].case_index].id;
        if (o.failure) results.failures.push_back({case_id, engines[tasks[ti].engine_index]->name(), *o.failure});
        for (std::string& w : o.model_warnings) results.model_warnings.push_back({case_id, std::move(w)});
        for (MetricRow& r : o.rows) results.rows.push_back(std::move(r));
        for (Trace& t : o.traces) results.traces.push_back(std::move(t));
    }
    results.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return results;
}

}  // namespace vssw::compare

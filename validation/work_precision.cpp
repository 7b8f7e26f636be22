#include "validation/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/specimens.hpp"
#include "compare/experiments.hpp"
#include "compare/metrics.hpp"
#include "compare/response.hpp"
#include "compare/targets.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "validation/bench_spec.hpp"

namespace vssw::validation {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The Fig. 6 walls (4 x 0.4 m; the VSSW's hinge at h1/h 0.7), the validation suite's.
constexpr double kFig6Height = 4.0, kFig6Thickness = 0.4, kFig6Hinge = 0.7;
// Table 1 #1 at xi 0.5: one of the walls on which Bullet's restitution misses its target at its defaults
// (docs/contributing/engines.md "Bullet").
constexpr int kTable1Specimen = 1;
constexpr double kTable1Xi = 0.5;
// Release of the free vibrations, in units of alpha: the suite's middle release.
constexpr double kRelease = 0.5;
// The record problem: Rinaldi 228 scaled by 0.45 on the Fig. 6 VSSW, the validation suite's scale (the middle of the
// band that rocks the analytic wall without overturning it).
constexpr double kRecordScale = 0.45;

multibody::WallScene fig6_vssw() {
    return multibody::WallScene::of(make_vssw(kFig6Height, kFig6Thickness, kFig6Hinge));
}

multibody::WallScene problem_scene(const std::string& problem) {
    if (problem == "pw-free") return multibody::WallScene::of(make_parapet(kFig6Height, kFig6Thickness));
    if (problem == "t1-free") {
        const std::vector<Specimen> table = read_table1(default_table1_path());
        return multibody::WallScene::of(make_vssw(table1_specimen(table, kTable1Specimen), kTable1Xi));
    }
    return fig6_vssw();
}

// The analytic model at its defaults (the set `mechanism`: what the engines are measured against) and this tolerance.
multibody::EngineSettings analytic_at(double rtol) {
    multibody::EngineSettings s = multibody::AnalyticEngine{}.default_settings();
    s.knobs["rtol"] = rtol;
    return s;
}

// |value / reference - 1| (compare_metric's error, unsigned); NaN unless both are finite and the reference is not 0.
double relative_error(double value, double reference) {
    if (!std::isfinite(value) || !std::isfinite(reference) || reference == 0.0) return kNaN;
    return std::abs(compare::compare_metric(reference, value).rel_error);
}

// The peak_rotation [alpha] of a run from rest under the record, as the report and a study measure it
// (compare/response.hpp).
double peak_over_alpha1(const multibody::Trajectory& traj, const multibody::WallScene& scene) {
    return compare::response_of(traj, scene).peak / scene.alpha();
}

multibody::Excitation record_excitation(const std::string& record_path) {
    multibody::Excitation e;
    e.horizontal = read_record(record_path).scaled(kRecordScale);
    e.t_end = e.horizontal.duration() + compare::kResponseTail;
    e.motion_only = true;  // the peak is read from theta1 alone
    return e;
}

// One problem as the sweep runs it, prepared once per bench before any point is timed: its wall, the record's
// excitation (read and parsed here, not inside a timed run) and its converged references by metric: the analytic
// model's under the set `mechanism`, what every backend, the analytic model at its defaults included, is measured
// against.
struct Problem {
    std::string name;
    multibody::WallScene scene;
    multibody::Excitation record;  // the record problem's only
    std::map<std::string, double> refs;
};

Problem prepare_problem(const std::string& name, const BenchOptions& options) {
    Problem p{name, problem_scene(name), {}, {}};
    const multibody::AnalyticEngine analytic;
    if (name == "threshold") {
        const double closed = eq12_threshold(*p.scene.vssw) / p.scene.vssw->g;  // Eq. (12)
        p.refs["threshold"] = closed;
    } else if (name == "record") {
        p.record = record_excitation(options.record_path);
        p.refs["peak"] = peak_over_alpha1(analytic.simulate(p.scene, p.record, analytic_at(kReferenceRtol)), p.scene);
    } else {
        compare::FreeVibrationOptions free;
        free.r = kRelease;
        const compare::FreeVibrationResult ref = compare::run_free_vibration(analytic, analytic_at(kReferenceRtol), p.scene, free);
        p.refs["period"] = ref.period.value_or(kNaN);
        p.refs["restitution"] = p.scene.is_vssw() ? restitution_whole_mechanism(*p.scene.vssw)
                                                  : housner_restitution(p.scene.parapet->alpha);
    }
    require_measured_references(name, p.refs);
    return p;
}

// One experiment at one setting: the metric values by name (NaN when not measured).
std::map<std::string, double> run_problem(const Problem& problem, const multibody::Engine& engine,
                                          const multibody::EngineSettings& settings) {
    if (problem.name == "threshold") return {{"threshold", compare::find_threshold(engine, settings, problem.scene).value_g}};
    if (problem.name == "record")
        return {{"peak",
                 peak_over_alpha1(engine.simulate(problem.scene, problem.record, settings), problem.scene)}};
    compare::FreeVibrationOptions free;
    free.r = kRelease;
    const compare::FreeVibrationResult run = compare::run_free_vibration(engine, settings, problem.scene, free);
    return {{"period", run.period.value_or(kNaN)}, {"restitution", run.restitution.value_or(kNaN)}};
}

}  // namespace

double process_cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double median_of(std::vector<double> values) {
    if (values.empty()) return kNaN;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

CpuTiming time_cpu(const std::function<void()>& run, int repeats) {
    require(repeats >= 1, "repeats", ">= 1", repeats);
    CpuTiming t;
    for (int i = 0; i < repeats; ++i) {
        const double start = process_cpu_seconds();
        run();
        t.repeats.push_back(process_cpu_seconds() - start);
    }
    t.median = median_of(t.repeats);
    const auto [lo, hi] = std::minmax_element(t.repeats.begin(), t.repeats.end());
    t.noise = t.median > 0.0 ? (*hi - *lo) / t.median : 0.0;
    return t;
}

std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error) {
    require(cost.size() == error.size(), "pareto_front sizes", "equal", static_cast<double>(error.size()));
    const std::size_t n = cost.size();
    auto usable = [&](std::size_t i) { return std::isfinite(cost[i]) && std::isfinite(error[i]); };
    std::vector<bool> front(n, false);
    for (std::size_t i = 0; i < n; ++i) {
        if (!usable(i)) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < n && !dominated; ++j)
            dominated = j != i && usable(j) && cost[j] <= cost[i] && error[j] <= error[i] &&
                        (cost[j] < cost[i] || error[j] < error[i]);
        front[i] = !dominated;
    }
    return front;
}

std::vector<BenchSetting> bench_sweep(const multibody::Engine& engine, bool quick) {
    const std::string name = engine.name();
    std::vector<BenchSetting> sweep;
    const multibody::EngineSettings defaults = engine.default_settings();
    if (name == "analytic") {
        const std::vector<double> rtols =
            quick ? std::vector<double>{1e-6, 1e-10} : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
        for (double rtol : rtols) sweep.push_back({"rtol=" + sci(rtol), analytic_at(rtol)});
        return sweep;
    }
    if (quick) return {{"defaults", defaults}};  // known to work: the CTest checks the files, not the engines
    // Each engine's sweep is a fact of its folder (the BENCH lines of its engine.cmake); a stepped engine that
    // states none sweeps its step.
    const std::string_view spec = bench_spec_of(name);
    sweep = expand_bench_spec(defaults, spec.empty() ? "dt={dt}: dt 2e-3 1e-3 5e-4 2.5e-4" : spec);
    for (const BenchSetting& s : sweep) engine.check_settings(s.settings);
    return sweep;
}

std::vector<std::string> bench_problem_names() { return {"threshold", "fig6-free", "t1-free", "pw-free", "record"}; }

std::vector<std::string> default_bench_problems(bool quick) {
    if (quick) return {"fig6-free", "pw-free"};
    return bench_problem_names();
}

void check_bench_problem(const std::string& name) {
    const std::vector<std::string> known = bench_problem_names();
    if (std::find(known.begin(), known.end(), name) == known.end())
        throw InputError(fmt::format("--problems: unknown problem '{}' (known: {})", name, fmt::join(known, ", ")));
}

std::vector<std::string> bench_problem_metrics(const std::string& problem) {
    if (problem == "threshold") return {"threshold"};
    if (problem == "record") return {"peak"};
    return {"period", "restitution"};
}

std::optional<double> bench_target(const std::string& metric) {
    if (metric == "threshold") return compare::kThresholdTarget;
    if (metric == "period") return compare::kPeriodTarget;
    if (metric == "restitution") return compare::kRestitutionTarget;
    return std::nullopt;
}

void require_measured_references(const std::string& problem, const std::map<std::string, double>& by_metric) {
    for (const auto& [metric, value] : by_metric)
        if (!std::isfinite(value))
            throw multibody::EngineFailure(fmt::format(
                "the converged analytic reference of problem '{}' has no {} (rtol {:g}): none of its points can be "
                "measured",
                problem, metric, kReferenceRtol));
}

std::vector<BenchPoint> run_bench(const BenchOptions& options, const std::function<void(const BenchPoint&)>& progress) {
    require(options.repeats >= 1, "--repeats", "a whole number >= 1", options.repeats);
    for (const std::string& p : options.problems) check_bench_problem(p);
    // Every problem's references first: one that cannot be measured ends the bench before minutes of sweeps are run.
    std::vector<Problem> problems;
    for (const std::string& name : options.problems) problems.push_back(prepare_problem(name, options));
    std::vector<BenchPoint> points;
    for (const Problem& problem : problems) {
        for (const std::string& engine_name : options.engines) {
            // In this process: a point's cost is this process's CPU time (a child's would not be counted). The sweep's
            // settings are the program's own, never the user's, so no setting of the user's reaches the library here.
            const std::unique_ptr<multibody::Engine> engine = multibody::make_engine_in_process(engine_name);
            for (const BenchSetting& setting : bench_sweep(*engine, options.quick)) {
                std::map<std::string, double> values;
                std::string failure;
                const CpuTiming cpu = time_cpu(
                    [&] {
                        try {
                            values = run_problem(problem, *engine, setting.settings);
                        } catch (const multibody::EngineFailure& e) {
                            failure = e.what();
                        }
                    },
                    options.repeats);
                for (const std::string& metric : bench_problem_metrics(problem.name)) {
                    BenchPoint p{engine_name, problem.name, metric, setting.label, setting.settings, cpu,
                                 kNaN, kNaN, kNaN, failure};
                    p.reference = problem.refs.at(metric);
                    if (failure.empty()) {
                        p.value = values.count(metric) ? values.at(metric) : kNaN;
                        p.error = relative_error(p.value, p.reference);
                        if (!std::isfinite(p.error)) p.failure = "not measured";
                    }
                    points.push_back(p);
                    if (progress) progress(points.back());
                }
            }
        }
    }
    return points;
}

std::vector<Cheapest> cheapest_within_targets(const std::vector<BenchPoint>& points,
                                              const std::vector<std::string>& engines) {
    std::vector<Cheapest> out;
    for (const std::string& engine : engines) {
        Cheapest c{engine, std::nullopt, 0.0, {}};
        // Settings in sweep order; whether each meets every target, and its CPU summed once per problem.
        std::vector<std::string> settings;
        std::map<std::string, bool> ok;
        std::map<std::string, std::map<std::string, double>> cpu;  // setting -> problem -> median
        std::vector<std::string> keys;                              // problem/metric with a target, in order
        for (const BenchPoint& p : points) {
            if (p.engine != engine) continue;
            if (!ok.count(p.setting)) settings.push_back(p.setting), ok[p.setting] = true;
            cpu[p.setting][p.problem] = p.cpu.median;
            const std::optional<double> target = bench_target(p.metric);
            if (!p.failure.empty()) ok[p.setting] = false;
            if (!target) continue;
            if (!(p.error <= *target)) ok[p.setting] = false;
            const std::string key = p.problem + "/" + p.metric;
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
        }
        for (const std::string& s : settings) {
            // Without a metric with a target (only the record's peak was run) no setting is "within every target".
            if (!ok[s] || keys.empty()) continue;
            double total = 0.0;
            for (const auto& [problem, median] : cpu[s]) total += median;
            if (!c.setting || total < c.cpu_s) c.setting = s, c.cpu_s = total;
        }
        for (const std::string& key : keys) {
            std::optional<std::size_t> best;
            for (std::size_t i = 0; i < points.size(); ++i) {
                const BenchPoint& p = points[i];
                if (p.engine != engine || p.problem + "/" + p.metric != key) continue;
                if (!(p.error <= *bench_target(p.metric))) continue;
                if (!best || p.cpu.median < points[*best].cpu.median) best = i;
            }
            c.per_metric.emplace_back(key, best);
        }
        out.push_back(c);
    }
    return out;
}

}  // namespace vssw::validation

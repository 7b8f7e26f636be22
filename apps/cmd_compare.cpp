// `vssw compare`: one engine against the analytic model (exact kinematics) on threshold, period and restitution,
// every metric measured from both trajectories by the same code (compare/).
#include <chrono>
#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "apps/commands.hpp"
#include "apps/option_values.hpp"
#include "apps/simulation_failure.hpp"
#include "apps/table.hpp"
#include "apps/wall_options.hpp"
#include "compare/experiments.hpp"
#include "compare/targets.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {
namespace {

using compare::kPeriodTarget;  // compare/targets.hpp
using compare::kRestitutionTarget;
using compare::kThresholdTarget;

// Smallest release, in units of alpha, that compare measures: the threshold's lift criterion (ThresholdOptions::
// lift_angle). Below it an engine's elastic rotation on its contacts (~1e-6 rad) and its step are no longer small
// against the motion (at 1e-4 alpha the Fig. 6 wall's whole period is 18 ms), and at 1e-6 alpha the analytic model
// comes to rest without an impact to measure.
constexpr double kMinRelease = 0.01;

struct CompareOptions {
    WallOptions wall;
    ModelOptions model;
    std::string engine;
    double theta0 = 0.5;
    std::optional<double> dt;
    std::optional<std::string> iterations;  // as typed, checked by parse_bounded_int
    std::vector<std::string> knobs;  // NAME=VALUE
    bool json = false;
};

multibody::EngineSettings settings_of(const multibody::Engine& engine, const CompareOptions& o) {
    multibody::EngineSettings s = engine.default_settings();
    if (o.dt) s.dt = *o.dt;
    require(std::isfinite(s.dt) && s.dt > 0.0, "--dt (engine step, s)", "a positive finite number", s.dt);
    if (o.iterations) {
        s.iterations = parse_bounded_int("--iterations", *o.iterations, 1, kMaxIterations);
    }
    for (const std::string& kv : o.knobs) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError(fmt::format("--set takes NAME=VALUE, got '{}'", kv));
        const std::string value = kv.substr(eq + 1);
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(v))
            throw InputError(fmt::format("--set {}: '{}' is not a finite number", kv.substr(0, eq), value));
        s.knobs[kv.substr(0, eq)] = v;
    }
    return s;
}

Json metric_json(const compare::MetricComparison& m, double target) {
    return {{"analytic", finite_or_null(m.analytic)},
            {"engine", finite_or_null(m.engine)},
            {"rel_error", finite_or_null(m.rel_error)},
            {"target", target},
            {"within_target", std::isfinite(m.rel_error) && std::abs(m.rel_error) <= target}};
}

std::string verdict(const compare::MetricComparison& m, double target) {
    if (!std::isfinite(m.rel_error)) return "not measured";
    return std::abs(m.rel_error) <= target ? "within target" : fmt::format("OUTSIDE {:.1f} %", 100.0 * target);
}

// A comparison with a metric that could not be measured (on either side) is not a result: the output above shows
// what was measured and why the rest was not, and the exit code is 3, as for an engine that fails outright.
void throw_if_incomplete(const compare::EngineComparison& c) {
    if (c.failures.empty()) return;
    throw SimulationFailure(fmt::format("{} metric{} not measured: {}", c.failures.size(),
                                        c.failures.size() == 1 ? "" : "s", fmt::join(c.failures, "; ")));
}

}  // namespace

Command add_compare_command(CLI::App& root) {
    auto o = std::make_shared<CompareOptions>();
    CLI::App* cmd = root.add_subcommand(
        "compare", "One engine against the analytic model (exact kinematics): threshold, period, restitution");
    cmd->add_option("--engine", o->engine,
                    fmt::format("backend to compare (available: {}) (required)",
                                fmt::join(multibody::available_engines(), ", ")))
        ->required();
    add_model_options(*cmd, o->model);
    add_wall_options(*cmd, o->wall, true);
    cmd->add_option("--theta0", o->theta0,
                    fmt::format("release from rest at theta0 = r * alpha for the period and restitution, r from {:g} to below 1 "
                                "(default 0.5)",
                                kMinRelease));
    cmd->add_option("--dt", o->dt, "engine step [s] (default: the engine's own, see the README)");
    cmd->add_option("--iterations", o->iterations,
                    fmt::format("solver iterations, 1 to {} (default: the engine's own)", kMaxIterations));
    cmd->add_option("--set", o->knobs, "engine setting NAME=VALUE (repeatable; each adapter lists its own)");
    cmd->add_flag("--json", o->json, "print JSON instead of a table");
    cmd->footer(
        "The threshold (in g) is the smallest constant ground acceleration that lifts the wall off rest, by bisection\n"
        "to 1e-4; the period is 4x the time from release at theta0 to the first impact; the restitution is the ratio\n"
        "of theta1' after and before the first impact. rel_error = engine / analytic - 1; targets 0.5 %, 0.5 %, 2 %.\n"
        "JSON keys: engine, version, threshold, period, restitution, restitution_amplitude (each {analytic, engine,\n"
        "rel_error, target, within_target}), closed_forms {threshold_g, restitution, restitution_whole_mechanism,\n"
        "period_linearised}, theta0, settings {dt, iterations, knobs}, wall_time_s, failures, wall {...}.\n"
        "failures: why a metric is null (e.g. an engine's first-impact ratio outside (0, 1]).\n"
        "analytic_warnings: the analytic model's own assumptions failing along its free vibration (e.g. a roller\n"
        "that would have to pull): its values are the model's, but the model may not hold there.\n"
        "Exit 3 when the engine fails (NaN, sliding, ...) or a metric could not be measured (the output is printed).");
    return {cmd, [o](std::ostream& out) {
                const WallKind kind = parse_wall_kind(o->model.model);
                const multibody::WallScene scene = kind == WallKind::vssw
                                                       ? multibody::WallScene::of(vssw_geometry(o->wall))
                                                       : multibody::WallScene::of(parapet_geometry(o->wall));
                const std::unique_ptr<multibody::Engine> engine = multibody::make_engine(o->engine);
                const multibody::EngineSettings settings = settings_of(*engine, *o);
                require(std::isfinite(o->theta0) && o->theta0 >= kMinRelease && o->theta0 < 1.0, "--theta0",
                        fmt::format("from {:g} to below 1 (a fraction of alpha)", kMinRelease), o->theta0);
                const auto start = std::chrono::steady_clock::now();
                compare::EngineComparison c;
                try {
                    c = compare::compare_with_analytic(*engine, settings, scene, o->theta0);
                } catch (const multibody::EngineFailure& e) {
                    throw SimulationFailure(e.what());
                }
                const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                // What an engine's impact should give: every constraint of the new mechanism acting at once.
                const double whole = scene.vssw ? restitution_whole_mechanism(*scene.vssw)
                                                : housner_restitution(scene.parapet->alpha);
                if (o->json) {
                    Json knobs = Json::object();
                    for (const auto& [k, v] : settings.knobs) knobs[k] = v;
                    const Json j = {
                        {"engine", engine->name()},
                        {"version", engine->version()},
                        {"threshold", metric_json(c.threshold_g, kThresholdTarget)},
                        {"period", metric_json(c.period, kPeriodTarget)},
                        {"restitution", metric_json(c.restitution, kRestitutionTarget)},
                        {"restitution_amplitude", metric_json(c.restitution_amplitude, kRestitutionTarget)},
                        {"closed_forms",
                         {{"threshold_g", finite_or_null(c.threshold_closed_form_g)},
                          {"restitution", finite_or_null(c.restitution_closed_form)},
                          {"restitution_whole_mechanism", whole},
                          {"period_linearised", finite_or_null(c.period_linearised)}}},
                        {"theta0", o->theta0},
                        {"settings", {{"dt", settings.dt}, {"iterations", settings.iterations}, {"knobs", knobs}}},
                        {"wall_time_s", seconds},
                        {"failures", c.failures},
                        {"analytic_warnings", c.analytic_warnings},
                        {"wall", wall_inputs_json(o->wall, kind)}};
                    out << j.dump(2) << '\n';
                    throw_if_incomplete(c);
                    return;
                }
                Table t(fmt::format("{} against the analytic model (exact kinematics), {}", engine->version(),
                                    describe_wall(o->wall, kind)));
                t.text("settings", fmt::format("dt {} s, iterations {}, release at theta0 = {} alpha", settings.dt,
                                               settings.iterations, o->theta0));
                auto row = [&](const char* name, const compare::MetricComparison& m, const char* unit, double target) {
                    t.add(name, fmt::format("{} / {}", num(m.analytic), num(m.engine)), unit,
                          fmt::format("analytic / engine, rel. error {:+.2e}: {}", m.rel_error, verdict(m, target)));
                };
                row("threshold", c.threshold_g, "g", kThresholdTarget);
                row("period", c.period, "s", kPeriodTarget);
                row("restitution (first impact)", c.restitution, "", kRestitutionTarget);
                row("restitution (from peaks)", c.restitution_amplitude, "", kRestitutionTarget);
                t.add("closed forms", fmt::format("{} g, e = {}", num(c.threshold_closed_form_g),
                                                  num(c.restitution_closed_form)),
                      "", "Eq. (12)/(17) threshold, Eq. (19)/Housner restitution");
                t.add("restitution, whole mechanism", num(whole), "",
                      fmt::format("plastic impact with the roller acting (README); engine / this - 1 = {:+.2e}",
                                  c.restitution.engine / whole - 1.0));
                t.add("wall time", fmt::format("{:.1f}", seconds), "s");
                for (const std::string& f : c.failures) t.text("not measured", f);
                for (const std::string& w : c.analytic_warnings) t.text("analytic model warns", w);
                t.print(out);
                throw_if_incomplete(c);
            }};
}

}  // namespace vssw::cli

#include "cli/compare_output.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "cli/friction_option.hpp"
#include "cli/table.hpp"
#include "compare/targets.hpp"

namespace vssw::cli {
namespace {

using compare::kPeriodTarget;  // compare/targets.hpp
using compare::kRestitutionTarget;
using compare::kThresholdTarget;

io::Json metric_json(const compare::MetricComparison& m, double target) {
    return {{"analytic", io::finite_or_null(m.analytic)},
            {"engine", io::finite_or_null(m.engine)},
            {"rel_error", io::finite_or_null(m.rel_error)},
            {"target", target},
            {"within_target", std::isfinite(m.rel_error) && std::abs(m.rel_error) <= target}};
}

std::string verdict(const compare::MetricComparison& m, double target) {
    if (!std::isfinite(m.rel_error)) return "not measured";
    return std::abs(m.rel_error) <= target ? "within target" : fmt::format("OUTSIDE {:.1f} %", 100.0 * target);
}

// "mechanism: exact kinematics, impact whole-mechanism, unilateral roller" (a parapet: "mechanism: impact ...").
std::string describe_model(const CompareReference& r) {
    const std::string impact = "impact " + to_string(r.impact);
    if (!r.kinematics) return r.set_name + ": " + impact;
    return fmt::format("{}: {} kinematics, {}, {} roller", r.set_name, to_string(*r.kinematics), impact,
                       r.roller ? to_string(*r.roller) : "no");
}

}  // namespace

io::Json analytic_model_json(const CompareReference& r) {
    return {{"assumptions", r.set_name},
            {"kinematics", r.kinematics ? io::Json(to_string(*r.kinematics)) : io::Json(nullptr)},
            {"impact", to_string(r.impact)},
            {"roller", r.roller ? io::Json(to_string(*r.roller)) : io::Json(nullptr)}};
}

io::Json to_json(const EngineCompareRun& run, const CompareReference& r) {
    const compare::EngineComparison& c = run.comparison;
    io::Json knobs = io::Json::object();
    for (const auto& [k, v] : run.settings.knobs) knobs[k] = v;
    io::Json j = {{"engine", run.engine},
            {"version", run.version},
            {"analytic_model", analytic_model_json(r)},
            {"threshold", metric_json(c.threshold_g, kThresholdTarget)},
            {"period", metric_json(c.period, kPeriodTarget)},
            {"restitution", metric_json(c.restitution, kRestitutionTarget)},
            {"restitution_amplitude", metric_json(c.restitution_amplitude, kRestitutionTarget)},
            {"closed_forms",
             {{"threshold_g", io::finite_or_null(c.threshold_closed_form_g)},
              {"restitution", io::finite_or_null(c.restitution_closed_form)},
              {"restitution_whole_mechanism", r.restitution_whole_mechanism},
              {"period_linearised", io::finite_or_null(c.period_linearised)}}},
            {"theta0", r.theta0},
            {"settings", {{"dt", run.settings.dt}, {"iterations", run.settings.iterations}, {"knobs", knobs}}},
            {"wall_time_s", run.seconds},
            {"failures", c.failures},
            {"analytic_warnings", c.analytic_warnings},
            {"wall", wall_inputs_json(r.wall, r.kind)}};
    // With --friction: the engine's slips along its free vibration (friction_option.hpp).
    if (c.free_vibration_slip) j["free_vibration_slip"] = slip_json(*c.free_vibration_slip, r.kind == WallKind::vssw);
    return j;
}

io::Json to_json(const std::vector<EngineCompareRun>& runs, const CompareReference& reference, double seconds) {
    io::Json comparisons = io::Json::array(), failed = io::Json::array();
    for (const EngineCompareRun& run : runs) {
        if (run.failure.empty()) comparisons.push_back(to_json(run, reference));
        else failed.push_back({{"engine", run.engine}, {"version", run.version}, {"message", run.failure}});
    }
    return {{"comparisons", comparisons}, {"engine_failures", failed}, {"wall_time_s", seconds}};
}

void print_compare(std::ostream& out, const EngineCompareRun& run, const CompareReference& r) {
    Table t(fmt::format("{} against the analytic model ({}), {}", run.version, describe_model(r),
                        describe_wall(r.wall, r.kind)));
    if (!run.failure.empty()) {
        t.text("simulation failed", run.failure);
        t.print(out);
        return;
    }
    const compare::EngineComparison& c = run.comparison;
    t.text("settings", fmt::format("dt {} s, iterations {}, release at theta0 = {} alpha1", run.settings.dt,
                                   run.settings.iterations, r.theta0));
    auto row = [&](const char* name, const compare::MetricComparison& m, const char* unit, double target) {
        t.add(name, fmt::format("{} / {}", io::num(m.analytic), io::num(m.engine)), unit,
              fmt::format("analytic / engine, rel. error {:+.2e}: {}", m.rel_error, verdict(m, target)));
    };
    row("threshold", c.threshold_g, "g", kThresholdTarget);
    row("period", c.period, "s", kPeriodTarget);
    row("restitution (first impact)", c.restitution, "", kRestitutionTarget);
    row("restitution (from peaks)", c.restitution_amplitude, "", kRestitutionTarget);
    t.add("closed forms", fmt::format("{} g, e = {}", io::num(c.threshold_closed_form_g), io::num(c.restitution_closed_form)),
          "", fmt::format("Eq. ({}{}) threshold{}, Eq. (19)/Housner restitution", r.kind == WallKind::vssw ? "12" : "17",
                          r.wall.eccentricity != 0.0 ? "e" : "",
                          r.wall.eccentricity != 0.0 ? " (N off the centre: the lower side)" : ""));
    t.add("restitution, whole mechanism", io::num(r.restitution_whole_mechanism), "",
          fmt::format("plastic impact with the roller acting (docs/measurements/findings.md); engine / this - 1 = {:+.2e}",
                      c.restitution.engine / r.restitution_whole_mechanism - 1.0));
    t.add("wall time", fmt::format("{:.1f}", run.seconds), "s");
    for (const std::string& f : c.failures) t.text("not measured", f);
    for (const std::string& w : c.analytic_warnings) t.text("analytic model warns", w);
    if (const auto& s = c.free_vibration_slip)
        t.text("slip (free vibration)", fmt::format("base {:.3g} b, hinge {:.3g} b (largest){}", s->base_largest / s->b,
                                                    s->hinge_largest / s->b, s->slid_off ? ": " + *s->slid_off : ""));
    t.print(out);
}

// A comparison with a metric that could not be measured (on either side) is not a result: the output shows what was
// measured and why the rest was not, and the exit code is 3, as for an engine that fails outright.
std::string incomplete(const EngineCompareRun& run) {
    if (!run.failure.empty()) return run.failure;
    const std::vector<std::string>& f = run.comparison.failures;
    if (f.empty()) return "";
    return fmt::format("{} metric{} not measured: {}", f.size(), f.size() == 1 ? "" : "s", fmt::join(f, "; "));
}

}  // namespace vssw::cli

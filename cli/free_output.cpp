#include "cli/free_output.hpp"

#include "analytic/closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "cli/model_validity.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/table.hpp"

namespace vssw::cli {

std::optional<double> FreeRun::stop_time() const {
    if (result.overturned || result.rest_times.empty()) return std::nullopt;
    return result.rest_times.back();
}

std::optional<double> FreeRun::first_impact() const {
    if (result.impacts.empty()) return std::nullopt;
    return result.impacts.front().t;
}

FreeRun run_free(const WallOptions& wall, const ModelOptions& model, const FreeRequest& request) {
    const double r = request.theta0_over_alpha;
    require(std::isfinite(r) && r != 0.0, "theta0/alpha1 (--theta0)", "a finite nonzero number", r);
    ChosenModel chosen = choose_model(wall, model);
    const double alpha = chosen.model->reference_angle();

    SimulationOptions options;
    options.step.rtol = request.rtol;
    options.keep_samples = request.keep_trajectory;  // the tables need events only
    require(std::isfinite(request.output_dt) && request.output_dt > 0.0, "output interval (--output-dt) [s]",
            "a positive finite number", request.output_dt);
    if (request.keep_trajectory) options.output_dt = request.output_dt;
    options.roller = chosen.roller();
    try {
        validate(options);
    } catch (const InputError& e) {
        // validate() names the setting first; say which command-line option it came from (the output interval's
        // bound was once reported as --rtol's).
        const std::string what = e.what();
        throw InputError(fmt::format("{}: {}", what.rfind("output interval", 0) == 0 ? "--output-dt" : "--rtol", what));
    }
    SimulationResult result = run_simulation([&] {
        try {
            return free_vibration(*chosen.model, r * alpha, options);
        } catch (const InputError& e) {
            // The library names the rotation in rad; say which command-line value it came from.
            throw InputError(fmt::format("--theta0 {} (theta0 = {:.6g} rad): {}", r, r * alpha, e.what()));
        }
    });
    // free_vibration() runs until the wall stops or overturns (its end time is far beyond either); a run that did
    // neither has failed, whatever the integrator says.
    std::vector<std::string> warnings = validity_warnings(chosen, result);
    if (!result.overturned && result.rest_times.empty())
        throw SimulationFailure(
            fmt::format("free vibration from --theta0 {} neither came to rest nor overturned "
                        "(the run ended at t = {} s after {} impacts){}",
                        r, result.t_final, result.impacts.size(), warnings.empty() ? "" : "; " + warnings.front()));
    const ImpactLaw impact = chosen.impact();
    const double restitution = chosen.model->restitution();
    return {wall,   chosen.kind, chosen.kinematics(), r, alpha, std::move(result), std::move(warnings), impact,
            restitution, chosen.roller(), chosen.set_name(), std::move(chosen.model)};
}

io::Json to_json(const FreeRun& run) {
    const SimulationResult& res = run.result;
    io::Json impacts = io::Json::array();
    for (const Impact& i : res.impacts)
        impacts.push_back(
            {{"t", i.t}, {"theta_dot_before", i.theta_dot_before}, {"theta_dot_after", i.theta_dot_after}});
    io::Json peaks = io::Json::array(), peak_times = io::Json::array();
    for (const TurningPoint& p : res.peaks) {
        peaks.push_back(std::abs(p.theta) / run.alpha);
        peak_times.push_back(p.t);
    }
    io::Json j;
    j["model"] = to_string(run.kind);
    j["assumptions"] = run.set_name;
    j["kinematics"] = run.kinematics ? io::Json(to_string(*run.kinematics)) : io::Json(nullptr);
    j["theta0"] = run.theta0_over_alpha;
    j["alpha1"] = run.alpha;  // the angle rotations are measured in (a parapet's alpha)
    j["impact"] = {{"law", to_string(run.impact)}, {"restitution", run.restitution}};
    j["warnings"] = run.warnings;
    j["impacts"] = std::move(impacts);
    j["peaks"] = std::move(peaks);
    j["peak_times"] = std::move(peak_times);
    j["stop_time"] = io::or_null(run.stop_time());
    j["falls"] = res.overturned;
    j["t_overturn"] = res.overturned ? io::Json(res.t_overturn) : io::Json(nullptr);
    j["energy_balance_error"] = res.energy_balance_error;
    j["impact_count"] = res.impacts.size();
    j["first_impact_time"] = io::or_null(run.first_impact());
    j["end_time"] = res.t_final;
    add_support_json(j, res, run.roller);
    j["wall"] = wall_inputs_json(run.wall, run.kind);
    return j;
}

void print_free_summary(std::ostream& out, const FreeRun& run, const std::string& title) {
    const SimulationResult& res = run.result;
    const char* alpha_name = reference_angle_name(run.kind);
    Table table(title);
    table
        .text("model", run.kinematics ? fmt::format("{}, {} kinematics ({} assumptions)", to_string(run.kind),
                                                    to_string(*run.kinematics), run.set_name)
                                      : fmt::format("{} ({} assumptions)", to_string(run.kind), run.set_name))
        .text("release from rest at", fmt::format("theta0 = {} {} = {} rad", io::num(run.theta0_over_alpha), alpha_name,
                                                  io::num(run.theta0_over_alpha * run.alpha)))
        .text("impact law", fmt::format("{} (restitution {})", to_string(run.impact), io::num(run.restitution)))
        .add("impacts", std::to_string(res.impacts.size()));
    for (const std::string& w : run.warnings) table.text("warning", w);
    table
        .add("first impact (quarter period)", num_or(run.first_impact(), "none"), run.first_impact() ? "s" : "")
        .add("comes to rest at", num_or(run.stop_time(), "never"), run.stop_time() ? "s" : "");
    if (res.overturned)
        table.add("overturns at", io::num(res.t_overturn), "s");
    else
        table.add("overturns", "no");
    table.add("energy balance error", fmt::format("{:.2e}", res.energy_balance_error), "",
              "largest residual / largest energy in play");
    add_support_rows(table, res);
    table.print(out);
}

void print_free_impacts(std::ostream& out, const FreeRun& run, std::size_t max_rows) {
    const SimulationResult& res = run.result;
    if (res.impacts.empty()) return;
    auto row = [&out](const auto&... cells) {
        out << fmt::format("  {:>4}  {:>15}  {:>10}  {:>16}  {:>16}  {:>11}\n", cells...);
    };
    row("#", fmt::format("peak |th|/{}", reference_angle_name(run.kind)), "t [s]", "theta'- [rad/s]", "theta'+ [rad/s]",
        "ratio +/-");
    const std::size_t shown = std::min(max_rows, res.impacts.size());
    for (std::size_t i = 0; i < shown; ++i) {
        const Impact& imp = res.impacts[i];
        // peaks[i] is the turning point before impact i (the release comes first).
        const std::string peak = i < res.peaks.size() ? io::num(std::abs(res.peaks[i].theta) / run.alpha) : "-";
        row(i + 1, peak, io::num(imp.t), io::num(imp.theta_dot_before), io::num(imp.theta_dot_after),
            io::num(imp.theta_dot_after / imp.theta_dot_before));
    }
    if (shown < res.impacts.size())
        out << fmt::format("  ... {} more impacts (all of them with --json)\n", res.impacts.size() - shown);
}

}  // namespace vssw::cli

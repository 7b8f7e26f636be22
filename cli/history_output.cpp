#include "cli/history_output.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "analytic/response.hpp"
#include "analytic/error.hpp"
#include "cli/model_validity.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/table.hpp"

namespace vssw::cli {
HistoryRun prepare_history(const WallOptions& wall, const ModelOptions& model, const GroundMotionOptions& motion,
                           const HistoryRequest& request) {
    ChosenModel chosen = choose_model(wall, model);
    LoadedMotion input = load_ground_motion(motion);
    require_model_follows_top(chosen.wall, input.motion);  // history is the analytic model's
    SimulationOptions options;
    options.output_dt = request.output_dt.value_or(input.sample_dt);
    require(std::isfinite(options.output_dt) && options.output_dt > 0.0, "output interval (--output-dt) [s]",
            "a positive finite number", options.output_dt);
    // The longer of the two components, so that a vertical record longer than the horizontal one is not cut.
    options.t_end =
        request.t_end.value_or(std::max(input.motion.duration(), input.vertical.duration()) + kDefaultExtraTime);
    require(std::isfinite(options.t_end) && options.t_end > 0.0, "end time (--t-end) [s]", "a positive finite number",
            options.t_end);
    // The default output interval is the record's: say so, rather than refuse an --output-dt nobody gave.
    if (!request.output_dt && request.keep_trajectory && options.t_end / options.output_dt > kMaxOutputSamples)
        throw InputError(fmt::format("the output interval defaults to the ground motion's sample step, {:g} s, which "
                                     "gives more than {:g} samples over the run's {:g} s: give --output-dt of at "
                                     "least {:g} s",
                                     options.output_dt, kMaxOutputSamples, options.t_end,
                                     options.t_end / kMaxOutputSamples));
    options.keep_samples = request.keep_trajectory;
    options.stop_at_rest = true;
    options.roller = chosen.roller();
    return {wall, motion.record, motion.vertical_record, std::move(input), std::move(chosen), options, {}, {}};
}

void simulate_history(HistoryRun& run) {
    run.result = run_simulation([&] {
        return simulate(*run.chosen.model, run.input.motion, run.input.vertical, InitialState{}, run.options);
    });
    run.warnings = validity_warnings(run.chosen, run.result);
}

io::Json to_json(const HistoryRun& run) {
    const SimulationResult& res = run.result;
    io::Json j;
    j["record"] = run.record ? io::Json(*run.record) : io::Json(nullptr);
    j["input"] = run.input.motion.name();
    j["scale_factor"] = run.input.scale_factor;
    j["pga_g"] = run.input.motion.pga() / vssw::kStandardGravity;
    j["duration"] = run.input.motion.duration();
    j["model"] = to_string(run.chosen.kind);
    j["assumptions"] = run.chosen.set_name();
    j["kinematics"] = run.chosen.kinematics() ? io::Json(to_string(*run.chosen.kinematics())) : io::Json(nullptr);
    j["vertical_record"] = run.vertical_record ? io::Json(*run.vertical_record) : io::Json(nullptr);
    j["vertical_pga_g"] = run.vertical_record ? io::Json(run.input.vertical.pga() / vssw::kStandardGravity) : io::Json(nullptr);
    j["alpha1"] = run.chosen.model->reference_angle();
    // The peak a study and `vssw compare --record` give the same run: an overturned run's is the model's collapse
    // angle, not a rocking peak (analytic/response.hpp).
    const AnalyticResponse response = response_of(res, *run.chosen.model);
    j["max_theta_over_alpha1"] = response.peak / run.chosen.model->reference_angle();
    j["max_theta"] = response.peak;
    j["t_max_theta"] = response.peak_time;
    j["peak_is_collapse"] = res.overturned;
    j["overturned"] = res.overturned;
    j["t_overturn"] = res.overturned ? io::Json(res.t_overturn) : io::Json(nullptr);
    j["impacts"] = res.impacts.size();
    j["energy_balance_error"] = res.energy_balance_error;
    j["lift_offs"] = res.lift_offs.size();
    j["end_time"] = res.t_final;
    j["at_rest_at_end"] = res.at_rest_at_end;
    j["t_end"] = run.options.t_end;
    j["output_dt"] = run.options.output_dt;
    j["impact"] = impact_json(run.chosen);
    j["warnings"] = run.warnings;
    add_support_json(j, res, run.chosen.roller());
    j["wall"] = wall_inputs_json(run.wall, run.chosen.kind);
    return j;
}

void print_history_summary(std::ostream& out, const HistoryRun& run, const std::string& title) {
    const SimulationResult& res = run.result;
    const AnalyticResponse response = response_of(res, *run.chosen.model);  // as in history_json
    const char* alpha_name = reference_angle_name(run.chosen.kind);
    Table table(title);
    table.text("ground motion", run.record ? *run.record : run.input.motion.name())
        .add("peak ground acceleration", io::num(run.input.motion.pga() / vssw::kStandardGravity), "g",
             run.input.scale_factor == 1.0 ? "unscaled" : fmt::format("scaled by {}", io::num(run.input.scale_factor)));
    if (run.vertical_record)
        table.text("vertical component", *run.vertical_record)
            .add("its peak acceleration", io::num(run.input.vertical.pga() / vssw::kStandardGravity), "g");
    table
        .add("duration", io::num(run.input.motion.duration()), "s")
        .text("model", fmt::format("{} ({})", to_string(run.chosen.kind), describe_assumptions(run.chosen)))
        .text("impact law",
              fmt::format("{} (restitution {})", to_string(run.chosen.impact()), io::num(run.chosen.model->restitution())))
        .add("lift-offs", std::to_string(res.lift_offs.size()))
        .add("impacts", std::to_string(res.impacts.size()))
        .add(fmt::format("max |theta|/{}", alpha_name), io::num(response.peak / run.chosen.model->reference_angle()),
             "", res.overturned ? "the collapse angle: overturned, not a rocking peak" : "")
        .add("max |theta|", io::num(response.peak), "rad")
        .add("at", io::num(response.peak_time), "s");
    for (const std::string& w : run.warnings) table.text("warning", w);
    if (res.overturned)
        table.add("overturns at", io::num(res.t_overturn), "s");
    else
        table.add("overturns", "no");
    table.add("run ended at", io::num(res.t_final), "s", res.at_rest_at_end ? "at rest" : "")
        .add("energy balance error", fmt::format("{:.2e}", res.energy_balance_error), "",
             "largest residual / largest energy in play");
    add_support_rows(table, res);
    table.print(out);
}

}  // namespace vssw::cli

// `vssw history`: the response of a wall, from rest, to a recorded or synthetic ground motion.
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/commands.hpp"
#include "cli/engine_runs.hpp"
#include "cli/engine_setting_options.hpp"
#include "cli/model_validity.hpp"
#include "cli/history_output.hpp"
#include "cli/trajectory_csv.hpp"
#include "io/json.hpp"

namespace vssw::cli {

Command add_history_command(CLI::App& root) {
    struct Options {
        WallOptions wall;
        ModelOptions model;
        GroundMotionOptions motion;
        HistoryRequest request;
        std::optional<std::string> csv;  // --csv as given (empty is refused)
        bool json = false;
        bool strict = false;
        std::string engine = "analytic";
        EngineSettingOptions engine_settings;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = root.add_subcommand(
        "history",
        "Response from rest to a ground motion: a record file (and its vertical component) or a synthetic pulse");
    add_engine_choice(*cmd, o->engine);
    add_ground_motion_options(*cmd, o->motion, true);
    add_model_options(*cmd, o->model);
    add_assumption_options(*cmd, o->model);
    add_wall_options(*cmd, o->wall, true);
    add_diaphragm_options(*cmd, o->wall, true);
    cmd->add_option_function<double>(
        "--output-dt", [o](const double& dt) { o->request.output_dt = dt; },
        "spacing of the CSV samples [s] (default: the record's sample spacing; T_p/100 for a pulse)");
    cmd->add_option_function<double>(
        "--t-end", [o](const double& t) { o->request.t_end = t; },
        fmt::format("end of the run [s] (default: the ground motion's duration + {} s; the run also ends once the "
                    "wall is at rest after the shaking, or overturns)",
                    kDefaultExtraTime));
    cmd->add_option("--csv", o->csv,
                    "write the trajectory to this file, or with '-' to standard output (the summary then goes to the "
                    "error stream): t [s], theta1_over_alpha1, theta_dot_over_ref, E_over_Vr, ED_over_Vr, ag_g");
    cmd->add_flag("--json", o->json, "print JSON instead of a table");
    add_strict_flag(*cmd, o->strict);
    add_engine_setting_options(*cmd, o->engine_settings);
    cmd->footer(std::string(kEngineRunHelp) +
        "Exactly one of --record and --pulse is required. Accelerations given in g use g0 = 9.80665 m/s^2.\n"
        "JSON keys: record (path, null for a pulse), input, scale_factor, pga_g (after scaling), duration [s], model,\n"
        "vertical_record (path or null), vertical_pga_g, kinematics, alpha1, max_theta_over_alpha1, max_theta [rad],\n"
        "t_max_theta [s] (when: the turning point, or the overturning), peak_is_collapse (true: the max is the collapse angle), overturned, t_overturn (null if not), impacts, energy_balance_error\n"
        "(relative to the largest energy in play), lift_offs, end_time, at_rest_at_end, t_end, output_dt,\n"
        "impact {law, restitution}, warnings, roller {model, min_reaction, t_min_reaction, tension_at, departures,\n"
        "time_off},\n"
        "friction_needed {base, hinge}, contacts_pull {base_at, hinge_at} (as `vssw free --help` says),\n"
        "wall {height, thickness, hinge_ratio (null for a parapet), xi, density, g}.\n"
        "CSV: theta_dot_over_ref = theta_dot / reference velocity; E = kinetic + weights' potential - work of N,\n"
        "ED = energy dissipated by impacts, both over V_r (the potential energy at alpha1); ag_g = a_h / g0.");
    return {cmd, nullptr, [o, cmd](std::ostream& out, std::ostream& err) {
                std::vector<std::string> inputs;  // the CSV must not replace them
                for (const auto& file : {o->motion.record, o->motion.vertical_record})
                    if (file) inputs.push_back(*file);
                if (!names_analytic_model(o->engine)) {
                    refuse_analytic_options(*cmd, {"--assumptions", "--kinematics", "--impact", "--roller", "--strict",
                                                   "--vertical-record"},
                                            o->engine);
                    EngineRun run = prepare_engine_history(o->engine, o->engine_settings, o->wall, o->model, o->motion,
                                                           o->request.output_dt, o->request.t_end);
                    TrajectoryCsv csv(o->csv, o->json, inputs);
                    run_and_print_engine(out, err, csv, run, o->json, "Time history", o->wall);
                    return;
                }
                refuse_engine_settings(*cmd);
                o->request.keep_trajectory = o->csv.has_value();
                HistoryRun run = prepare_history(o->wall, o->model, o->motion, o->request);
                TrajectoryCsv csv(o->csv, o->json, inputs);  // after the options are checked, before the run
                simulate_history(run);
                csv.write(out, *run.chosen.model, run.result);
                std::ostream& summary = csv.summary(out, err);
                if (o->json)
                    summary << io::dump_json(to_json(run), 2) << '\n';
                else
                    print_history_summary(summary, run,
                                          "Time history of the " + describe_wall(o->wall, run.chosen.kind));
                if (o->strict) refuse_warnings(run.warnings);
            }};
}

}  // namespace vssw::cli

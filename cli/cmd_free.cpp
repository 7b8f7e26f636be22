// `vssw free`: free vibration from rest at theta0 = r * alpha1 (a parapet's alpha).
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/commands.hpp"
#include "cli/engine_runs.hpp"
#include "cli/engine_setting_options.hpp"
#include "cli/model_validity.hpp"
#include "cli/free_output.hpp"
#include "cli/trajectory_csv.hpp"
#include "io/json.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {
namespace {

// Impact rows in the table; the JSON output always has all of them.
constexpr std::size_t kImpactRowsShown = 20;

}  // namespace

Command add_free_command(CLI::App& root) {
    struct Options {
        WallOptions wall;
        ModelOptions model;
        FreeRequest request;
        std::optional<std::string> csv;  // --csv as given (empty is refused)
        bool json = false;
        bool strict = false;
        std::string engine = "analytic";
        EngineSettingOptions engine_settings;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = root.add_subcommand("free", "Free vibration released from rest, until the wall stops or overturns");
    add_engine_choice(*cmd, o->engine);
    add_model_options(*cmd, o->model);
    add_assumption_options(*cmd, o->model);
    add_wall_options(*cmd, o->wall, true);
    cmd->add_option("--theta0", o->request.theta0_over_alpha,
                    "initial rotation as a fraction r of alpha1 (a parapet's alpha): finite, "
                    "nonzero, r * alpha1 below the collapse angle (required)")
        ->required();
    cmd->add_option("--rtol", o->request.rtol,
                    fmt::format("relative tolerance of the integrator (default {})", o->request.rtol));
    cmd->add_option("--csv", o->csv,
                    "write the trajectory to this file, or with '-' to standard output (the summary then goes to the "
                    "error stream): t [s], theta1_over_alpha1, theta_dot_over_ref, E_over_Vr, ED_over_Vr, ag_g");
    cmd->add_option("--output-dt", o->request.output_dt,
                    fmt::format("spacing of the CSV samples [s] (default {})", o->request.output_dt));
    cmd->add_flag("--json", o->json, "print JSON instead of tables");
    add_strict_flag(*cmd, o->strict);
    add_engine_setting_options(*cmd, o->engine_settings);
    cmd->footer(std::string(kEngineRunHelp) +
        "Times in s, angular velocities in rad/s, rotations as |theta|/alpha1 (alpha1: the lower block's\n"
        "angle atan(b/h1); a parapet's alpha1 is its alpha, atan(b/h)).\n"
        "JSON keys: model, kinematics (null for a parapet), theta0 (r), alpha1 [rad],\n"
        "impacts [{t, theta_dot_before, theta_dot_after}], peaks (|theta|/alpha1 at each turning point, the release\n"
        "first), peak_times, stop_time (null if it overturned), falls, t_overturn (null unless it fell),\n"
        "impact {law, restitution}, warnings (the model's assumptions failing along the run),\n"
        "roller {model, min_reaction [N/m, > 0 pushing], t_min_reaction, tension_at (null if it never pulls),\n"
        "departures, time_off (a unilateral roller: how often and how long the top was off it)},\n"
        "friction_needed {base, hinge} (largest |T|/N), contacts_pull {base_at, hinge_at} (null: never; all null\n"
        "for a parapet),\n"
        "energy_balance_error (relative to the largest energy in play), impact_count, first_impact_time (a quarter period), end_time,\n"
        "wall {height, thickness, hinge_ratio (null for a parapet), xi, density, g}.");
    return {cmd, nullptr, [o, cmd](std::ostream& out, std::ostream& err) {
                if (!names_analytic_model(o->engine)) {
                    refuse_analytic_options(*cmd, {"--rtol", "--assumptions", "--kinematics", "--impact", "--roller",
                                                   "--strict"},
                                            o->engine);
                    EngineRun run = prepare_engine_free(o->engine, o->engine_settings, o->wall, o->model,
                                                        o->request.theta0_over_alpha, o->request.output_dt);
                    TrajectoryCsv csv(o->csv, o->json);
                    run_and_print_engine(out, err, csv, run, o->json, "Free vibration", o->wall);
                    return;
                }
                refuse_engine_settings(*cmd);
                TrajectoryCsv csv(o->csv, o->json);
                o->request.keep_trajectory = csv.wanted();
                const FreeRun run = run_free(o->wall, o->model, o->request);
                csv.write(out, *run.model, run.result);
                std::ostream& summary = csv.summary(out, err);
                if (o->json) {
                    summary << io::dump_json(to_json(run), 2) << '\n';
                } else {
                    print_free_summary(summary, run, "Free vibration of the " + describe_wall(o->wall, run.kind));
                    print_free_impacts(summary, run, kImpactRowsShown);
                }
                if (o->strict) refuse_warnings(run.warnings);
            }};
}

}  // namespace vssw::cli

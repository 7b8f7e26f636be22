#pragma once
// `vssw free --engine E` and `vssw history --engine E`: the wall run by a rigid-body engine instead of the analytic
// model (multibody::Engine::simulate, in a child process as every engine run), its trajectory written as CSV in the
// analytic model's reference units, and a short summary measured from the samples by compare/ (the measures
// `vssw compare` reads). The analytic model's own runs stay in free_output and history_output.
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/engine_setting_options.hpp"
#include "cli/ground_motion_options.hpp"
#include "cli/trajectory_csv.hpp"
#include "cli/wall_options.hpp"
#include "io/json.hpp"
#include "multibody/engine.hpp"

namespace CLI {
class App;
}

namespace vssw::cli {

// The columns of an engine's trajectory CSV: the analytic CSV's first three (same names, same units), then what only
// an engine's run has, and the ground motion (docs/guide/program.md, "An engine's trajectory").
inline constexpr const char* kEngineCsvHeader =
    "t,theta1_over_alpha1,theta_dot_over_ref,theta2_over_alpha1,top_dy,E_over_Vr,ag_g,contacts";

// What free's and history's --help say of an engine's run (their footers' first part).
inline constexpr const char* kEngineRunHelp =
    "With --engine E (a rigid-body engine instead of the analytic model, the default): the engine's run of the wall,\n"
    "in a child process, with its settings (--dt, --iterations, --set; vssw compare --list-settings); the analytic\n"
    "model's options (--assumptions, --kinematics, --impact, --roller, --rtol, --strict, --vertical-record) are\n"
    "refused. free's release is from 0.01 to below 1 and its run lasts 1.25 times the paper's model's time to rest\n"
    "(Eq. 19 impacts, exact kinematics, sharp corners), as vssw compare's free vibration.\n"
    "Its CSV: t [s], theta1_over_alpha1 and theta_dot_over_ref (as the analytic CSV), theta2_over_alpha1,\n"
    "top_dy [m] (the top's rise), E_over_Vr (kinetic + weights' potential + N times the top's rise, over V_r),\n"
    "ag_g, contacts (contact points in use). JSON keys: engine, version, settings {dt, iterations, knobs,\n"
    "sample_dt}, model, alpha1, theta0, first_impact_time, impact_count, impact_times (free), record, input\n"
    "(history), max_theta_over_alpha1, t_max_theta, overturned, t_overturn, at_rest_at_end, end_time, t_end,\n"
    "samples, steps.\n\n";

// --engine NAME, default analytic (free, history).
void add_engine_choice(CLI::App& cmd, std::string& engine);
// Whether --engine names the analytic model, in any letter case ("Analytic"): make_engine reads an engine's name so,
// and a raw comparison would run the analytic model as an engine.
bool names_analytic_model(const std::string& engine);
// --dt, --iterations or --set given without an engine: InputError naming it.
void refuse_engine_settings(const CLI::App& cmd);

struct EngineRun {
    std::string command;  // "free" or "history"
    std::unique_ptr<multibody::Engine> engine;
    multibody::EngineSettings settings;
    ChosenModel chosen;  // the wall, its kind and the reference units (the default model's)
    multibody::WallScene scene;
    multibody::Excitation excitation;
    double r = 0.0;  // free: the release as a fraction of alpha1 (a parapet's alpha)
    std::optional<std::string> record;  // history: the record's path, when the input is one
    multibody::Trajectory trajectory;   // after simulate_engine_run
};

// The options given that an engine's run cannot honour (what only the analytic model takes: its assumptions,
// tolerance, --strict, a vertical record): InputError naming the first one and the engine.
void refuse_analytic_options(const CLI::App& cmd, const std::vector<std::string>& names, const std::string& engine);

// Everything checked (engine, settings, wall, release, step), nothing run. r from compare::kMinRelease to below 1.
// The samples are output_dt apart, rounded to a whole number of the engine's steps (default: free 1 ms, history the
// ground motion's sample spacing, as the analytic runs).
EngineRun prepare_engine_free(const std::string& engine, const EngineSettingOptions& settings,
                              const WallOptions& wall, const ModelOptions& model, double r, double output_dt);
EngineRun prepare_engine_history(const std::string& engine, const EngineSettingOptions& settings,
                                 const WallOptions& wall, const ModelOptions& model, const GroundMotionOptions& motion,
                                 std::optional<double> output_dt, std::optional<double> t_end);
// Fills run.trajectory; SimulationFailure with the engine's reason when the run fails.
void simulate_engine_run(EngineRun& run);

// kEngineCsvHeader, then one row per sample (10 significant digits, as the analytic CSV).
void write_engine_trajectory_csv(std::ostream& out, const EngineRun& run);
io::Json to_json(const EngineRun& run);
void print_engine_run(std::ostream& out, const EngineRun& run, const std::string& title);
// The run (simulate_engine_run), then the CSV where --csv sends it and the JSON or the table where the summary goes,
// the table titled "<what> of the <wall>". csv is opened before: after the options are checked, before the run.
void run_and_print_engine(std::ostream& out, std::ostream& err, TrajectoryCsv& csv, EngineRun& run, bool json,
                          const std::string& what, const WallOptions& wall);

}  // namespace vssw::cli

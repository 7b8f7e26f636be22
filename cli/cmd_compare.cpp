// `vssw compare`: engines against the analytic model (exact kinematics unless --kinematics says otherwise) on
// threshold, period and restitution, every metric measured from both trajectories by the same code (compare/).
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
#include "cli/commands.hpp"
#include "cli/compare_response.hpp"
#include "cli/early_output.hpp"
#include "cli/engine_setting_options.hpp"
#include "cli/friction_option.hpp"
#include "cli/ground_motion_options.hpp"
#include "cli/model_validity.hpp"
#include "cli/option_values.hpp"
#include "cli/compare_output.hpp"
#include "cli/compare_rounded.hpp"
#include "cli/settings_listing.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/wall_options.hpp"
#include "cli/run_budget_option.hpp"
#include "compare/experiments.hpp"
#include "compare/rounded_corners.hpp"
#include "io/json.hpp"
#include "study/response_comparison.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "multibody/kit/settings_reader.hpp"

namespace vssw::cli {
namespace {

using compare::kMinRelease;  // compare/experiments.hpp says why 0.01

struct CompareOptions {
    WallOptions wall;
    ModelOptions model;  // the reference's: the set `mechanism` unless --assumptions says otherwise
    std::vector<std::string> engines;  // as given, comma-separated lists split
    double theta0 = 0.5;
    EngineSettingOptions engine_settings;  // --dt, --iterations, --set
    bool json = false;
    GroundMotionOptions motion;  // --record or --pulse: a comparison under a ground motion (compare_response.hpp)
    bool theta0_given = false;
    bool strict = false;  // exit 3 when the analytic reference's own assumptions fail (its warnings)
    std::optional<std::string> friction;  // --friction as typed (friction_option.hpp)
};

multibody::EngineSettings settings_of(const multibody::Engine& engine, const CompareOptions& o) {
    return engine_settings_of(engine, o.engine_settings);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The free vibration's release: a fraction of alpha1, from kMinRelease to below 1.
void require_release(const CompareOptions& o) {
    require(std::isfinite(o.theta0) && o.theta0 >= kMinRelease && o.theta0 < 1.0, "--theta0",
            fmt::format("from {:g} to below 1 (a fraction of alpha1)", kMinRelease), o.theta0);
}

// What every engine is measured against; the release checked first.
CompareReference reference_of(const CompareOptions& o, const ChosenModel& chosen, const multibody::WallScene& scene) {
    require_release(o);
    const bool vssw = chosen.kind == WallKind::vssw;
    // What an engine's impact should give: every constraint of the new mechanism acting at once.
    const double whole = vssw ? restitution_whole_mechanism(*scene.vssw) : housner_restitution(scene.parapet->alpha);
    return {o.wall, chosen.kind, chosen.kinematics(), chosen.impact(), vssw ? std::optional(chosen.roller()) : std::nullopt,
            chosen.set_name(), o.theta0, whole};
}

// Under a ground motion: the engines and the analytic model from rest, peak against peak (a one-case study).
void run_compare_response(const CompareOptions& o, std::ostream& out) {
    if (o.theta0_given) throw InputError("--theta0 is a release for the free vibration; with --record or --pulse the "
                                         "wall starts from rest");
    LoadedMotion loaded = load_ground_motion(o.motion);
    const ChosenModel chosen = choose_model(o.wall, o.model);
    std::vector<study::ResponseEngine> engines;
    for (const std::string& name : parse_engine_list("--engine", o.engines))
        engines.push_back({name, settings_of(*multibody::make_engine(name), o)});
    const study::ResponseMotion motion = response_motion(o.motion, std::move(loaded));
    // The reference's assumptions as resolved: a parapet ignores its kinematics and roller.
    const multibody::AnalyticAssumptions& reference = chosen.assumptions;
    const auto start = std::chrono::steady_clock::now();
    const study::ResponseComparison result = study::compare_response(
        with_friction(multibody::WallScene(chosen.wall), o.friction), reference, motion, engines);
    print_response_comparison(result, chosen, seconds_since(start), o.json, o.strict, out);
}

// Rounded corners: the model gives the threshold only (Eq. 12r / 17r); each engine's threshold and period, and their
// spread (compare/rounded_corners.hpp).
void run_compare_rounded(const CompareOptions& o, const ChosenModel& chosen, std::ostream& out) {
    require_release(o);
    const multibody::WallScene scene(chosen.wall);
    std::vector<std::unique_ptr<multibody::Engine>> engines;
    std::vector<compare::RoundedEngine> runs;
    for (const std::string& name : parse_engine_list("--engine", o.engines)) {
        if (name == "analytic")
            throw InputError("--engine analytic with --corner-radius: the analytic model's motion is the sharp "
                             "blocks'; its threshold (Eq. 12r / 17r) is printed beside the engines'");
        engines.push_back(multibody::make_engine(name));
        runs.push_back({engines.back().get(), settings_of(*engines.back(), o)});
        multibody::require_settings_fit_wall(engines.back()->display_name(), runs.back().settings,
                                             engines.back()->setting_descriptions(), scene);
    }
    const compare::RoundedCornerComparison result = compare::compare_rounded_corners(runs, scene, o.theta0);
    if (o.json)
        out << io::dump_json(to_json(result, o.wall, chosen.kind, o.theta0), 2) << '\n';
    else
        print_rounded_corners(out, result, o.wall, chosen.kind);
    std::vector<std::string> why;
    for (const compare::RoundedEngineResult& e : result.engines)
        if (!e.failure.empty()) why.push_back(e.engine + ": " + e.failure);
        else if (!std::isfinite(e.period))
            why.push_back(e.engine +
                          (e.overturned ? ": no first impact: the wall overturned" : ": no first impact resolved"));
    if (!why.empty()) throw SimulationFailure(fmt::format("{}", fmt::join(why, "; ")));
}

void run_compare(const CompareOptions& o, std::ostream& out) {
    if (o.wall.corner_radius != 0.0 && (o.motion.record || o.motion.pulse))
        throw InputError("--corner-radius with --record or --pulse: the analytic reference cannot roll on rounded "
                         "corners; without a motion, compare gives each engine's threshold and period and their "
                         "spread");
    if (o.motion.record || o.motion.pulse) {
        run_compare_response(o, out);
        return;
    }
    // Every input is checked before the first engine runs: the wall and the reference's model, the engines and each
    // one's settings, the release.
    const ChosenModel chosen = choose_model(o.wall, o.model);
    // The metrics' threshold is the analytic model's under a constant acceleration, which a moving top takes out of
    // its mechanism (docs/model/top-support.md); the free vibration has no ground motion for a diaphragm to follow.
    // Checked before the rounded corners' branch, whose runs are free vibrations too.
    if (!chosen.wall.diaphragm.is_rigid())
        throw InputError(fmt::format("--diaphragm-period {:g} applies to a run under --pulse or --record: the "
                                     "threshold's reference, the analytic model, cannot follow a moving top, and a "
                                     "free vibration has no ground motion for the diaphragm to follow",
                                     chosen.wall.diaphragm.period));
    if (o.wall.corner_radius != 0.0) {
        // Its runs give thresholds and periods, not slips: a friction would change them unreported.
        if (o.friction)
            throw InputError(fmt::format("--friction {} with --corner-radius: compare's rounded corners give each "
                                         "engine's threshold and period, not its slips; a study with the keys "
                                         "friction and corner_radius measures both",
                                         *o.friction));
        run_compare_rounded(o, chosen, out);
        return;
    }
    const multibody::WallScene scene = with_friction(multibody::WallScene(chosen.wall), o.friction);
    compare::ComparisonOptions options;
    options.reference = multibody::analytic_settings(chosen.assumptions);
    std::vector<std::unique_ptr<multibody::Engine>> engines;
    std::vector<EngineCompareRun> runs;
    for (const std::string& name : parse_engine_list("--engine", o.engines)) {
        engines.push_back(multibody::make_engine(name));
        const multibody::Engine& e = *engines.back();
        runs.push_back({e.name(), e.version(), settings_of(e, o), {}, 0.0, ""});
    }
    const CompareReference reference = reference_of(o, chosen, scene);
    // A setting for another wall, or a step no run can use: refused before the first engine runs.
    for (std::size_t i = 0; i < runs.size(); ++i) {
        multibody::require_settings_fit_wall(engines[i]->display_name(), runs[i].settings,
                                             engines[i]->setting_descriptions(), scene);
        compare::require_comparison_steps(*engines[i], runs[i].settings, scene, o.theta0, options);
    }
    const bool several = runs.size() > 1;

    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < runs.size(); ++i) {
        EngineCompareRun& run = runs[i];
        const auto engine_start = std::chrono::steady_clock::now();
        try {
            run.comparison = compare::compare_with_analytic(*engines[i], run.settings, scene, o.theta0, options);
        } catch (const multibody::EngineFailure& e) {
            if (!several) throw SimulationFailure(e.what());  // one engine: nothing to print, as before
            run.failure = e.what();  // the others still run
        }
        run.seconds = seconds_since(engine_start);
        if (o.json) continue;
        if (i > 0) out << '\n';
        print_compare(out, run, reference);  // as each engine ends: a long run shows its progress
    }
    if (o.json) {
        io::Json j = several ? to_json(runs, reference, seconds_since(start)) : to_json(runs.front(), reference);
        if (scene.slip_measured) j["friction"] = friction_json(scene);  // as under a motion: the run can be repeated
        out << io::dump_json(j, 2) << '\n';
    }

    std::vector<std::string> why;
    for (const EngineCompareRun& run : runs)
        if (const std::string w = incomplete(run); !w.empty()) why.push_back(several ? run.engine + ": " + w : w);
    if (!why.empty()) throw SimulationFailure(fmt::format("{}", fmt::join(why, "; ")));
    // Every run succeeded here (a failure threw above), and one reference serves them all: the first one's warnings.
    if (o.strict) refuse_warnings(runs.front().comparison.analytic_warnings);
}

}  // namespace

Command add_compare_command(CLI::App& root) {
    auto o = std::make_shared<CompareOptions>();
    CLI::App* cmd = root.add_subcommand(
        "compare", "Engines against the analytic model (the set 'mechanism'): threshold, period, restitution");
    add_list_option(*cmd, "--engine", o->engines,
                    fmt::format("backends to compare, comma-separated, or all ({}) (available: {}) (required)",
                                fmt::join(multibody::default_compared_engines(), ", "),
                                fmt::join(multibody::available_engines(), ", ")))
        ->required();
    add_model_options(*cmd, o->model);
    add_assumption_options(*cmd, o->model);
    add_wall_options(*cmd, o->wall, true);
    add_diaphragm_options(*cmd, o->wall, false);
    add_corner_radius_option(*cmd, o->wall);
    add_friction_option(*cmd, o->friction);
    cmd->add_option_function<double>(
           "--theta0",
           [o](const double& r) {
               o->theta0 = r;
               o->theta0_given = true;
           },
                    fmt::format("release from rest at theta0 = r * alpha for the period and restitution, r from "
                                "{:g} to below 1 (default 0.5)",
                                kMinRelease));
    add_ground_motion_options(*cmd, o->motion);
    cmd->add_option("--dt", o->engine_settings.dt,
                    "engine step [s], for every engine named (default: each engine's own, see --list-settings)");
    cmd->add_option("--iterations", o->engine_settings.iterations,
                    fmt::format("solver iterations, 1 to {}, for every engine named (default: each engine's own)",
                                multibody::kMaxIterations));
    cmd->add_option("--set", o->engine_settings.knobs,
                    "engine setting NAME=VALUE, for every engine named (repeatable; each adapter lists its own; one "
                    "that an engine does not know is refused)");
    cmd->add_flag("--json", o->json, "print JSON instead of a table");
    add_run_budget_option(*cmd);
    cmd->add_flag("--strict", o->strict,
                  "exit 3 when the analytic reference's own assumptions fail (its warnings), after printing (for CI)");
    // Defined after --engine and --json: CLI11 runs the callbacks in this order, so both are read by then.
    cmd->add_flag_callback(
        "--list-settings", [o] { throw EarlyOutput(settings_listing(o->engines, o->json)); },
        "print every setting of the --engine backends (all compiled in when none is named) with its default, unit "
        "and meaning, then exit (JSON with --json: [{engine, version, settings [{name, flag, default, unit, "
        "min, max, meaning, walls}]}]; min and max null when unbounded; walls \"any\", or \"vssw\" or \"parapet\" "
        "for a setting of that wall only)");
    // A function, so that the backends are built for the listing only when the help is printed.
    cmd->footer([]() -> std::string {
        return std::string(
               "The analytic reference is the model of --assumptions (default mechanism: the exact kinematics, the whole\n"
               "mechanism's impact and the unilateral roller, what every engine realises), with --kinematics, --impact\n"
               "and --roller overriding one of them; the engines' options (--dt, --iterations, --set) do not reach it.\n"
               "The threshold (in g) is the smallest constant ground acceleration that lifts the wall off rest, by bisection\n"
               "to 1e-4; the period is 4x the time from release at theta0 to the first impact; the restitution is the ratio\n"
               "of theta1' after and before the first impact. rel_error = engine / analytic - 1; targets 0.5 %, 0.5 %, 2 %.\n"
               "JSON keys (one engine): engine, version, analytic_model {assumptions, kinematics, impact, roller}, threshold, period,\n"
               "restitution, restitution_amplitude (each {analytic, engine, rel_error, target, within_target}), closed_forms\n"
               "{threshold_g, restitution, restitution_whole_mechanism, period_linearised}, theta0, settings {dt,\n"
               "iterations, knobs}, wall_time_s, failures, analytic_warnings, wall {...}.\n"
               "Several engines: {comparisons [one such object per engine], engine_failures [{engine, version, message}],\n"
               "wall_time_s}; the table has one block per engine.\n"
               "failures: why a metric is null (e.g. an engine's first-impact ratio outside (0, 1]).\n"
               "analytic_warnings: the analytic model's own assumptions failing along its free vibration (e.g. a roller\n"
               "that would have to pull): its values are the model's, but the model may not hold there; --strict makes\n"
               "them exit 3 (after printing).\n"
               "Exit 3 when an engine fails (NaN, sliding, ...) or a metric could not be measured (the output is printed;\n"
               "with one engine, an engine that fails prints nothing).\n"
               "With --record or --pulse (the ground-motion options of `vssw history`): every engine and the analytic model\n"
               "from rest under that motion instead, each run's peak rotation (theta1/alpha1), its time and overturning side\n"
               "by side: a one-case study (`vssw study` runs grids of them). JSON: {ground_motion, analytic_model, runs\n"
               "[{engine, version, settings, peak_rotation, peak_time, overturned, t_overturn, status, warnings (analytic),\n"
               "peak_rotation_rel_error (engines)}], wall_time_s}; exit 3 when a run failed.\n"
               "With --corner-radius (rounded blocks, engines only: the analytic model gives Eq. 12r / 17r, not the\n"
               "motion): each engine's threshold and period and their spread. JSON: {wall, corner_radius, closed_forms\n"
               "{threshold_g, threshold_sharp_g}, theta0, engines [{engine, threshold_g, threshold_rel_error, period,\n"
               "overturned, failure}], threshold_spread, period_spread}; exit 3 when an engine failed or has no period.\n\n"
               "With --friction as well: friction {base, hinge}; each engine's run slip {base, hinge {largest_b, largest_m,\n"
               "residual_b, residual_m}, slid_before_rocking, slid_off}, the analytic run's friction_needed {base, hinge}\n"
               "and would_slide {base, hinge} (docs/guide/program.md, \"Finite friction\"); without a ground motion each\n"
               "engine's free_vibration_slip {base, hinge, tolerance_b, t_first_slip, t_first_lift, slid_before_rocking,\n"
               "slid_off}.\n\n"
               "Every backend's settings in this build (--list-settings prints them alone):\n\n") +
               settings_listing({}, false);
    });
    return {cmd, [o](std::ostream& out) { run_compare(*o, out); }};
}

}  // namespace vssw::cli

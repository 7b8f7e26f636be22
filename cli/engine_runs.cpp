#include "cli/engine_runs.hpp"

#include <cmath>
#include <limits>
#include <ostream>
#include <utility>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "cli/history_output.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/table.hpp"
#include "compare/experiments.hpp"
#include "compare/metrics.hpp"
#include "compare/response.hpp"
#include "multibody/host/engine_names.hpp"
#include "multibody/kit/settings_reader.hpp"

namespace vssw::cli {
namespace {

// The free vibration lasts as the paper's model's does (until rest, past every impact it has): impacts enough that
// free_vibration_duration gives 1.25 times its time to rest (or to overturning).
constexpr int kEveryImpact = std::numeric_limits<int>::max();

EngineRun engine_run(const std::string& command, const std::string& engine, const EngineSettingOptions& options,
                     ChosenModel chosen) {
    EngineRun run{command, multibody::make_engine(engine), {}, std::move(chosen), {}, {}, 0.0, {}, {}};
    run.settings = engine_settings_of(*run.engine, options);
    run.scene = multibody::WallScene(run.chosen.wall);
    multibody::require_settings_fit_wall(run.engine->display_name(), run.settings, run.engine->setting_descriptions(),
                                         run.scene);
    return run;
}

void set_sampling(EngineRun& run, double output_dt) {
    require(std::isfinite(output_dt) && output_dt > 0.0, "output interval (--output-dt) [s]",
            "a positive finite number", output_dt);
    run.settings.sample_dt = output_dt;
}

}  // namespace

void add_engine_choice(CLI::App& cmd, std::string& engine) {
    cmd.add_option("--engine", engine,
                   fmt::format("the backend that runs the wall: analytic (the model) or an engine, whose trajectory "
                               "the CSV holds (available: {}) (default analytic)",
                               fmt::join(multibody::available_engines(), ", ")));
}

bool names_analytic_model(const std::string& engine) {
    return multibody::canonical_engine(engine).value_or(engine) == "analytic";
}

void refuse_engine_settings(const CLI::App& cmd) {
    for (const char* name : {"--dt", "--iterations", "--set"})
        if (cmd.count(name) > 0)
            throw InputError(fmt::format("{} is an engine's setting: give --engine too (the analytic model's "
                                         "output interval is --output-dt)",
                                         name));
}

void refuse_analytic_options(const CLI::App& cmd, const std::vector<std::string>& names, const std::string& engine) {
    for (const std::string& name : names)
        if (cmd.count(name) > 0)
            throw InputError(fmt::format("--engine {} cannot honour {} (only the analytic model takes it): leave it "
                                         "out, or run the analytic model",
                                         engine, name));
}

EngineRun prepare_engine_free(const std::string& engine, const EngineSettingOptions& settings,
                              const WallOptions& wall, const ModelOptions& model, double r, double output_dt) {
    using compare::kMinRelease;
    EngineRun run = engine_run("free", engine, settings, choose_model(wall, model));
    require(std::isfinite(r) && r >= kMinRelease && r < 1.0, fmt::format("--theta0 with --engine {}", engine),
            fmt::format("from {:g} to below 1 (a fraction of alpha1, as vssw compare measures an engine's free "
                        "vibration)",
                        kMinRelease),
            r);
    set_sampling(run, output_dt);
    run.r = r;
    run.excitation.theta0 = r * run.scene.alpha();
    run.excitation.t_end = compare::free_vibration_duration(run.scene, run.excitation.theta0, kEveryImpact);
    compare::FreeVibrationOptions free;
    free.r = r;
    free.t_end = run.excitation.t_end;
    compare::require_free_vibration_steps(*run.engine, run.settings, run.scene, free);
    return run;
}

EngineRun prepare_engine_history(const std::string& engine, const EngineSettingOptions& settings,
                                 const WallOptions& wall, const ModelOptions& model, const GroundMotionOptions& motion,
                                 std::optional<double> output_dt, std::optional<double> t_end) {
    // The analytic run's preparation gives the motion, its end and its sampling, checked as they are there.
    HistoryRun history = prepare_history(wall, model, motion, {output_dt, t_end, true});
    EngineRun run = engine_run("history", engine, settings, std::move(history.chosen));
    set_sampling(run, history.options.output_dt);
    run.record = history.record;
    run.excitation.horizontal = history.input.motion;
    run.excitation.t_end = history.options.t_end;
    // The step against the motion's time scales is checked by the engine's run before it starts (isolated_engine.hpp).
    return run;
}

void simulate_engine_run(EngineRun& run) {
    try {
        run.trajectory = run.engine->simulate(run.scene, run.excitation, run.settings);
    } catch (const multibody::EngineFailure& e) {
        throw SimulationFailure(e.what());
    }
}

void write_engine_trajectory_csv(std::ostream& out, const EngineRun& run) {
    const RockingModel& model = *run.chosen.model;
    const double alpha = model.reference_angle(), v_ref = model.reference_velocity(), e_ref = model.reference_energy();
    const bool vssw = run.scene.is_vssw();
    out << kEngineCsvHeader << '\n';
    for (const multibody::TrajectorySample& s : run.trajectory.samples) {
        const double theta2 = vssw ? s.theta2 / alpha : 0.0;  // a parapet has no upper block
        out << fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{}\n", s.t, s.theta1 / alpha,
                           s.theta1_dot / v_ref, theta2, s.top_dy, (s.kinetic + s.potential) / e_ref,
                           run.excitation.horizontal(s.t) / vssw::kStandardGravity, s.contacts);
    }
}

io::Json to_json(const EngineRun& run) {
    const multibody::Trajectory& t = run.trajectory;
    const compare::Response response = compare::response_of(t, run.scene);
    const double alpha = run.chosen.model->reference_angle();
    io::Json j;
    j["engine"] = run.engine->name();
    j["version"] = run.engine->version();
    io::Json knobs = io::Json::object();
    for (const auto& [name, value] : run.settings.knobs) knobs[name] = value;
    j["settings"] = {{"dt", run.settings.dt}, {"iterations", run.settings.iterations}, {"knobs", knobs},
                     {"sample_dt", run.settings.sample_dt}};
    j["model"] = to_string(run.chosen.kind);
    j["alpha1"] = alpha;
    if (run.command == "free") {
        j["theta0"] = run.r;
        const std::vector<compare::ImpactMetric> impacts = compare::impacts(t);
        const std::optional<double> quarter = compare::quarter_period(t);
        j["first_impact_time"] = quarter ? io::Json(*quarter) : io::Json(nullptr);
        j["impact_count"] = impacts.size();
        io::Json times = io::Json::array();
        for (const compare::ImpactMetric& m : impacts) times.push_back(m.t);
        j["impact_times"] = times;
    } else {
        j["record"] = run.record ? io::Json(*run.record) : io::Json(nullptr);
        j["input"] = run.excitation.horizontal.name();
    }
    j["max_theta_over_alpha1"] = response.peak / alpha;
    j["t_max_theta"] = response.peak_time;
    j["overturned"] = response.overturned;
    j["t_overturn"] = response.t_overturn ? io::Json(*response.t_overturn) : io::Json(nullptr);
    j["at_rest_at_end"] = t.at_rest_at_end;
    j["end_time"] = t.samples.empty() ? 0.0 : t.samples.back().t;
    j["t_end"] = run.excitation.t_end;
    j["samples"] = t.samples.size();
    j["steps"] = t.steps;
    return j;
}

void print_engine_run(std::ostream& out, const EngineRun& run, const std::string& title) {
    const multibody::Trajectory& t = run.trajectory;
    const compare::Response response = compare::response_of(t, run.scene);
    const double alpha = run.chosen.model->reference_angle();
    Table table(fmt::format("{} by {} ({}, step {:g} s)", title, run.engine->display_name(), run.engine->version(),
                            run.settings.dt));
    if (run.command == "free") {
        table.add("release theta0/alpha1", fmt::format("{:g}", run.r));
        table.add("first impact", num_or(compare::quarter_period(t), "none"), "s", "a quarter period");
        table.add("impacts", fmt::format("{}", compare::impacts(t).size()));
    }
    table.add("max |theta1|/alpha1", num_or(response.peak / alpha, "none"));
    table.add("at", num_or(response.peak_time, "none"), "s");
    table.add("overturned", t.overturned ? "yes" : "no");
    table.add("at rest at the end", t.at_rest_at_end ? "yes" : "no");
    table.add("end of the run", num_or(t.samples.empty() ? 0.0 : t.samples.back().t, "none"), "s");
    table.add("engine steps", fmt::format("{}", t.steps));
    table.print(out);
}

void run_and_print_engine(std::ostream& out, std::ostream& err, TrajectoryCsv& csv, EngineRun& run, bool json,
                          const std::string& what, const WallOptions& wall) {
    simulate_engine_run(run);
    const std::string title = what + " of the " + describe_wall(wall, run.chosen.kind);
    csv.write_with(out, [&](std::ostream& to) { write_engine_trajectory_csv(to, run); });
    std::ostream& summary = csv.summary(out, err);
    if (json)
        summary << io::dump_json(to_json(run), 2) << '\n';
    else
        print_engine_run(summary, run, title);
}

}  // namespace vssw::cli

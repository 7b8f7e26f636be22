// vssw._core: the library behind the pure-Python package vssw/ (docs/guide/python.md).
//  - run(args): the vssw program's commands in-process, exactly what `vssw ARGS...` would give (vssw.cli). The GIL
//    stays held: a command may run an engine library in this process (`vssw bench` times them in-process, and ODE's
//    library is not re-entrant), and nothing in it calls back into Python.
//  - run_with_progress(args, progress): the same for `study` and `report`, the GIL released, the commands' progress
//    lines (cli/progress.hpp) handed to a Python callable instead of a terminal. Those commands make their engines
//    with make_engine(), whose engine-library runs are each a forked child (multibody/host/isolated_engine.hpp): nothing of
//    ODE's process-wide state is shared between two Python threads.
//  - simulate(...), compare(...): one backend's trajectory, one engine against the analytic model, over the library
//    (multibody/engine.hpp, compare/experiments.hpp), the GIL released around the runs for the same reason. The
//    Python layer names and documents every parameter; the checks are the library's, each message naming the value.
// The calls that release the GIL run their work through interruptible(): Ctrl-C raises KeyboardInterrupt within
// kInterruptionCheckS, their engine runs stopped, rather than when the whole call would have returned.
// Library errors reach Python as the package's own classes: vssw::InputError as vssw.InputError (a ValueError),
// multibody::EngineFailure as vssw.SimulationError (a RuntimeError).
#include <chrono>
#include <cmath>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "analytic/closed_forms.hpp"
#include "cli/build_commit.hpp"
#include "cli/cli.hpp"
#include "cli/compare_response.hpp"
#include "cli/friction_option.hpp"
#include "cli/ground_motion_options.hpp"
#include "cli/message_line.hpp"
#include "cli/progress.hpp"
#include "cli/wall_options.hpp"
#include "compare/experiments.hpp"
#include "compare/metrics.hpp"
#include "compare/response.hpp"
#include "compare/targets.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/host/child_process.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/engine_names.hpp"
#include "multibody/host/run_budget.hpp"

namespace py = pybind11;

namespace {

// The program's text as a Python str; bytes that are not UTF-8 (a file name given on the command line, echoed in a
// message) are replaced rather than raising a UnicodeDecodeError in place of the program's own message.
py::str text(const std::string& bytes) {
    PyObject* decoded = PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()), "replace");
    if (decoded == nullptr) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(decoded);
}

// A C argument ends at its first NUL: "4\0junk" would be read as 4. Refused as the program refuses bad input.
std::optional<py::tuple> refuse_nul(const std::vector<std::string>& args) {
    for (const std::string& arg : args)
        if (arg.find('\0') != std::string::npos)
            return py::make_tuple(vssw::cli::kExitBadInput, py::str(""),
                                  text("vssw: error: an argument holds a NUL character: '" +
                                       arg.substr(0, arg.find('\0')) + "\\0...'\n"));
    return std::nullopt;
}

int run_cli(const std::vector<std::string>& args, std::ostringstream& out, std::ostringstream& err) {
    std::vector<const char*> argv;
    argv.reserve(args.size() + 2);
    argv.push_back("vssw");
    for (const std::string& arg : args) argv.push_back(arg.c_str());
    argv.push_back(nullptr);  // argv[argc] is null, as for main()
    return vssw::cli::run(static_cast<int>(args.size() + 1), argv.data(), out, err);
}

py::tuple run(const std::vector<std::string>& args) {
    if (auto refused = refuse_nul(args)) return *refused;
    std::ostringstream out, err;
    const int code = run_cli(args, out, err);
    return py::make_tuple(code, text(out.str()), text(err.str()));
}

// Ctrl-C during a long call: the library's work runs on a thread of its own while this thread, the caller's, waits with
// the GIL released and looks for Python's signals every kInterruptionCheckS. A signal whose handler raises (Ctrl-C:
// KeyboardInterrupt) stops every engine run of the process (multibody::interrupt_children: a study ends as an
// interrupted one, its journal resumable), waits for the work to end and raises it. Python runs signal handlers on
// its main thread only: called from another thread, the call runs to its end as before.
template <class Work>
auto interruptible(Work work) -> decltype(work()) {
    auto done = std::async(std::launch::async, std::move(work));
    const std::chrono::duration<double> check(vssw::multibody::kInterruptionCheckS);
    for (;;) {
        {
            const py::gil_scoped_release released;
            if (done.wait_for(check) == std::future_status::ready) return done.get();
        }
        if (PyErr_CheckSignals() != 0) {
            vssw::multibody::interrupt_children(true);
            {
                const py::gil_scoped_release released;
                done.wait();
            }
            vssw::multibody::interrupt_children(false);
            throw py::error_already_set();
        }
    }
}

// `progress` (None or a callable (done, total, what)) is called from the command's threads, each call holding the
// GIL; the first exception it raises stops the command's engine runs as Ctrl-C does (interruptible: a study ends as
// an interrupted one, its journal resumable, no results written) and is raised from this call once the command has
// ended. The callable is not called again after it. Runs of the analytic model, in this process, finish (milliseconds
// each).
py::tuple run_with_progress(const std::vector<std::string>& args, const py::object& progress) {
    if (auto refused = refuse_nul(args)) return *refused;
    auto raised = std::make_shared<std::optional<py::error_already_set>>();
    vssw::cli::ProgressHook hook;
    if (!progress.is_none())
        hook = [progress, raised](long done, long total, const std::string& what) {
            const py::gil_scoped_acquire gil;
            if (raised->has_value()) return;
            try {
                progress(done, total, what);
            } catch (py::error_already_set& e) {
                raised->emplace(std::move(e));
                vssw::multibody::interrupt_children(true);  // no further engine run; those under way are stopped
            }
        };
    std::ostringstream out, err;
    const int code = interruptible([&] {
        const vssw::cli::ScopedProgressHook scoped(progress.is_none() ? nullptr : &hook);  // the command's thread's
        return run_cli(args, out, err);
    });
    if (raised->has_value()) {
        vssw::multibody::interrupt_children(false);
        throw **raised;
    }
    return py::make_tuple(code, text(out.str()), text(err.str()));
}

// The wall and the analytic model's assumptions as the Python functions take them.
struct WallArgs {
    std::string model;
    double height, thickness;
    std::optional<double> hinge;
    double xi, density, g;
    std::string assumptions;                                // a named set: paper | mechanism
    std::optional<std::string> kinematics, impact, roller;  // each overrides the set's
    double overburden_eccentricity = 0.0;  // e/b of N on the (upper) body's top face (analytic/geometry.hpp)
    double corner_radius = 0.0;            // r/b of every block corner (analytic/wall.hpp with_corner_radius)
    double diaphragm_period = 0.0;         // T_d [s] of the top support's diaphragm (analytic/diaphragm.hpp); 0 rigid
    double diaphragm_damping = vssw::kDefaultDiaphragmDamping;  // zeta_d
};

vssw::cli::ChosenModel chosen_model(const WallArgs& a) {
    vssw::cli::WallOptions w;
    w.height = a.height;
    w.thickness = a.thickness;
    w.hinge = a.hinge;
    w.xi = a.xi;
    w.density = a.density;
    w.g = a.g;
    w.eccentricity = a.overburden_eccentricity;
    w.corner_radius = a.corner_radius;
    w.diaphragm.period = a.diaphragm_period;
    w.diaphragm.damping = a.diaphragm_damping;
    vssw::cli::ModelOptions m;
    m.model = a.model;
    m.assumptions = a.assumptions;
    m.kinematics = a.kinematics;
    m.impact = a.impact;
    m.roller = a.roller;
    return vssw::cli::choose_model(w, m);
}

// The same wall under the default assumptions: what an engine's settings are built from (its physics is its own).
WallArgs with_default_assumptions(WallArgs wall) {
    wall.assumptions = vssw::to_string(vssw::kDefaultAssumptionSet);
    wall.kinematics = wall.impact = wall.roller = std::nullopt;
    return wall;
}

// The engine's settings: the analytic model's assumptions for "analytic", else the engine's defaults; then the step,
// the iterations and the knobs given, checked by the engine before anything runs.
vssw::multibody::EngineSettings settings_of(const vssw::multibody::Engine& engine,
                                            const vssw::cli::ChosenModel& chosen, std::optional<double> dt,
                                            std::optional<double> sample_dt, std::optional<int> iterations,
                                            const std::map<std::string, double>& knobs) {
    using vssw::require;
    vssw::multibody::EngineSettings s =
        engine.name() == "analytic"
            ? vssw::multibody::analytic_settings(chosen.assumptions)
            : engine.default_settings();
    if (dt) {
        // dt is an engine's step; the analytic model takes none of a fixed size (its output interval is sample_dt).
        if (engine.name() == "analytic")
            throw vssw::InputError(fmt::format(
                "dt {}: the analytic model takes no fixed step (its integrator chooses its steps to its tolerance, "
                "settings={{'rtol': ...}}); its output interval is vssw.simulate's sample_dt", *dt));
        require(std::isfinite(*dt) && *dt > 0.0, "dt (engine step, s)", "a positive finite number", *dt);
        s.dt = *dt;
    }
    if (sample_dt) {
        require(std::isfinite(*sample_dt) && *sample_dt >= 0.0, "sample_dt (trajectory sampling, s)",
                "a finite number >= 0 (0: every step)", *sample_dt);
        s.sample_dt = *sample_dt;
    }
    if (iterations) {
        require(*iterations >= 1 && *iterations <= vssw::multibody::kMaxIterations, "iterations",
                fmt::format("a whole number from 1 to {}", vssw::multibody::kMaxIterations), *iterations);
        s.iterations = *iterations;
    }
    for (const auto& [name, value] : knobs) {
        if (!std::isfinite(value))
            throw vssw::InputError(fmt::format("settings['{}']: '{}' is not a finite number", name, value));
        s.knobs[name] = value;
    }
    engine.check_settings(s);
    return s;
}

// A budget for every engine run of one call (multibody/host/run_budget.hpp), the previous one restored afterwards.
class ScopedRunBudget {
public:
    explicit ScopedRunBudget(std::optional<double> seconds) : previous_(vssw::multibody::RunBudget::given()) {
        if (seconds) vssw::multibody::RunBudget::set(seconds);
        set_ = seconds.has_value();
    }
    ~ScopedRunBudget() {
        if (set_) vssw::multibody::RunBudget::set(previous_);
    }
    ScopedRunBudget(const ScopedRunBudget&) = delete;
    ScopedRunBudget& operator=(const ScopedRunBudget&) = delete;

private:
    std::optional<double> previous_;
    bool set_ = false;
};

py::array_t<double> column(const std::vector<vssw::multibody::TrajectorySample>& samples,
                           double vssw::multibody::TrajectorySample::*field) {
    py::array_t<double> a(static_cast<py::ssize_t>(samples.size()));
    auto view = a.mutable_unchecked<1>();
    for (std::size_t i = 0; i < samples.size(); ++i) view(static_cast<py::ssize_t>(i)) = samples[i].*field;
    return a;
}

py::dict settings_dict(const vssw::multibody::EngineSettings& s) {
    py::dict d;
    d["dt"] = s.dt;
    d["iterations"] = s.iterations;
    d["sample_dt"] = s.sample_dt;
    d["knobs"] = s.knobs;
    return d;
}

py::list impacts_list(const std::vector<vssw::compare::ImpactMetric>& impacts) {
    py::list l;
    for (const auto& i : impacts) {
        py::dict d;
        d["t"] = i.t;
        d["theta_dot_before"] = i.theta_dot_before;
        d["theta_dot_after"] = i.theta_dot_after;
        d["ratio"] = i.ratio;
        d["resolved"] = i.resolved;
        l.append(d);
    }
    return l;
}

// The wall as the model built it, for drawing it (python/vssw/_plot.py): the paper's half dimensions [m] (b, h1, h2
// of a VSSW, h2 None for a parapet, whose h is h1), alpha1 and alpha2 [rad], xi and N [N/m], N's e/b and the
// corners' r/b (analytic/geometry.hpp).
py::dict geometry_dict(const vssw::Wall& wall) {
    py::dict d;
    d["model"] = wall.is_vssw() ? "vssw" : "parapet";
    if (wall.is_vssw()) {
        const vssw::VsswGeometry& w = *wall.vssw;
        d["b"] = w.b;
        d["h1"] = w.h1;
        d["h2"] = w.h2;
        d["alpha1"] = w.alpha1;
        d["alpha2"] = w.alpha2;
        d["xi"] = w.xi;
    } else {
        const vssw::ParapetGeometry& p = *wall.parapet;
        d["b"] = p.b;
        d["h1"] = p.h;
        d["h2"] = py::none();
        d["alpha1"] = p.alpha;
        d["alpha2"] = py::none();
        d["xi"] = p.xi;
    }
    d["N"] = wall.overburden();
    d["overburden_eccentricity"] = wall.overburden_eccentricity();
    d["corner_radius"] = wall.corner_radius_ratio();
    return d;
}

// A sample this close to a time of the grid (relative to its interval) is taken at it: an engine's sample is at its
// step i * dt, which differs from k * sample_dt by rounding only.
constexpr double kOnGridTolerance = 1e-9;

// The samples at t = k * sample_dt, their times set to exactly that (one time grid for every backend): an engine's
// last sample, taken where its run ended (at rest, overturned) between two times of the grid, is left out.
std::vector<vssw::multibody::TrajectorySample> on_grid(std::vector<vssw::multibody::TrajectorySample> samples,
                                                       double sample_dt) {
    std::vector<vssw::multibody::TrajectorySample> kept;
    for (vssw::multibody::TrajectorySample& p : samples) {
        const double k = std::round(p.t / sample_dt);
        if (std::abs(p.t - k * sample_dt) > kOnGridTolerance * sample_dt) continue;
        if (!kept.empty() && k * sample_dt <= kept.back().t) continue;
        p.t = k * sample_dt;
        kept.push_back(p);
    }
    return kept;
}

// sample_dt on an engine of a fixed step: a whole number of its steps, else no sample would fall on the grid.
void require_whole_steps(const vssw::multibody::Engine& engine, const vssw::multibody::EngineSettings& s) {
    if (engine.name() == "analytic" || s.sample_dt <= 0.0) return;
    const double steps = std::round(s.sample_dt / s.dt);
    if (steps < 1.0 || std::abs(steps * s.dt - s.sample_dt) > kOnGridTolerance * s.sample_dt)
        throw vssw::InputError(fmt::format("sample_dt {:g} s is not a whole number of {}'s steps (dt {:g} s): give a "
                                           "multiple of dt, or a dt that divides sample_dt",
                                           s.sample_dt, engine.name(), s.dt));
}

// A trajectory as NumPy arrays (one per sample field, from `samples`: the run's, or those on the time grid) and what
// the metrics code reads from the whole run.
py::dict trajectory_dict(const vssw::multibody::Trajectory& traj,
                         const std::vector<vssw::multibody::TrajectorySample>& samples,
                         const vssw::GroundMotion& motion) {
    using Sample = vssw::multibody::TrajectorySample;
    py::dict d;
    d["t"] = column(samples, &Sample::t);
    d["theta1"] = column(samples, &Sample::theta1);
    d["theta1_dot"] = column(samples, &Sample::theta1_dot);
    d["theta2"] = column(samples, &Sample::theta2);
    d["top_dy"] = column(samples, &Sample::top_dy);
    d["kinetic"] = column(samples, &Sample::kinetic);
    d["potential"] = column(samples, &Sample::potential);
    py::array_t<int> contacts(static_cast<py::ssize_t>(samples.size()));
    py::array_t<double> ground(static_cast<py::ssize_t>(samples.size()));
    auto c = contacts.mutable_unchecked<1>();
    auto a = ground.mutable_unchecked<1>();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        c(static_cast<py::ssize_t>(i)) = samples[i].contacts;
        a(static_cast<py::ssize_t>(i)) = motion(samples[i].t);
    }
    d["contacts"] = contacts;
    d["ground_acceleration"] = ground;
    d["overturned"] = traj.overturned;
    d["at_rest_at_end"] = traj.at_rest_at_end;
    d["steps"] = traj.steps;
    d["warnings"] = traj.warnings;
    const auto impacts = vssw::compare::impacts(traj);
    d["impacts"] = impacts_list(impacts);
    py::list peaks;
    for (const auto& p : vssw::compare::peaks(traj)) peaks.append(py::make_tuple(p.t, p.theta));
    d["peaks"] = peaks;
    const auto quarter = vssw::compare::quarter_period(traj);
    d["period"] = quarter ? py::cast(4.0 * *quarter) : py::none();
    d["max_abs_theta1"] = vssw::compare::max_abs_theta(traj);
    return d;
}

// The whole wall's slenderness atan(b/h) (a study's `alpha`, Fig. 10's; study/grid.cpp computes it alike): alpha1
// of a VSSW is its lower block's.
double wall_alpha(const vssw::multibody::WallScene& scene) {
    return scene.vssw ? std::atan(scene.vssw->b / scene.vssw->h()) : scene.parapet->alpha;
}

py::dict simulate(const std::string& engine_name, const WallArgs& wall, double theta0, std::optional<double> t_end,
                  std::optional<double> dt, std::optional<double> sample_dt, std::optional<int> iterations,
                  const std::map<std::string, double>& knobs, const vssw::cli::GroundMotionOptions& motion_options,
                  bool stop_at_rest, std::optional<double> friction, std::optional<double> run_budget) {
    using vssw::require;
    if (engine_name != "analytic" && (wall.assumptions != vssw::to_string(vssw::kDefaultAssumptionSet) ||
                                      wall.kinematics || wall.impact || wall.roller))
        throw vssw::InputError(fmt::format(
            "assumptions, kinematics, impact and roller are the analytic model's; engine '{}' realises its own "
            "physics (its settings are its knobs: vssw.engine_settings('{}'))",
            engine_name, engine_name));
    const vssw::cli::ChosenModel chosen = chosen_model(wall);
    vssw::multibody::WallScene scene(chosen.wall);
    if (friction) {
        require(std::isfinite(*friction) && *friction > 0.0, "friction", "a positive finite coefficient", *friction);
        scene.friction = *friction;
        scene.slip_measured = true;  // the user's friction: sliding is measured (multibody/engine.hpp)
    }
    const bool shaken = motion_options.record || motion_options.pulse;
    vssw::multibody::Excitation ex;
    if (shaken) ex.horizontal = vssw::cli::load_ground_motion(motion_options).motion;
    require(std::isfinite(theta0) && std::abs(theta0) < 1.0, "theta0 (release from rest, a fraction of alpha)",
            "a number from -1 to 1, both excluded", theta0);
    if (!shaken && theta0 == 0.0)
        throw vssw::InputError("nothing moves the wall: give a release theta0 (a fraction of alpha) or a ground "
                               "motion (record= or pulse=)");
    ex.theta0 = theta0 * scene.alpha();
    if (t_end) {
        require(std::isfinite(*t_end) && *t_end > 0.0, "t_end (s)", "a positive finite number", *t_end);
        ex.t_end = *t_end;
    } else {
        // As vssw compare runs them: a free vibration long enough for the analytic model's impacts that
        // FreeVibrationOptions shows (8), a response the motion and kResponseTail.
        const int impacts = vssw::compare::FreeVibrationOptions{}.impacts;
        ex.t_end = shaken ? ex.horizontal.duration() + vssw::compare::kResponseTail
                          : vssw::compare::free_vibration_duration(scene, ex.theta0, impacts);
    }
    ex.stop_at_rest = stop_at_rest;
    const std::unique_ptr<vssw::multibody::Engine> engine = vssw::multibody::make_engine(engine_name);
    const vssw::multibody::EngineSettings settings = settings_of(*engine, chosen, dt, sample_dt, iterations, knobs);
    require_whole_steps(*engine, settings);
    const ScopedRunBudget budget(run_budget);
    vssw::multibody::Trajectory traj;
    if (engine->runs_concurrently()) {  // every backend make_engine() gives; one that is not keeps the GIL
        traj = interruptible([&] { return engine->simulate(scene, ex, settings); });
    } else {
        traj = engine->simulate(scene, ex, settings);
    }
    const bool grid = sample_dt && *sample_dt > 0.0;
    py::dict d = trajectory_dict(traj, grid ? on_grid(traj.samples, *sample_dt) : traj.samples, ex.horizontal);
    d["engine"] = engine->name();
    d["version"] = engine->version();
    py::dict used = settings_dict(settings);
    if (engine->name() == "analytic") {  // no step of its own: its dt is the output interval, sample_dt's
        used["sample_dt"] = settings.sample_dt > 0.0 ? settings.sample_dt : settings.dt;
        used["dt"] = py::none();
    }
    d["settings"] = used;
    d["alpha1"] = scene.alpha();
    d["alpha"] = wall_alpha(scene);
    d["geometry"] = geometry_dict(scene);
    // The measures a study, `vssw compare --record` and the report give this run (compare/response.hpp).
    const vssw::compare::Response response = vssw::compare::response_of(traj, scene);
    d["peak_rotation"] = response.peak / scene.alpha();
    d["peak_time"] = response.peak_time;
    d["theta0"] = ex.theta0;
    d["t_end"] = ex.t_end;
    d["assumptions"] = engine_name == "analytic" ? py::cast(chosen.set_name()) : py::none();
    d["kinematics"] = engine_name == "analytic" && chosen.kinematics()
                          ? py::cast(chosen.kinematics() == vssw::Kinematics::exact ? "exact" : "paper")
                          : py::none();
    d["ground_motion"] = shaken ? py::cast(ex.horizontal.name()) : py::none();
    d["slip"] = py::none();
    if (traj.slip) {  // the engines' measured sliding, friction given: `vssw compare --friction --json`'s slip
        py::dict slip = py::module_::import("json").attr("loads")(
            vssw::io::dump_json(vssw::cli::slip_json(*traj.slip, scene.vssw.has_value())));
        slip["b"] = traj.slip->b;  // [m]: the unit of the *_b values
        d["slip"] = slip;
    }
    return d;
}

py::dict metric(const vssw::compare::MetricComparison& m, double target) {
    py::dict d;
    d["value"] = m.engine;
    d["reference"] = m.analytic;
    d["rel_error"] = m.rel_error;
    d["target"] = target;
    return d;
}

py::dict compare(const std::string& engine_name, const WallArgs& wall, double theta0, std::optional<double> dt,
                 std::optional<int> iterations, const std::map<std::string, double>& knobs,
                 std::optional<double> run_budget) {
    using vssw::require;
    const vssw::cli::ChosenModel chosen = chosen_model(wall);
    const vssw::multibody::WallScene scene(chosen.wall);
    require(std::isfinite(theta0) && theta0 >= vssw::compare::kMinRelease && theta0 < 1.0,
            "theta0 (release for the period and restitution, a fraction of alpha)",
            fmt::format("from {:g} to below 1", vssw::compare::kMinRelease), theta0);
    vssw::compare::ComparisonOptions options;
    options.reference = vssw::multibody::analytic_settings(chosen.assumptions);
    const std::unique_ptr<vssw::multibody::Engine> engine = vssw::multibody::make_engine(engine_name);
    // The engine's own settings: the analytic model's assumptions belong to the reference, not to the engine.
    vssw::cli::ChosenModel engine_model = chosen_model(with_default_assumptions(wall));
    const vssw::multibody::EngineSettings settings =
        settings_of(*engine, engine_model, dt, std::nullopt, iterations, knobs);
    const ScopedRunBudget budget(run_budget);
    vssw::compare::EngineComparison c;
    if (engine->runs_concurrently()) {
        c = interruptible(
            [&] { return vssw::compare::compare_with_analytic(*engine, settings, scene, theta0, options); });
    } else {
        c = vssw::compare::compare_with_analytic(*engine, settings, scene, theta0, options);
    }
    py::dict d;
    d["engine"] = engine->name();
    d["version"] = engine->version();
    d["settings"] = settings_dict(settings);
    d["theta0"] = theta0;
    d["threshold"] = metric(c.threshold_g, vssw::compare::kThresholdTarget);
    d["period"] = metric(c.period, vssw::compare::kPeriodTarget);
    d["restitution"] = metric(c.restitution, vssw::compare::kRestitutionTarget);
    d["restitution_amplitude"] = metric(c.restitution_amplitude, vssw::compare::kRestitutionTarget);
    py::dict closed;
    closed["threshold_g"] = c.threshold_closed_form_g;
    closed["restitution"] = c.restitution_closed_form;
    closed["restitution_whole_mechanism"] = scene.vssw ? vssw::restitution_whole_mechanism(*scene.vssw)
                                                       : vssw::housner_restitution(scene.parapet->alpha);
    closed["period_linearised"] = c.period_linearised;
    d["closed_forms"] = closed;
    d["threshold_trials"] = py::make_tuple(c.analytic_threshold.trials, c.engine_threshold.trials);
    d["impacts"] = py::make_tuple(c.analytic_impacts, c.engine_impacts);
    d["failures"] = c.failures;
    d["analytic_warnings"] = c.analytic_warnings;
    return d;
}

// Engines and the analytic model from rest under one ground motion (`vssw compare --record|--pulse`): the reference's
// run and the engines' in order, each as a dict (vssw.ResponseRun's fields).
py::dict compare_response(const std::vector<std::string>& engine_names, const WallArgs& wall,
                          const vssw::cli::GroundMotionOptions& motion_options, std::optional<double> dt,
                          std::optional<int> iterations, const std::map<std::string, double>& knobs,
                          std::optional<double> run_budget) {
    const vssw::cli::ChosenModel chosen = chosen_model(wall);
    // The engines' own settings: the analytic model's assumptions belong to the reference, as in compare().
    const vssw::cli::ChosenModel engine_model = chosen_model(with_default_assumptions(wall));
    std::vector<vssw::study::ResponseEngine> engines;
    bool concurrent = true;  // every engine may run beside another thread's (else the GIL serialises them, as compare)
    for (const std::string& name : engine_names) {
        const std::unique_ptr<vssw::multibody::Engine> e = vssw::multibody::make_engine(name);
        engines.push_back({name, settings_of(*e, engine_model, dt, std::nullopt, iterations, knobs)});
        concurrent = concurrent && e->runs_concurrently();
    }
    const ScopedRunBudget budget(run_budget);
    vssw::study::ResponseComparison result;
    if (concurrent)
        result = interruptible([&] { return vssw::cli::compare_under_motion(chosen, motion_options, engines); });
    else
        result = vssw::cli::compare_under_motion(chosen, motion_options, engines);
    py::list runs;
    py::object reference_run = py::none();
    for (const vssw::study::ResponseRun& r : result.runs) {
        py::dict d;
        d["engine"] = r.engine;
        d["version"] = r.version;
        d["settings"] = r.settings;
        d["peak"] = r.peak;
        d["peak_time"] = r.peak_time;
        d["overturned"] = std::isfinite(r.overturned) ? py::cast(r.overturned == 1.0) : py::none();
        d["t_overturn"] = r.t_overturn;
        d["status"] = r.status;
        d["warnings"] = r.warnings;
        if (r.engine == "analytic") reference_run = d;
        else runs.append(d);
    }
    // compare_response leaves the reference out when its assumptions are not a model; choose_model refuses the one
    // such set known today (the paper's kinematics with the unilateral roller) before this. Kept for any other: an
    // engine's peak would have nothing to be compared with.
    if (reference_run.is_none())
        throw vssw::InputError("the analytic reference did not run (its assumptions are not a model): give other "
                               "assumptions, kinematics, impact or roller");
    const vssw::study::CaseSpec& c = result.the_case;
    py::dict out;
    out["ground_motion"] = c.file.empty() ? fmt::format("{} pulse, amplitude {} g, period {} s", c.shape,
                                                        c.amplitude_g, c.pulse_period)
                                          : fmt::format("{} scaled by {:.6g} (PGA {:.4g} g)", c.file, c.scale, c.pga_g);
    out["reference"] = reference_run;
    out["runs"] = runs;
    return out;
}

py::list engine_settings(const std::string& engine_name) {
    const std::unique_ptr<vssw::multibody::Engine> engine = vssw::multibody::make_engine(engine_name);
    py::list l;
    for (const auto& s : engine->setting_descriptions()) {
        py::dict d;
        d["name"] = s.name;
        d["default"] = s.default_value;
        d["unit"] = s.unit;
        d["meaning"] = s.meaning;
        d["min"] = s.lo;
        d["max"] = s.hi;
        d["walls"] = vssw::multibody::walls_of(s);  // "vssw", "parapet" or "any"
        l.append(d);
    }
    return l;
}

// Raises `name` of the vssw package (InputError, SimulationError) with the library's message, as the Python layer
// raises it for the program's errors: Error(message, code, stderr).
// The message as the program prints it (cli/message_line.hpp): an input's control characters and bytes that are not
// UTF-8 escaped, so that it is a valid str and shows nothing a terminal would act on.
void raise_package_error(const char* name, int code, const char* message) {
    const py::object cls = py::module_::import("vssw").attr(name);
    const py::object exc = cls(vssw::cli::message_text(message), code, "");
    PyErr_SetObject(cls.ptr(), exc.ptr());
}

}  // namespace

// The ground motion as the Python functions take it (record= with scale= or pga=, or pulse= with its parameters).
// record_samples: (times [s], accelerations [g]) when the record was given as arrays (vssw/_api.py has checked them),
// `record` then its name; read as a two-column file of the same numbers is (analytic/ground_motion.cpp).
using RecordSamples = std::optional<std::pair<std::vector<double>, std::vector<double>>>;

vssw::cli::GroundMotionOptions motion_options(std::optional<std::string> record, const RecordSamples& record_samples,
                                              std::optional<double> scale, std::optional<double> pga,
                                              std::optional<std::string> pulse, std::optional<double> amplitude,
                                              std::optional<double> pulse_period, std::optional<double> duration) {
    vssw::cli::GroundMotionOptions motion;
    if (record_samples) {
        const double factor = vssw::to_m_per_s2(vssw::AccelUnits::g);
        std::vector<double> accel;
        accel.reserve(record_samples->second.size());
        for (double a : record_samples->second) accel.push_back(a * factor);
        motion.samples = vssw::GroundMotion::sampled(record_samples->first, std::move(accel), record.value_or("array"));
    }
    motion.record = std::move(record);
    motion.scale = scale;
    motion.pga_g = pga;
    motion.pulse = std::move(pulse);
    motion.amplitude_g = amplitude;
    motion.pulse_period = pulse_period;
    motion.duration = duration;
    return motion;
}

PYBIND11_MODULE(_core, m) {
    m.doc() = "The library behind the vssw package (use the vssw package, not this module).";
    m.def("run", &run, py::arg("args"),
          "Runs `vssw ARGS...` in this process: returns (exit code, standard output, standard error). Never raises "
          "for the program's own errors: they are the exit code and the stderr line.");
    m.def("run_with_progress", &run_with_progress, py::arg("args"), py::arg("progress"),
          "run(args) with the GIL released and the command's progress lines given to progress(done, total, what).");
    py::class_<WallArgs>(m, "WallArgs")
        .def(py::init<std::string, double, double, std::optional<double>, double, double, double, std::string,
                      std::optional<std::string>, std::optional<std::string>, std::optional<std::string>, double,
                      double, double, double>(),
             py::arg("model"), py::arg("height"), py::arg("thickness"), py::arg("hinge"), py::arg("xi"),
             py::arg("density"), py::arg("g"), py::arg("assumptions"), py::arg("kinematics"), py::arg("impact"),
             py::arg("roller"), py::arg("overburden_eccentricity") = 0.0, py::arg("corner_radius") = 0.0,
             py::arg("diaphragm_period") = 0.0, py::arg("diaphragm_damping") = vssw::kDefaultDiaphragmDamping);
    m.def(
        "simulate",
        [](const std::string& engine, const WallArgs& wall, double theta0, std::optional<double> t_end,
           std::optional<double> dt, std::optional<double> sample_dt, std::optional<int> iterations,
           const std::map<std::string, double>& knobs, std::optional<std::string> record,
           const RecordSamples& record_samples, std::optional<double> scale, std::optional<double> pga,
           std::optional<std::string> pulse, std::optional<double> amplitude, std::optional<double> pulse_period,
           std::optional<double> duration, bool stop_at_rest, std::optional<double> friction,
           std::optional<double> run_budget) {
            const auto motion = motion_options(std::move(record), record_samples, scale, pga, std::move(pulse),
                                               amplitude, pulse_period, duration);
            return simulate(engine, wall, theta0, t_end, dt, sample_dt, iterations, knobs, motion, stop_at_rest,
                            friction, run_budget);
        },
        py::arg("engine"), py::arg("wall"), py::arg("theta0"), py::arg("t_end"), py::arg("dt"), py::arg("sample_dt"),
        py::arg("iterations"), py::arg("knobs"), py::arg("record"), py::arg("record_samples"), py::arg("scale"),
        py::arg("pga"), py::arg("pulse"), py::arg("amplitude"), py::arg("pulse_period"), py::arg("duration"),
        py::arg("stop_at_rest"), py::arg("friction"), py::arg("run_budget"),
        "One backend's run (vssw.simulate documents the arguments): the trajectory's arrays and what it measured.");
    m.def("compare", &compare, py::arg("engine"), py::arg("wall"), py::arg("theta0"), py::arg("dt"),
          py::arg("iterations"), py::arg("knobs"), py::arg("run_budget"),
          "One engine against the analytic model (vssw.compare documents the arguments).");
    m.def(
        "compare_response",
        [](const std::vector<std::string>& engines, const WallArgs& wall, std::optional<std::string> record,
           const RecordSamples& record_samples, std::optional<double> scale, std::optional<double> pga,
           std::optional<std::string> pulse, std::optional<double> amplitude, std::optional<double> pulse_period,
           std::optional<double> duration, std::optional<double> dt, std::optional<int> iterations,
           const std::map<std::string, double>& knobs, std::optional<double> run_budget) {
            const auto motion = motion_options(std::move(record), record_samples, scale, pga, std::move(pulse),
                                               amplitude, pulse_period, duration);
            return compare_response(engines, wall, motion, dt, iterations, knobs, run_budget);
        },
        py::arg("engines"), py::arg("wall"), py::arg("record"), py::arg("record_samples"), py::arg("scale"),
        py::arg("pga"), py::arg("pulse"),
        py::arg("amplitude"), py::arg("pulse_period"), py::arg("duration"), py::arg("dt"), py::arg("iterations"),
        py::arg("knobs"), py::arg("run_budget"),
        "Engines and the analytic model from rest under one ground motion (vssw.compare with record= or pulse=).");
    m.def("engine_settings", &engine_settings, py::arg("engine"), "Every setting of one backend.");
    m.def("available_engines", &vssw::multibody::available_engines, "The backends of this build.");
    m.def("canonical_engine", &vssw::multibody::canonical_engine, py::arg("name"),
          "The backend of this build a name means (\"ODE\", \"Simbody-Rigid\": ode, simbody-rigid), None when none.");
    m.def("engine_name_hint", &vssw::multibody::engine_name_hint, py::arg("name"),
          "The end of a message refusing an engine's name: \" (did you mean 'mujoco'?)\" for the backend nearest to it, "
          "else empty.");
    m.def("default_compared_engines", &vssw::multibody::default_compared_engines,
          "The engines `all` stands for (every engine but the analytic model and simbody-rigid).");
    m.def("data_dir", &vssw::shipped_data_dir, "The shipped data folder (records, Table 1).");
    m.attr("VERSION") = VSSW_VERSION;
    m.attr("COMMIT") = vssw::cli::build_commit();
    m.attr("EXIT_OK") = vssw::cli::kExitOk;
    m.attr("EXIT_OUT_OF_BOUNDS") = vssw::cli::kExitOutOfBounds;
    m.attr("EXIT_BAD_INPUT") = vssw::cli::kExitBadInput;
    m.attr("EXIT_SIMULATION_FAILED") = vssw::cli::kExitSimulationFailed;
    // The analytic model's default assumption set, the same in the module as in every command.
    m.attr("DEFAULT_ASSUMPTIONS") = vssw::to_string(vssw::kDefaultAssumptionSet);
    m.attr("DEFAULT_DIAPHRAGM_DAMPING") = vssw::kDefaultDiaphragmDamping;
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const vssw::InputError& e) {
            raise_package_error("InputError", vssw::cli::kExitBadInput, e.what());
        } catch (const vssw::multibody::EngineFailure& e) {
            raise_package_error("SimulationError", vssw::cli::kExitSimulationFailed, e.what());
        }
    });
}

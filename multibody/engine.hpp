#pragma once
// One interface for every way of simulating a wall: the analytic model and each rigid-body engine. A backend gets the
// wall as the analytic core describes it (nothing about a wall is typed twice), an excitation and its settings, and
// returns a trajectory sampled in one format, which compare/ measures with one piece of code whatever produced it.
//
// Conventions shared by every backend (so trajectories are comparable sample by sample):
//  - the wall lies in the x-y plane, y up, its centreline on x = 0 at rest, base on the ground at y = 0;
//  - theta1 is the lower body's rotation, positive CLOCKWISE (the wall tipping towards +x about its corner (+b, 0)),
//    which is the analytic model's sign: a positive ground acceleration a_h (along +x) tips it towards theta1 < 0;
//  - theta2 is the upper body's rotation in the same sense (negative while theta1 > 0, Eq. 2);
//  - top_dy is the vertical displacement of the centre of the top face from rest (the roller lets it rise).
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "analytic/ground_motion.hpp"
#include "analytic/wall.hpp"
#include "analytic/wall_scene.hpp"

namespace vssw::multibody {

// The wall an engine builds: the analytic description (analytic/wall_scene.hpp: exactly one of a VSSW and a parapet)
// and the friction of the contacts, which only the engines have (the analytic model assumes no sliding).
struct WallScene : Wall {
    // Coulomb friction at the ground and at the hinge: high enough that nothing slides (sliding is reported).
    double friction = 2.0;
    // Finite friction given by the user (docs/model/analytic-core.md "Finite friction"): the hinge's coefficient when
    // it differs from `friction` (which is then the base's), and whether sliding is a measured response (Trajectory::
    // slip) rather than a failed run. Unset: the default friction, where a slide is still a failure (a bug).
    std::optional<double> hinge_friction;
    bool slip_measured = false;
    double base_mu() const { return friction; }
    double hinge_mu() const { return hinge_friction.value_or(friction); }

    static WallScene of(const VsswGeometry& w) { return WallScene(Wall::of(w)); }
    static WallScene of(const ParapetGeometry& p) { return WallScene(Wall::of(p)); }
    WallScene() = default;
    explicit WallScene(const Wall& wall) : Wall(wall) {}
};

// How the run starts and what shakes it.
struct Excitation {
    GroundMotion horizontal = GroundMotion::none();  // a_h(t), m/s^2, along +x
    double theta0 = 0.0;      // release from rest at this rotation of the lower body [rad]
    double t_end = 10.0;      // [s]
    bool stop_at_rest = true;  // end the run once the wall is at rest and the shaking can no longer lift it (RunMonitor)
    // > 0: end the run once |theta1| reaches this angle [rad] (a threshold trial needs to know no more than that).
    double stop_angle = 0.0;
    // true: the caller reads the lower body's motion alone (t, theta1, theta1_dot: all that compare/ and study/
    // measure), so the samples' theta2, top_dy, kinetic and potential are not computed (NaN; contacts 0). On the
    // analytic model those fields were three quarters of a sampled run's instructions (docs/measurements/speed.md).
    bool motion_only = false;
};

// Solver iterations a caller may ask of an engine (`vssw compare --iterations`, a study's settings): Bullet's
// sequential-impulse iterations per step (default 10; 100 changes nothing measured, docs/contributing/engines.md
// "Bullet"), Box2D's velocity iterations (default 8), MuJoCo's Newton iterations and Siconos's Gauss-Seidel sweeps (at
// most; defaults 100 and 1000), ODE's quickstep iterations (default 20); unused by DART, Simbody and the analytic
// model (each engine's `--list-settings` says). The cost grows linearly with them; 1000, 50 times a default of 20,
// still ends a compare in minutes rather than days.
constexpr int kMaxIterations = 1000;

// Engine settings: the step and the solver's knobs. Every adapter documents its defaults and why (docs/contributing/engines.md).
struct EngineSettings {
    double dt = 1e-4;        // engine step [s]
    int iterations = 0;      // solver iterations (0: the adapter's default)
    std::map<std::string, double> knobs;  // engine-specific options by name (each adapter lists its own)
    double sample_dt = 0.0;  // trajectory sampling [s]; 0: every step

    // A setting by the name a study or suite file gives it: "dt" the step, "iterations" the solver iterations (a whole
    // number, checked by the file's reader), any other name a knob. The one place that turns (name, value) into
    // settings for the files; the command line gives dt and iterations as their own options, every --set a knob.
    void set(const std::string& name, double value) {
        if (name == "dt") dt = value;
        else if (name == "iterations") iterations = static_cast<int>(value);
        else knobs[name] = value;
    }
};

// One setting of a backend as `vssw compare --list-settings` prints it. "dt" and "iterations" are given as --dt and
// --iterations (EngineSettings::dt and ::iterations); every other name is a knob, given as --set NAME=VALUE.
struct SettingDescription {
    std::string name;
    // As typed on the command line ("0.2", "1e-10", "inf"; a switch "0" or "1"), or words when the default is not one
    // number ("Eq. (19)", "none"). A number here is the value the backend uses when the setting is not given (the
    // test SettingDescriptions.EveryNumericDefaultIsTheDefaultInUse holds it).
    std::string default_value;
    std::string unit;     // "s", "m", "m/s", "Pa", ...; "" when dimensionless; "0/1" for a switch; "choice" for 0, 1, ...
    std::string meaning;  // one line
    // The documented range of a knob, both ends included: a value outside it is refused (InputError naming it) before
    // the engine library sees it (SettingsReader). Each range holds every value the settings were measured at with a
    // wide margin and stops where the library aborts, hangs or gives nothing a wall could mean
    // (docs/contributing/engines.md "Isolation": an ODE margin of 1e308 aborted the process). Unbounded by default; dt
    // and iterations are checked on their own.
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    // A setting for the single block only: any value but its default is refused for a VSSW, with the other settings
    // before anything runs (require_settings_fit_wall in settings_reader.hpp).
    bool parapet_only = false;
    // A setting for the two-block wall only (its roller, its hinge): any value but its default is refused for a
    // parapet, the same way.
    bool vssw_only = false;
};

// "[0, 1]", "[1e-06, 1]", "any" for an unbounded one: a range's ends (--list-settings prints the unit beside them).
std::string range_bounds_text(const SettingDescription& d);
// The same with the unit: "[1e-06, 1] m" (for messages).
std::string range_text(const SettingDescription& d);
// The walls a setting may be given for: "vssw" (vssw_only), "parapet" (parapet_only) or "any".
inline const char* walls_of(const SettingDescription& d) {
    return d.vssw_only ? "vssw" : d.parapet_only ? "parapet" : "any";
}

// dt and iterations are EngineSettings' own fields; every other setting an engine describes is one of its knobs.
inline bool is_knob(const std::string& setting_name) { return setting_name != "dt" && setting_name != "iterations"; }

struct TrajectorySample {
    double t, theta1, theta1_dot, theta2, top_dy;
    double kinetic, potential;  // [J/m] per unit depth (WallEnergy::fill divides an engine's by its depth)
    int contacts;               // contact points in use (0 for the analytic model)
};

// A sample of the motion alone (Excitation::motion_only): the fields not computed are NaN, so that nothing can read
// them as values.
inline TrajectorySample motion_sample(double t, double theta1, double theta1_dot) {
    constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();
    return {t, theta1, theta1_dot, kNotComputed, kNotComputed, kNotComputed, kNotComputed, 0};
}

// What a backend that locates its events by root finding knows beyond its samples: the analytic model's turning
// points and overturning, its energy balance and the supports' demand. Unset for the engines, whose metrics come from
// their samples alone; a study reads these when present, so that the analytic trajectory can be sampled coarsely.
struct LocatedEvents {
    // largest |theta1| [rad]: a located turning point, the run's end when it was cut off mid-swing past every one,
    // or the collapse angle when it overturned (analytic/response.hpp, response_of)
    double max_abs_theta1 = 0.0;
    double t_max_abs_theta1 = 0.0;  // when [s]
    std::optional<double> t_overturn;  // [s] when the collapse angle was reached
    double energy_balance_error = 0.0;  // the run's, relative to the largest energy in play (analytic/simulate.hpp)
    bool supports_computed = false;     // the supports' demand was computed (a VSSW)
    std::optional<double> roller_tension_at;  // first time the bilateral roller would have to pull [s]
    // The friction the no-sliding assumption needs while each contact pushes (largest |T|/N; 0 when not computed).
    double base_friction_needed = 0.0, hinge_friction_needed = 0.0;
};

// Sliding measured along an engine's run when the scene's friction was given (WallScene::slip_measured): at the base,
// the contact corner's drift from its place on the ground; at the hinge, the upper block's contact corner's drift
// along the lower block's top face (multibody/kit/slip_meter.hpp). Signed slips are along +x (base) or the lower
// block's top face (hinge) [m]; a parapet's hinge stays 0.
struct SlipMeasures {
    // Largest |slip| over the run and the last slip measured [m]: at the run's end, or where the wall left its
    // mechanism (overturning: the blocks' drift as they fold is the collapse, not a slip).
    double base_largest = 0.0, base_residual = 0.0;
    double hinge_largest = 0.0, hinge_residual = 0.0;  // the same at the hinge [m]
    double b = 0.0;                                    // the half-thickness the slips are given in units of [m]
    // The first time either slip passed kSlipTolerance b, and the first time |theta1| passed kLiftTolerance alpha
    // (slip_meter.hpp); unset when it never did.
    std::optional<double> t_first_slip, t_first_lift;
    // The wall left its support: a slip past kSlidOffLimit b ended the run (RunMonitor), with this reason.
    std::optional<std::string> slid_off;
    bool slid_before_rocking() const { return t_first_slip && (!t_first_lift || *t_first_slip < *t_first_lift); }
};

struct Trajectory {
    std::vector<TrajectorySample> samples;
    bool overturned = false;
    bool at_rest_at_end = false;
    long steps = 0;          // engine steps (or integrator steps) taken
    // The backend's own assumptions failing along the run, in words (the analytic model's validity warnings:
    // analytic/validity.hpp); empty for the engines, whose physics is their own.
    std::vector<std::string> warnings;
    std::optional<LocatedEvents> located;  // the analytic model only
    std::optional<SlipMeasures> slip;      // an engine's, when the scene's friction was given (WallScene::slip_measured)
};

// A run the engine could not finish honestly: NaN, blow-up, penetration past a bound, sliding. The message names the
// reason and when; the program reports it, it never crashes.
struct EngineFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The scene an engine runs, in the engine library's own file format (Engine::scene_file): the text the adapter builds
// its world from, so that a user can open it in the library's own viewer or load it with its own parser.
struct SceneFile {
    std::string format;     // "MJCF" (MuJoCo's XML), "URDF" (DART's)
    std::string extension;  // the format's usual file name ending, with its dot (".xml", ".urdf")
    std::string text;
};

class Engine {
public:
    virtual ~Engine() = default;
    virtual std::string name() const = 0;
    virtual std::string version() const = 0;  // of the engine library, for reports
    // The name a report prints ("ODE" for "ode"); the name itself unless the adapter says otherwise.
    virtual std::string display_name() const { return name(); }
    virtual EngineSettings default_settings() const = 0;
    // Every setting this backend reads (dt, iterations and each knob), with its default, unit and meaning; the knobs'
    // names are the ones check_settings() accepts.
    virtual std::vector<SettingDescription> setting_descriptions() const = 0;
    // Throws EngineFailure when the run fails; InputError on a bad scene or setting.
    virtual Trajectory simulate(const WallScene& scene, const Excitation& excitation,
                                const EngineSettings& settings) const = 0;
    // Throws InputError on a knob this backend does not know or a knob value it refuses, as simulate() would: lets a
    // caller refuse a whole study before anything runs. The step and iterations are the caller's to check.
    virtual void check_settings(const EngineSettings& settings) const = 0;
    // Whether simulate() may run on several threads at once (each call with its own scene). false for a library
    // with process-wide state that is not re-entrant (ODE): callers running cases in parallel run that engine's work
    // one task at a time (validation/suite.hpp, study/runner.cpp). make_engine()'s isolated engines are each run in a
    // process of its own and say true.
    virtual bool runs_concurrently() const { return true; }
    // Whether settings.dt is only the trajectory's sampling (the analytic model, Simbody's compliant route: their
    // integrators pick their own steps and see the ground motion between samples) rather than the engine's step.
    virtual bool dt_is_a_reporting_interval() const { return false; }
    // Wall time per simulated second at the default settings [s/s], measured (docs/measurements/speed.md): callers
    // order their tasks longest first by it (compare/task_pool.hpp); only the order depends on it.
    virtual double cost_per_simulated_second() const = 0;
    // The scene simulate() would build for this wall, release and settings, in the library's own format; unset for a
    // backend whose library reads no scene file (it is built through the library's calls only: docs/engines.md
    // "Scene files"). What a file cannot hold (a ground motion applied step by step, N pushed on the top) is said
    // in it, as a comment. InputError on a bad scene or setting, as simulate() would.
    virtual std::optional<SceneFile> scene_file(const WallScene& scene, const Excitation& excitation,
                                                const EngineSettings& settings) const {
        (void)scene, (void)excitation, (void)settings;
        return std::nullopt;
    }
};

// Backends of this build ("analytic" always, built in; "bullet", ... when found at configure time, each a plugin built
// with the program: engine_plugin.hpp). Known from a list fixed at build time: naming the engines opens no plugin.
std::vector<std::string> available_engines();
// Opens the engine's plugin the first time one of its engines is made (registry.hpp). Throws InputError naming the
// engine and the available ones, or naming the engine, its plugin and where it was looked for when the plugin cannot
// be found, opened or is of another build. Every engine library's runs are isolated: each in a child process with a
// CPU budget (isolated_engine.hpp), so that a library that aborts, crashes or hangs fails one run.
std::unique_ptr<Engine> make_engine(const std::string& name);
// The adapter itself, its runs in the caller's process: for callers that time a run's CPU inside the process (the
// work-precision sweep, the benchmarks) or isolate runs themselves (vssw stress). A library's abort ends the caller.
std::unique_ptr<Engine> make_engine_in_process(const std::string& name);
// The backends this project has adapters for that this build left out (not found at configure time), in the order of
// available_engines(); empty when every one is compiled in.
std::vector<std::string> missing_engines();
// Engine::display_name() of a backend of this build, from the build-time list (no plugin opened); the name itself
// otherwise (a report read back without the engine).
std::string engine_display_name(const std::string& name);
// For a name no backend answers to (host/engine_names.hpp canonical_engine, which takes a backend's name in other
// letter cases, with '_' for '-', and its display name): " (did you mean 'mujoco'?)" for the backend nearest to it, else "": messages refusing a name end with it.
std::string engine_name_hint(const std::string& name);
// The engines compared when none is named (vssw report) or with `vssw compare --engine all`: every backend compiled in
// except the analytic model, which is the reference, and simbody-rigid, Simbody's second route, whose threshold
// bisections take minutes (docs/contributing/engines.md, "Simbody"); name it to include it.
std::vector<std::string> default_compared_engines();

}  // namespace vssw::multibody

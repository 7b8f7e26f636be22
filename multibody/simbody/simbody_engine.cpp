// Simbody adapter, rigid route (engine "simbody-rigid"; "simbody" is the compliant route, simbody_compliant.cpp, and
// shares this file's engine class): the wall as rigid bodies with rigid unilateral contacts, stepped by Simbody's
// SemiExplicitEulerTimeStepper (a velocity-level time stepper: impacts and contact forces as impulses from an
// ImpulseSolver, PLUS by default).
//
// Scene (from the analytic description; depth 1 m, so masses and energies are per unit depth as in the paper):
//  - each block is a MobilizedBody::Planar on Ground (x, y and the rotation about z): the wall cannot leave its plane,
//    by construction;
//  - contacts are PointPlaneContact (Coulomb friction, scene.friction for both the static and the dynamic
//    coefficient) of a corner against a face: the lower block's two base corners against the ground plane y = 0, the
//    upper block's two bottom corners against the lower block's top face (the hinge). The lower block's top corners
//    against the upper block's bottom face would be the same points once the hinge is shut (the blocks share their
//    width): four rows where two hold, so they are left out; the corner pair that opens is the other side's, caught
//    by the upper block's corner on that side. Nothing else can touch (no ground-upper pair);
//  - rounded corners (corner radius r > 0): SpherePlaneContact of each base arc on the ground and SphereSphereContact of
//    each pair of hinge arcs instead of the corner points (add_rounded_contacts); the compliant route refuses them;
//  - the roller (VSSW only): a frictionless PointPlaneFrictionlessContact of each top corner of the upper block against
//    a vertical plane, x <= +b for the right corner and x >= -b for the left one, y free. Only the guide whose corner
//    is further out is offered to the stepper (its proximity test is gated; the Bullet and ODE adapters' rule;
//    `both_guides = 1` offers both, measured below);
//  - N: a force at the centre of the top face, only when xi > 0; ground motion: pseudo-forces -m a_h(t) at the centres
//    of mass, evaluated at each step's midpoint: the stepper ignores prescribed motion, so there are no moving
//    supports (moving_supports = 1 is refused; a ground on a heavy Slider whose speed was reset each step was tried
//    and failed: the parapet sank 0.01 m in a threshold trial, the VSSW's pulse peak came out 0.41 of the
//    pseudo-forces').
//
// Impacts: the stepper resolves an impact at the start of the step in which a contact is proximal and closing, with
// every proximal contact at once (Simultaneous), coefficient of restitution 0 everywhere: the plastic impact of the
// whole new mechanism, like ODE's LCP (docs/contributing/engines.md, "ODE"), not Eq. (19), which assumes no impulse at the roller.
//
// Defaults, each measured (vssw compare, bench/engine_accuracy.cpp; numbers in the comments where they are set).
#include "multibody/simbody/simbody_engine.hpp"
#include "multibody/simbody/quiet_stdout.hpp"
#include "multibody/simbody/simbody_compliant.hpp"
#include "multibody/simbody/simbody_wall.hpp"

#include <Simbody.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/rounded_corners.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/top_support.hpp"

namespace vssw::multibody {
namespace {

using namespace simbody_wall;  // kDepth, WallLoads, sample_of, ...

// The rigid route's name in its messages and failures (the compliant one's is "Simbody (compliant)").
constexpr const char* kRigidName = "Simbody (rigid)";

// Settings (EngineSettings::knobs), each with its default and the measurement that chose it.
struct Knobs {
    // constraint_tol (default 1e-6) [m]: the stepper's constraint tolerance. A contact whose gap is below it is
    // "proximal": given to the impulse solver for the step (an impact if it is closing). It must be well below the
    // distance a closing corner travels in a step (~0.16 m/s x dt on the Fig. 6 wall), or the faster-closing hinge is
    // caught a step before the new pivot and the landing is resolved as two impacts in sequence, which dissipates
    // less. Measured first-impact ratio on the Fig. 6 VSSW (whole-mechanism plastic impact 0.8252):
    //   tol 1e-4: 0.8265 / 0.8783 / 0.8804 at dt 1 / 0.5 / 0.2 ms (sequential from 0.5 ms down: not converged);
    //   tol 1e-5: 0.8260 / 0.8281 / 0.8807 at 1 / 0.5 / 0.2 ms (sequential at 0.2 ms);
    //   tol 1e-6: 0.8299 / 0.8265 / 0.8281 / 0.8259 / 0.8252 / 0.8253 at 2 / 1 / 0.5 / 0.2 / 0.1 / 0.05 ms;
    //   tol 1e-7: 0.8264 / 0.8281 / 0.8264 / 0.8255 / 0.8250 at 1 / 0.5 / 0.2 / 0.1 / 0.05 ms (same as 1e-6).
    // With 1e-6 at 2 / 1 / 0.5 / 0.2 ms, against the whole-mechanism impact: Table 1 #1 (xi 0.1) +0.8 / +0.4 / +0.2 /
    // -0.03 %, #7 +2.4 / +2.4 / +0.09 / +0.05 %, #15 +0.5 % / failed (slid, then a corner sank 5 mm at 3.4 s) /
    // +0.2 / +0.16 %: hence the default step of 0.5 ms. Run time is the same as with 1e-4.
    // A look-ahead proximity (also proximal when gap + closing speed x dt <= tol, so that contacts closing at the
    // same instant are caught in the same step) was tried and rejected: the stepper then holds a caught contact at
    // its gap for the step and lets it go the next, and the ratio scattered (Fig. 6: 0.79 to 0.96 over the steps).
    double constraint_tol;
    // transition_velocity (default 1e-3) [m/s]: the friction stick/slip transition speed. Simbody uses
    // max(this, 2 x constraint_tol), so without it a small tolerance would also make the contacts slip at 2e-6 m/s:
    // with 2e-4 the Fig. 6 VSSW released at 0.5 alpha1 slid 1 cm at its base by t = 1.83 s (dt 1 ms, tol 1e-6);
    // with 5e-4, 1e-3 and 1e-2 it does not slide and the restitution and period are unchanged (0.8265, 1.67128 s).
    double transition_velocity;
    // capture_velocity (default 2e-4) [m/s]: closing speeds below it are not impacts (resolved as contact forces in
    // the step); Simbody uses max(this, 2 x constraint_tol). 2e-4 is what the former default tolerance (1e-4) gave.
    double capture_velocity;
    // projection (default 1): position correction after each step, 0 bilateral (every proximal contact pulled onto
    // its plane, a lifting corner too), 1 unilateral (penetrations only), 2 none.
    int projection;
    // restitution (default 2): the stepper's restitution model, 0 Poisson, 1 Newton, 2 none. Every contact has a
    // coefficient of 0, so the three agree: measured identical (0.8265 at 1 ms, 0.8259 at 0.2 ms on Fig. 6).
    int restitution;
    // solver (default 0): the impulse solver, 0 PLUS, 1 PGS. PGS: 0.8265 at 1 ms, 0.8264 at 0.2 ms (+0.15 % from the
    // whole-mechanism impact, PLUS +0.08 %), with more contact events (29 against 27 in the same run).
    int solver;
    // both_guides (default 0): 1 offers both roller guides to the stepper every step.
    bool both_guides;
    FailureLimits limits;  // slide_limit, penetration_limit (run_monitor.hpp)
};

// Ranges (SettingDescription::lo/hi): constraint tolerance 1 nm to 1 mm (a thousand times the default either way);
// transition velocity 1e-6 to 0.1 m/s and capture velocity 1e-7 to 0.1 m/s (below them the stepper's friction and
// impact tests meet rounding; at 0.1 m/s every closing of the wall's corners would be a capture, none an impact).
const std::vector<SettingDescription>& rigid_setting_table() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.0005", "s", "the step (the restitution is converged from 0.5 ms down)"},
        {"iterations", "none", "", "not used"},
        {"constraint_tol", "1e-06", "m", "a contact within this gap is proximal: given to the impulse solver for the step", 1e-9, 1e-3},
        {"transition_velocity", "0.001", "m/s", "friction's stick/slip transition speed", 1e-6, 0.1},
        {"capture_velocity", "0.0002", "m/s", "closing speeds below it are not impacts", 1e-7, 0.1},
        {"projection", "1", "choice", "position correction after each step: 0 bilateral, 1 unilateral, 2 none", 0.0, 2.0},
        {"restitution", "2", "choice", "the stepper's restitution model: 0 Poisson, 1 Newton, 2 none", 0.0, 2.0},
        {"solver", "0", "choice", "the impulse solver: 0 PLUS, 1 PGS", 0.0, 1.0},
        // A parapet has no roller: a value there would be ignored, so it is refused (vssw_only).
        {"both_guides", "0", "0/1", "1: offer both roller guides to the stepper at every step", 0.0, 1.0,
         /*parapet_only=*/false, /*vssw_only=*/true},
        {"moving_supports", "0", "0/1", "refused when 1: the stepper ignores prescribed motion", 0.0, 1.0},
    });
    return table;
}

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r(kRigidName, s, rigid_setting_table());
    Knobs k{};
    k.constraint_tol = r.positive("constraint_tol", 1e-6);
    k.transition_velocity = r.positive("transition_velocity", 1e-3);
    k.capture_velocity = r.positive("capture_velocity", 2e-4);
    k.projection = r.choice("projection", 1, 3);
    k.restitution = r.choice("restitution", 2, 3);
    k.solver = r.choice("solver", 0, 2);
    k.both_guides = r.flag("both_guides");
    k.limits = FailureLimits::read(r);
    if (r.flag("moving_supports"))
        throw InputError(
            std::string(kRigidName) +
            " setting moving_supports = 1 is not supported: the SemiExplicitEuler stepper ignores prescribed "
            "motion, and a ground carried by a heavy Slider whose speed is reset each step was tried and failed "
            "(the parapet sank 0.01 m into the ground during a threshold trial; the VSSW's peak response to a pulse "
            "came out 0.41 of the pseudo-forces' at 1 ms). Use the default pseudo-forces (moving_supports = 0)");
    return k;
}

// What the loop decides before each step and the scene's elements read during it.
struct StepInputs {
    double a_h = 0.0;          // ground acceleration at the step's midpoint (pseudo-forces)
    bool right_guide = false;  // which roller guides the stepper may use this step
    bool left_guide = false;
};

// A roller guide the loop can withhold from the stepper: proximal only while its gate is open.
class GatedGuide : public SimTK::PointPlaneFrictionlessContact {
public:
    GatedGuide(SimTK::MobilizedBody& plane_body, const SimTK::UnitVec3& normal, SimTK::Real height,
               SimTK::MobilizedBody& follower, const SimTK::Vec3& point, const bool& gate)
        : SimTK::PointPlaneFrictionlessContact(plane_body, normal, height, follower, point, 0.0), gate_(gate) {}
    bool isProximal(const SimTK::State& s, SimTK::Real tol) const override {
        return gate_ && SimTK::PointPlaneFrictionlessContact::isProximal(s, tol);
    }

private:
    const bool& gate_;
};

class SimbodyScene {
public:
    SimbodyScene(const WallScene& scene, double theta0)
        : matter_(system_), forces_(system_), sizes_(block_sizes(scene)) {
        using namespace SimTK;
        const double b = sizes_.b, mu = scene.base_mu(), mu_hinge = scene.hinge_mu();
        SimTK::Force::UniformGravity(forces_, matter_, Vec3(0, -scene.gravity(), 0));
        base_ = matter_.Ground();
        lower_ = add_block(sizes_.h_lower, sizes_.m_lower);
        add_base_contacts(scene.corner_radius(), mu);
        if (scene.vssw) {
            upper_ = add_block(sizes_.h_upper, sizes_.m_upper);
            has_upper_ = true;
            add_hinge_contacts(scene.corner_radius(), mu_hinge);
            // Roller guides: n . p >= height, i.e. -x >= -b (right corner) and x >= -b (left corner).
            matter_.adoptUnilateralContact(new GatedGuide(base_, UnitVec3(-1, 0, 0), -b, upper_,
                                                          Vec3(b, sizes_.h_upper, 0), inputs_.right_guide));
            matter_.adoptUnilateralContact(new GatedGuide(base_, UnitVec3(1, 0, 0), -b, upper_,
                                                          Vec3(-b, sizes_.h_upper, 0), inputs_.left_guide));
        }
        const double N = scene.overburden() * kDepth;
        // The ground motion of the step (its midpoint value, set by the loop before each step).
        SimTK::Force::Custom(forces_, new WallLoads([&in = inputs_](const State&) { return in.a_h; }, lower_,
                                                    has_upper_ ? &upper_ : nullptr, sizes_, N,
                                                    scene.overburden_offset()));

        state_ = system_.realizeTopology();
        const WallPose pose = pose_at(scene, theta0);
        place(lower_, pose.lower);
        if (has_upper_) place(upper_, pose.upper);
        system_.realize(state_, Stage::Position);
    }

    const SimTK::MultibodySystem& system() const { return system_; }
    const SimTK::SimbodyMatterSubsystem& matter() const { return matter_; }
    const SimTK::State& initial_state() const { return state_; }
    const SimTK::MobilizedBody& lower() const { return lower_; }
    const SimTK::MobilizedBody& upper() const { return upper_; }
    bool has_upper() const { return has_upper_; }
    StepInputs& inputs() { return inputs_; }

private:
    // The lower block on the ground, Coulomb friction mu: its two bottom corners as points on the plane, or, with
    // rounded corners (kit/rounded_corners.hpp, r > 0), its base arcs as spheres of radius r (their centres r inside
    // both faces; Simbody's SpherePlaneContact). At rest every sphere touches at a flat's end; the spheres lie inside
    // the block, so they report no contact the outline does not have.
    void add_base_contacts(double r, double mu) {
        using namespace SimTK;
        const double in = sizes_.b - r;
        for (double side : {1.0, -1.0}) {
            if (r > 0.0)
                matter_.adoptUnilateralContact(new SpherePlaneContact(base_, UnitVec3(0, 1, 0), 0.0, lower_,
                                                                      Vec3(side * in, -(sizes_.h_lower - r), 0), r,
                                                                      0.0, mu, mu, 0.0));
            else
                matter_.adoptUnilateralContact(new PointPlaneContact(base_, UnitVec3(0, 1, 0), 0.0, lower_,
                                                                     Vec3(side * sizes_.b, -sizes_.h_lower, 0), 0.0,
                                                                     mu, mu, 0.0));
        }
    }

    // The hinge, Coulomb friction mu: the upper block's two bottom corners as points on the lower block's top face,
    // or, rounded, each bottom arc a sphere on the lower block's top arc of the same side (SphereSphereContact).
    void add_hinge_contacts(double r, double mu) {
        using namespace SimTK;
        const double in = sizes_.b - r;
        for (double side : {1.0, -1.0}) {
            const Vec3 upper_arc(side * in, -(sizes_.h_upper - r), 0), lower_arc(side * in, sizes_.h_lower - r, 0);
            if (r > 0.0)
                matter_.adoptUnilateralContact(
                    new SphereSphereContact(upper_, upper_arc, r, lower_, lower_arc, r, 0.0, mu, mu, 0.0));
            else
                matter_.adoptUnilateralContact(new PointPlaneContact(lower_, UnitVec3(0, 1, 0), sizes_.h_lower, upper_,
                                                                     Vec3(side * sizes_.b, -sizes_.h_upper, 0), 0.0,
                                                                     mu, mu, 0.0));
        }
    }

    SimTK::MobilizedBody add_block(double half_h, double mass_per_depth) {
        using namespace SimTK;
        // I_z = m (b^2 + h^2) / 3 = m R^2 / 3, as the analytic model's homogeneous blocks.
        const Body::Rigid body(
            MassProperties(mass_per_depth * kDepth, Vec3(0), UnitInertia::brick(sizes_.b, half_h, 0.5 * kDepth)));
        return MobilizedBody::Planar(matter_.Ground(), Transform(), body, Transform());
    }

    void place(SimTK::MobilizedBody& body, const BlockPose& p) {
        body.setQToFitTransform(
            state_, SimTK::Transform(SimTK::Rotation(-p.angle, SimTK::ZAxis), SimTK::Vec3(p.x, p.y, 0)));
    }

    SimTK::MultibodySystem system_;
    SimTK::SimbodyMatterSubsystem matter_;
    SimTK::GeneralForceSubsystem forces_;
    BlockSizes sizes_;
    StepInputs inputs_;
    SimTK::MobilizedBody base_, lower_, upper_;
    bool has_upper_ = false;
    SimTK::State state_;
};

// One class for both routes: `simbody` (compliant contact, simbody_compliant.cpp; the default, docs/contributing/engines.md
// "Simbody" for why) and `simbody-rigid` (this file's rigid contact), each with its own defaults.
class SimbodyEngine final : public Engine {
public:
    explicit SimbodyEngine(bool compliant) : compliant_(compliant) {}
    std::string name() const override { return compliant_ ? "simbody" : "simbody-rigid"; }
    std::string display_name() const override { return compliant_ ? "Simbody" : "simbody-rigid"; }
    // docs/measurements/speed.md: the compliant route (CPodes, reports every 2 ms) 65 ms, the rigid route at 0.5 ms 189
    // ms per simulated second.
    double cost_per_simulated_second() const override { return compliant_ ? 65e-3 : 189e-3; }
    bool dt_is_a_reporting_interval() const override { return compliant_; }  // CPodes picks its steps
    std::string version() const override {
        int major = 0, minor = 0, build = 0;
        SimTK_version_simbody(&major, &minor, &build);
        return fmt::format("Simbody {}.{}.{} ({})", major, minor, build,
                           compliant_ ? "Hunt-Crossley compliant contact, CPodes"
                                      : "SemiExplicitEulerTimeStepper, rigid unilateral contact");
    }
    EngineSettings default_settings() const override {
        EngineSettings s;
        // Compliant: the reporting interval (the integrator picks its own steps). 2 ms (was 1 ms): each report costs
        // Simbody a realization of the interpolated state through accelerations inside stepTo, so halving the reports
        // cut the Fig. 6 VSSW's free vibration from 78 to 65 ms per simulated second, while every wall of
        // vssw_engine_accuracy stays as far inside the targets as at 1 ms (period within 1.1e-4, restitution within
        // 0.39 % of the whole mechanism's; docs/contributing/engines.md "Simbody (3.7)"). Rigid: the step;
        // constraint_tol's comment: the restitution is converged from 0.5 ms down.
        s.dt = compliant_ ? 2e-3 : 5e-4;
        s.iterations = 0;  // neither route has iterations to set
        return s;
    }
    std::vector<SettingDescription> setting_descriptions() const override {
        return compliant_ ? compliant_setting_descriptions() : rigid_setting_table();
    }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override {
        if (compliant_) check_compliant_settings(settings);
        else (void)read_knobs(settings);
    }

private:
    bool compliant_;
};

// The stepping kit's hooks (step_loop.hpp) on a SimbodyScene and its time stepper. N is a force element of the
// scene (its WallLoads read the state), so the loop pushes none (StepLoop::overburden false); no moving supports.
class SimbodyStepping {
public:
    SimbodyStepping(SimbodyScene& w, SimTK::SemiExplicitEulerTimeStepper& ts, const WallBodies& bodies,
                    const Knobs& knobs)
        : w_(w), ts_(ts), bodies_(bodies), knobs_(knobs) {}

    void drive(const GroundStep& g) {
        SimTK::State& st = ts_.updState();
        StepInputs& in = w_.inputs();
        in.a_h = g.a_h;
        if (bodies_.vssw) {
            // The roller guide whose corner is further out (both with both_guides).
            const BlockSizes& s = bodies_.sizes;
            w_.system().realize(st, SimTK::Stage::Position);
            const SimTK::Vec3 right = world_point(bodies_.upper, st, s.b, s.h_upper);
            const SimTK::Vec3 left = world_point(bodies_.upper, st, -s.b, s.h_upper);
            const bool use_left = left_guide_binds(right[0], left[0], 0.0, s.b);
            in.left_guide = knobs_.both_guides || use_left;
            in.right_guide = knobs_.both_guides || !use_left;
        }
        st.invalidateAllCacheAtOrAbove(SimTK::Stage::Dynamics);  // the loads just changed
    }
    void push_overburden() {}
    void step(const StepTimes& times, const GroundStep&) {
        try {
            ts_.stepTo(times.t);
        } catch (const std::exception& e) {
            throw EngineFailure(fmt::format("{}: {} at t = {:.6g} s", kRigidName, e.what(), times.t));
        }
    }
    WallState state(const GroundStep&) const {
        const SimTK::State& now = realized();
        return {block_state(bodies_.lower, now), bodies_.vssw ? block_state(bodies_.upper, now) : kNoBlock};
    }
    Rocking rocking() const { return rocking_of(bodies_, realized()); }
    void fill(TrajectorySample& p) const {
        const SimTK::State& st = realized();
        fill_sample(bodies_, st, p);
        const SimTK::SimbodyMatterSubsystem& matter = w_.matter();
        int contacts = 0;
        for (SimTK::UnilateralContactIndex i(0); i < matter.getNumUnilateralContacts(); ++i)
            if (matter.getUnilateralContact(i).isEnabled(st)) ++contacts;
        p.contacts = contacts;
    }

private:
    const SimTK::State& realized() const {
        const SimTK::State& st = ts_.getState();
        w_.system().realize(st, SimTK::Stage::Velocity);
        return st;
    }

    SimbodyScene& w_;
    SimTK::SemiExplicitEulerTimeStepper& ts_;
    const WallBodies& bodies_;
    const Knobs& knobs_;
};

Trajectory SimbodyEngine::simulate(const WallScene& scene, const Excitation& ex,
                                   const EngineSettings& settings) const {
    require(std::isfinite(settings.dt) && settings.dt > 0.0,
            compliant_ ? "Simbody reporting interval dt (s)" : "Simbody time step dt (s)", "a positive finite number",
            settings.dt);
    require_one_description(scene);
    require_rigid_top(scene, "Simbody",
                      "both routes drive the wall by pseudo-forces and "
                      "cannot prescribe the motion of a support");
    if (compliant_) {
        require_sharp_corners("Simbody", scene,
                              "its compliant contacts are small corner spheres on half-spaces with Hertz's law for "
                              "their radius; an arc rolling on an arc is not written (simbody-rigid rounds them)");
        return simulate_compliant(scene, ex, settings);
    }
    const Knobs knobs = read_knobs(settings);
    // PLUS holds a contact past Coulomb's bound: measured, the Fig. 6 parapet under a sine pulse of 0.15 g stayed put at
    // mu = 0.08 (2.6e-5 b) where Coulomb lets it slide and every other engine, and PGS, slid 0.05 b and more.
    if (scene.slip_measured && knobs.solver == 0)
        throw InputError("simbody-rigid cannot measure sliding with its PLUS impulse solver (solver = 0), which holds "
                         "the contacts past the friction given: set solver = 1 (PGS) for a friction given");
    const double dt = settings.dt;
    SimbodyScene w(scene, ex.theta0);
    const WallBodies bodies{w.lower(), w.upper(), w.has_upper(), block_sizes(scene), WallEnergy(scene, kDepth), scene.overburden_offset()};

    const QuietStdout quiet;
    SimTK::SemiExplicitEulerTimeStepper ts(w.system());
    ts.setConstraintTolerance(knobs.constraint_tol);
    ts.setDefaultFrictionTransitionVelocity(knobs.transition_velocity);
    ts.setDefaultImpactCaptureVelocity(knobs.capture_velocity);
    ts.setRestitutionModel(static_cast<SimTK::SemiExplicitEulerTimeStepper::RestitutionModel>(knobs.restitution));
    ts.setImpulseSolverType(static_cast<SimTK::SemiExplicitEulerTimeStepper::ImpulseSolverType>(knobs.solver));
    ts.setPositionProjectionMethod(
        static_cast<SimTK::SemiExplicitEulerTimeStepper::PositionProjectionMethod>(knobs.projection));
    ts.initialize(w.initial_state());

    SimbodyStepping stepping(w, ts, bodies, knobs);
    RunMonitor monitor(kRigidName, scene, ex, dt, knobs.limits);
    return run_fixed_steps(stepping, ex, StepLoop{dt, sample_every(settings, dt), false, false}, monitor);
}

}  // namespace

std::unique_ptr<Engine> make_simbody_engine() { return std::make_unique<SimbodyEngine>(true); }
std::unique_ptr<Engine> make_simbody_rigid_engine() { return std::make_unique<SimbodyEngine>(false); }

}  // namespace vssw::multibody

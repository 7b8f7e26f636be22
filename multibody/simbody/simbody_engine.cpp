// Simbody adapter: the wall as rigid bodies with rigid unilateral contacts, stepped by Simbody's
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
// whole new mechanism, like ODE's LCP (README, "ODE"), not Eq. (19), which assumes no impulse at the roller.
//
// Defaults, each measured (vssw compare, bench/engine_accuracy.cpp; numbers in the comments where they are set).
#include "multibody/simbody/simbody_engine.hpp"

#include <Simbody.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/run_monitor.hpp"
#include "multibody/settings_reader.hpp"
#include "multibody/scene_geometry.hpp"

namespace vssw::multibody {
namespace {

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

// Settings (EngineSettings::knobs), each with its default and the measurement that chose it.
struct Knobs {
    // constraint_tol (default see read_knobs) [m, m/s]: the stepper's constraint tolerance. A contact whose gap is
    // below it is "proximal" (given to the impulse solver for the step), and closing speeds below a tenth of it are
    // not impacts.
    double constraint_tol;
    // projection (default 1): position correction after each step, 0 bilateral (every proximal contact pulled onto
    // its plane, a lifting corner too), 1 unilateral (penetrations only), 2 none.
    int projection;
    // restitution (default 2): the stepper's restitution model, 0 Poisson, 1 Newton, 2 none. Every contact has a
    // coefficient of 0, so the three must agree (measured below).
    int restitution;
    // solver (default 0): the impulse solver, 0 PLUS, 1 PGS.
    int solver;
    // both_guides (default 0): 1 offers both roller guides to the stepper every step.
    bool both_guides;
    // slide_limit and penetration_limit (default 0.05, in units of b): failures past these (the other adapters').
    double slide_limit;
    double penetration_limit;
};

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("Simbody", s,
                           {"constraint_tol", "projection", "restitution", "solver", "both_guides", "slide_limit",
                            "penetration_limit", "moving_supports"});
    Knobs k{};
    k.constraint_tol = r.positive("constraint_tol", 1e-4);
    k.projection = r.choice("projection", 1, 3);
    k.restitution = r.choice("restitution", 2, 3);
    k.solver = r.choice("solver", 0, 2);
    k.both_guides = r.flag("both_guides");
    k.slide_limit = r.positive("slide_limit", 5e-2);
    k.penetration_limit = r.positive("penetration_limit", 5e-2);
    if (r.flag("moving_supports"))
        throw InputError(
            "Simbody setting moving_supports = 1 is not supported: the SemiExplicitEuler stepper ignores prescribed "
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

// Pseudo-forces -m a_h at the centres of mass (fixed supports only) and N at the centre of the top face.
class WallLoads : public SimTK::Force::Custom::Implementation {
public:
    WallLoads(const StepInputs& inputs, const SimTK::MobilizedBody& lower, const SimTK::MobilizedBody* upper,
              const BlockSizes& sizes, double N, bool pseudo)
        : inputs_(inputs), lower_(lower), has_upper_(upper != nullptr), sizes_(sizes), N_(N), pseudo_(pseudo) {
        if (upper) upper_ = *upper;
    }
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        const double a = inputs_.a_h;
        if (pseudo_ && a != 0.0) {
            lower_.applyForceToBodyPoint(s, SimTK::Vec3(0), SimTK::Vec3(-sizes_.m_lower * kDepth * a, 0, 0),
                                         body_forces);
            if (has_upper_)
                upper_.applyForceToBodyPoint(s, SimTK::Vec3(0), SimTK::Vec3(-sizes_.m_upper * kDepth * a, 0, 0),
                                             body_forces);
        }
        if (N_ > 0.0) {
            const SimTK::MobilizedBody& top = has_upper_ ? upper_ : lower_;
            const double half = has_upper_ ? sizes_.h_upper : sizes_.h_lower;
            top.applyForceToBodyPoint(s, SimTK::Vec3(0, half, 0), SimTK::Vec3(0, -N_, 0), body_forces);
        }
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0.0; }

private:
    const StepInputs& inputs_;
    SimTK::MobilizedBody lower_, upper_;
    bool has_upper_;
    BlockSizes sizes_;
    double N_;
    bool pseudo_;
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

// Debian's libsimbody 3.7 is built without NDEBUG, and SemiExplicitEulerTimeStepper then prints its working to
// stdout (printf and std::cout, several lines with whole vectors every step): it would corrupt `vssw compare --json`
// and cost most of the run time (measured: 178 s for `vssw compare` on the Fig. 6 VSSW with the text going to a
// pipe). While a run steps, file descriptor 1 goes to /dev/null and std::cout is put in a failed state (so that its
// formatting is skipped); both are restored, and what was buffered flushed, when the run ends, normally or not. This
// touches process-wide state: simulate() must not run on two threads at once, nor beside a thread writing to stdout.
class QuietStdout {
public:
    QuietStdout() {
        std::cout.flush();
        std::fflush(stdout);
        saved_fd_ = ::dup(1);
        const int null_fd = ::open("/dev/null", O_WRONLY);
        if (saved_fd_ >= 0 && null_fd >= 0) ::dup2(null_fd, 1);
        if (null_fd >= 0) ::close(null_fd);
        saved_state_ = std::cout.rdstate();
        std::cout.setstate(std::ios::badbit);
    }
    ~QuietStdout() {
        std::fflush(stdout);  // Simbody's leftover text goes to /dev/null, not to the restored stdout
        std::cout.clear(saved_state_);
        if (saved_fd_ >= 0) {
            ::dup2(saved_fd_, 1);
            ::close(saved_fd_);
        }
    }
    QuietStdout(const QuietStdout&) = delete;
    QuietStdout& operator=(const QuietStdout&) = delete;

private:
    int saved_fd_ = -1;
    std::ios::iostate saved_state_{};
};

// Clockwise angle of a body about z.
double clockwise_angle(const SimTK::MobilizedBody& body, const SimTK::State& s) {
    const SimTK::Rotation& r = body.getBodyRotation(s);
    return -std::atan2(r[1][0], r[0][0]);
}

struct Vec2 {
    double x, y;
};

Vec2 world_point(const SimTK::MobilizedBody& body, const SimTK::State& s, double lx, double ly) {
    const SimTK::Vec3 p = body.findStationLocationInGround(s, SimTK::Vec3(lx, ly, 0));
    return {p[0], p[1]};
}

class SimbodyScene {
public:
    SimbodyScene(const WallScene& scene, double theta0)
        : matter_(system_), forces_(system_), sizes_(block_sizes(scene)) {
        using namespace SimTK;
        const double b = sizes_.b, mu = scene.friction;
        SimTK::Force::UniformGravity(forces_, matter_, Vec3(0, -scene.gravity(), 0));
        base_ = matter_.Ground();
        lower_ = add_block(sizes_.h_lower, sizes_.m_lower);
        for (double side : {1.0, -1.0})
            matter_.adoptUnilateralContact(new PointPlaneContact(base_, UnitVec3(0, 1, 0), 0.0, lower_,
                                                                 Vec3(side * b, -sizes_.h_lower, 0), 0.0, mu, mu, 0.0));
        if (scene.vssw) {
            upper_ = add_block(sizes_.h_upper, sizes_.m_upper);
            has_upper_ = true;
            for (double side : {1.0, -1.0})
                matter_.adoptUnilateralContact(new PointPlaneContact(lower_, UnitVec3(0, 1, 0), sizes_.h_lower,
                                                                     upper_, Vec3(side * b, -sizes_.h_upper, 0),
                                                                     0.0, mu, mu, 0.0));
            // Roller guides: n . p >= height, i.e. -x >= -b (right corner) and x >= -b (left corner).
            matter_.adoptUnilateralContact(new GatedGuide(base_, UnitVec3(-1, 0, 0), -b, upper_,
                                                          Vec3(b, sizes_.h_upper, 0), inputs_.right_guide));
            matter_.adoptUnilateralContact(new GatedGuide(base_, UnitVec3(1, 0, 0), -b, upper_,
                                                          Vec3(-b, sizes_.h_upper, 0), inputs_.left_guide));
        }
        const double N = (scene.vssw ? scene.vssw->N : scene.parapet->N) * kDepth;
        SimTK::Force::Custom(forces_, new WallLoads(inputs_, lower_, has_upper_ ? &upper_ : nullptr, sizes_, N,
                                                    true));

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

class SimbodyEngine final : public Engine {
public:
    std::string name() const override { return "simbody"; }
    std::string version() const override {
        int major = 0, minor = 0, build = 0;
        SimTK_version_simbody(&major, &minor, &build);
        return fmt::format("Simbody {}.{}.{} (SemiExplicitEulerTimeStepper, rigid unilateral contact)", major, minor,
                           build);
    }
    EngineSettings default_settings() const override {
        EngineSettings s;
        s.dt = 1e-3;
        s.iterations = 0;  // PLUS has none to set
        return s;
    }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
};

Trajectory SimbodyEngine::simulate(const WallScene& scene, const Excitation& ex,
                                   const EngineSettings& settings) const {
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "Simbody time step dt (s)", "a positive finite number",
            settings.dt);
    if (scene.vssw.has_value() == scene.parapet.has_value())
        throw InputError("a wall scene must hold exactly one description (a VSSW or a parapet wall)");
    const Knobs knobs = read_knobs(settings);
    const double dt = settings.dt;
    SimbodyScene w(scene, ex.theta0);
    const BlockSizes s = block_sizes(scene);
    const double g = scene.gravity();
    const double N = (scene.vssw ? scene.vssw->N : scene.parapet->N) * kDepth;
    const double h_total = s.h_lower + s.h_upper;
    const bool vssw = w.has_upper();
    const SimTK::MobilizedBody& lower = w.lower();
    const SimTK::MobilizedBody& upper = w.upper();
    const SimTK::MobilizedBody& top_body = vssw ? upper : lower;
    const double top_half = vssw ? s.h_upper : s.h_lower;
    const double y_top0 = 2.0 * h_total;
    const double y_lower0 = s.h_lower, y_upper0 = 2.0 * s.h_lower + s.h_upper;

    const QuietStdout quiet;
    SimTK::SemiExplicitEulerTimeStepper ts(w.system());
    ts.setConstraintTolerance(knobs.constraint_tol);
    ts.setRestitutionModel(static_cast<SimTK::SemiExplicitEulerTimeStepper::RestitutionModel>(knobs.restitution));
    ts.setImpulseSolverType(static_cast<SimTK::SemiExplicitEulerTimeStepper::ImpulseSolverType>(knobs.solver));
    ts.setPositionProjectionMethod(
        static_cast<SimTK::SemiExplicitEulerTimeStepper::PositionProjectionMethod>(knobs.projection));
    ts.initialize(w.initial_state());

    Trajectory out;
    const long every = settings.sample_dt > 0.0 ? std::max(1L, std::lround(settings.sample_dt / dt)) : 1L;
    const SimTK::SimbodyMatterSubsystem& matter = w.matter();
    auto record = [&](double t) {
        const SimTK::State& st = ts.getState();
        w.system().realize(st, SimTK::Stage::Velocity);
        TrajectorySample p{};
        p.t = t;
        p.theta1 = clockwise_angle(lower, st);
        p.theta1_dot = -lower.getBodyAngularVelocity(st)[2];
        p.theta2 = vssw ? clockwise_angle(upper, st) : 0.0;
        p.top_dy = world_point(top_body, st, 0.0, top_half).y - y_top0;
        auto kinetic = [&](const SimTK::MobilizedBody& body, double mass, double half_h) {
            const SimTK::Vec3 v = body.getBodyOriginVelocity(st);
            const double wz = body.getBodyAngularVelocity(st)[2];
            const double vx = v[0];
            return 0.5 * mass * (vx * vx + v[1] * v[1]) + 0.5 * mass * (s.b * s.b + half_h * half_h) / 3.0 * wz * wz;
        };
        p.kinetic = (kinetic(lower, s.m_lower * kDepth, s.h_lower) +
                     (vssw ? kinetic(upper, s.m_upper * kDepth, s.h_upper) : 0.0)) /
                    kDepth;
        p.potential = (s.m_lower * kDepth * g * (lower.getBodyOriginLocation(st)[1] - y_lower0) +
                       (vssw ? s.m_upper * kDepth * g * (upper.getBodyOriginLocation(st)[1] - y_upper0) : 0.0) +
                       N * p.top_dy) /
                      kDepth;
        int contacts = 0;
        for (SimTK::UnilateralContactIndex i(0); i < matter.getNumUnilateralContacts(); ++i)
            if (matter.getUnilateralContact(i).isEnabled(st)) ++contacts;
        p.contacts = contacts;
        out.samples.push_back(p);
    };

    const long n_steps = std::lround(ex.t_end / dt);
    record(0.0);
    RunMonitor monitor("Simbody", scene, ex, dt, knobs.slide_limit, knobs.penetration_limit);
    StepInputs& in = w.inputs();
    for (long i = 1; i <= n_steps; ++i) {
        const double t0 = static_cast<double>(i - 1) * dt;
        const double t = static_cast<double>(i) * dt;
        // The ground motion at the step's midpoint: its impulse over the step to second order.
        const double a_h = ex.horizontal(t0 + 0.5 * dt);
        SimTK::State& st = ts.updState();
        in.a_h = a_h;
        if (vssw) {
            // The roller guide whose corner is further out (both with both_guides).
            w.system().realize(st, SimTK::Stage::Position);
            const Vec2 right = world_point(upper, st, s.b, s.h_upper), left = world_point(upper, st, -s.b, s.h_upper);
            const bool use_left = -s.b - left.x > right.x - s.b;
            in.left_guide = knobs.both_guides || use_left;
            in.right_guide = knobs.both_guides || !use_left;
        }
        st.invalidateAllCacheAtOrAbove(SimTK::Stage::Dynamics);  // the loads just changed
        try {
            ts.stepTo(t);
        } catch (const std::exception& e) {
            throw EngineFailure(fmt::format("Simbody: {} at t = {:.6g} s", e.what(), t));
        }
        ++out.steps;

        const SimTK::State& now = ts.getState();
        w.system().realize(now, SimTK::Stage::Velocity);
        const double theta = clockwise_angle(lower, now);
        const double rate = -lower.getBodyAngularVelocity(now)[2];
        const Vec2 right = world_point(lower, now, s.b, -s.h_lower), left = world_point(lower, now, -s.b, -s.h_lower);
        const auto verdict = monitor.check(t, theta, rate, {right.x - s.b, right.y, left.x + s.b, left.y});
        if (i % every == 0 || i == n_steps || verdict != RunMonitor::Verdict::go_on) record(t);
        if (RunMonitor::ends_run(verdict, out)) return out;
    }
    return out;
}

}  // namespace

std::unique_ptr<Engine> make_simbody_engine() { return std::make_unique<SimbodyEngine>(); }

}  // namespace vssw::multibody

// Simbody adapter, the default route (engine "simbody"; the rigid route is "simbody-rigid"): the wall as rigid bodies with compliant
// (Hunt-Crossley) contact from CompliantContactSubsystem + ContactTrackerSubsystem, integrated by an error-controlled
// integrator (CPodes, an implicit BDF method, by default; Runge-Kutta-Merson on request).
//
// Scene (the rigid route's, simbody_engine.cpp; depth 1 m, so masses and energies are per unit depth):
//  - each block is a MobilizedBody::Planar on Ground (no out-of-plane motion by construction);
//  - Simbody 3.7 has no brick-brick compliant pair, so the corners carry small spheres (radius `radius`) centred ON
//    the corners, pressed against half-spaces: the lower block's two base spheres against the ground, the upper
//    block's two bottom spheres against a half-space fixed to the lower block whose surface is its top face (the
//    hinge), and the upper block's two top spheres against two frictionless vertical half-spaces fixed to Ground, one
//    a wall-thickness from the other (the roller on both faces; VSSW only). A sphere centred on the corner keeps the
//    corner's geometry: the contact point is straight below the corner, so the lever arms and the threshold are those
//    of a sharp corner on a support lifted by r (relative error r/h: 5e-5 on the Fig. 6 wall at the defaults), and
//    rolling shifts the corner by r*theta (the moment of inertia about the contact changes by about 2r/h). The wall
//    therefore starts r (lower block) and 2r (upper block) above the analytic positions, and the guides stand at
//    x = +-(b + r);
//  - cliques keep the pairs that cannot touch apart (the rigid route's rule): the guides and the half-spaces among
//    themselves, the guides from every sphere but the upper block's top ones;
//  - both guides are always there: compliant contact has no redundant-loop trouble (the rigid adapters' single-guide
//    rule was for their LCP solvers); at rest both top spheres merely touch their guides;
//  - N at the centre of the top face (only when xi > 0) and the ground motion as pseudo-forces -m a_h(t) at the
//    centres of mass, both from a Force::Custom evaluated at the integrator's own times (a record is followed between
//    its samples by the error control, no midpoint rule needed). No moving supports (refused).
//
// Contact law (Simbody's HertzCircular generator, sphere on half-space): normal force f = fH (1 + 3/2 c xdot) with
// fH = 4/3 E sqrt(r) x^3/2, x the penetration, c the Hunt-Crossley dissipation, clamped at 0 when pulling. The knob
// `stiffness` is the effective modulus E of the pair (each material gets 2^1.5 E: Simbody combines equal materials as
// E_eff = E_material / 2^1.5). Friction: Simbody's Stribeck curve, mu rising smoothly from 0 at no slip to mu_s at the
// transition velocity vt: there is no true stiction, a loaded contact creeps at a fraction of vt (measured below).
//
// Time: settings.dt is the REPORTING interval (the integrator's steps are chosen by its error control); each report is
// interpolated by the integrator inside its step (or, with interpolate = 0, is a step end), the RunMonitor checks it,
// and the trajectory samples it.
//
// Defaults, each measured (vssw compare; numbers in the comments where they are set).
#include "multibody/simbody/simbody_compliant.hpp"
#include "multibody/simbody/corner_contacts.hpp"
#include "multibody/simbody/quiet_stdout.hpp"
#include "multibody/simbody/simbody_wall.hpp"

#include <Simbody.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/settings_reader.hpp"

namespace vssw::multibody {
namespace {

using namespace simbody_wall;  // kDepth, WallLoads, sample_of, ...
constexpr const char* kName = "Simbody (compliant)";
constexpr int kStepsPerCall = 100000;   // integrator steps per stepTo call (see setInternalStepLimit below)
constexpr int kMaxCallsPerReport = 20;  // stepTo calls per report interval before the run is declared stuck

struct Knobs {
    double stiffness;            // [Pa] effective Hertz modulus E of a sphere-on-half-space pair
    double radius;               // [m] corner sphere radius
    double dissipation;          // [s/m] Hunt-Crossley c
    double transition_velocity;  // [m/s] Simbody's friction transition (creep) velocity vt
    double accuracy;             // integrator accuracy (Simbody's relative/weighted error per step)
    int integrator;              // 0 Runge-Kutta-Merson, 1 CPodes (BDF, for stiff contact)
    bool contact_subsystem;      // 1: Simbody's CompliantContactSubsystem; 0: the same law as CornerContacts
    bool interpolate;            // 1: reports interpolated between the integrator's steps; 0: each report a step end
    FailureLimits limits;        // slide_limit, penetration_limit (run_monitor.hpp)
};

}  // namespace

// Ranges (SettingDescription::lo/hi), each holding the values measured below with decades to spare: stiffness 1e6 to
// 1e18 Pa (at 1e6 a corner of the Fig. 6 wall sinks centimetres; 1e18 is a thousand times the default, past which the
// contact's time scale falls below CPodes' smallest steps); radius 1 um to 1 cm (the spheres roll by r theta: at 1 cm
// the threshold is already off by 0.64 %); dissipation up to 1e5 s/m (a hundred times the plastic default);
// transition velocity 1e-6 to 0.1 m/s (at 1e-300 the friction law's slope mu N / vt was infinite and CPodes stepped
// forever; 0.1 m/s is the wall's own speed: no stick); accuracy 1e-10 to 0.1.
const std::vector<SettingDescription>& compliant_setting_descriptions() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.002", "s", "the reporting interval (the integrator picks its own steps)"},
        {"iterations", "none", "", "not used"},
        {"stiffness", "1e+15", "Pa", "Hunt-Crossley contact stiffness of the corner spheres", 1e6, 1e18},
        {"radius", "0.0001", "m", "radius of the corner spheres", 1e-6, 1e-2},
        {"dissipation", "1000", "s/m", "Hunt-Crossley dissipation (1000: a plastic contact at the wall's speeds)", 0.0, 1e5},
        {"transition_velocity", "0.0001", "m/s", "friction's stick/slip transition (creep) velocity", 1e-6, 0.1},
        {"accuracy", "3e-06", "", "the integrator's accuracy (relative error per step)", 1e-10, 0.1},
        {"integrator", "1", "choice", "0 Runge-Kutta-Merson, 1 CPodes (BDF, for stiff contact)", 0.0, 1.0},
        {"contact_subsystem", "0", "0/1",
         "1: Simbody's CompliantContactSubsystem and contact tracking; 0: the same law on the corner pairs directly", 0.0, 1.0},
        {"interpolate", "1", "0/1", "1: samples interpolated between the integrator's steps; 0: each sample a step end", 0.0, 1.0},
        {"moving_supports", "0", "0/1", "refused when 1: this route drives the wall by pseudo-forces only", 0.0, 1.0},
    });
    return table;
}

namespace {

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r(kName, s, compliant_setting_descriptions());
    Knobs k{};
    // Defaults, measured with `vssw compare` and single free vibrations on the Fig. 6 walls (4 m x 0.4 m, h1/h 0.7):
    // stiffness 1e15 Pa with radius 1e-4 m (E sqrt(r) = 1e13 N/m^1.5: a base corner sinks 1.6e-6 m under the whole
    // Fig. 6 VSSW). The threshold error has a compliance part and a rolling part (the spheres roll by r theta):
    // -0.17 % at (1e13 Pa, 1e-3 m), -0.068 % at (1e14, 1e-3), -0.051 % at (1e15, 1e-3), -0.12 % at (3.16e13, 1e-4)
    // (same E sqrt(r) as the first), -0.64 % at (3.16e12, 1e-2), -0.0085 % at the defaults.
    k.stiffness = r.positive("stiffness", 1e15);
    k.radius = r.positive("radius", 1e-4);
    // dissipation 1000 s/m: a corner striking at ~0.1 m/s has c v ~ 100, a plastic contact. Housner's e on the
    // Fig. 6 parapet: -0.027 % (every impact alike) at 1000; +0.22 % at 100 (impacts differ by 0.2 %: a partly
    // elastic contact); the VSSW's first impact 0.8287 at 1000, 0.8183 at 100, 0.7910 at 10 (whole-mechanism 0.8252).
    k.dissipation = r.non_negative("dissipation", 1000.0);
    // transition_velocity 1e-4 m/s: the base creeps 1.1e-5 m in a 3.6 s free vibration of the Fig. 6 VSSW (1.4e-5
    // m for the parapet), 1.8e-4 m with dissipation 10; 1e-5 m/s changes no metric beyond the sampling's and costs
    // 1.3x the steps.
    k.transition_velocity = r.positive("transition_velocity", 1e-4);
    // accuracy 3e-6 (was 1e-6): the flight agrees with the analytic model to 1e-6 rad at 1e-6 and 1e-8 alike; tighter
    // settings resolve the ~1 ms the impact lasts differently, which only moves the samples that fall inside it. With
    // interpolated reports the Fig. 6 VSSW's quarter-period error at reporting intervals 4 / 2 / 1 / 0.5 ms is
    // 4.1e-4 / 1.16e-4 / 8.4e-5 / 3.3e-5 at 3e-6 (the same as 1e-6: the sampling's), but 4.1e-4 / 1.15e-4 / 1.58e-4 /
    // 3.8e-5 at 1e-5: the integrator's error shows, and the error no longer falls with the interval. 1e-4 drifts
    // (theta1 0.0167 rad instead of 0.0092 after 2 s of free vibration). Cost per accuracy: docs/contributing/engines.md
    // "Simbody (3.7)". `vssw bench` finds 1e-5 the cheapest accuracy within every target (0.51 against 0.58 s of CPU at
    // 1e-6 on the Fig. 6 free vibration), but there the quarter-period error rises as the reporting interval falls from
    // 4 to 1 ms (1.15e-4 at 2 ms, 1.58e-4 at 1 ms: CrossEngine.QuarterPeriodErrorFallsAsTheStepFalls fails with 1 ms
    // reports). With the 2 ms reports (the default since 2026-11-25) that test holds at 1e-5 (8.1e-4, 4.1e-4, 1.6e-4 at
    // 8, 4, 2 ms), but 1e-5 bought no clear saving: the default report 0.94 of the CPU, the free vibration of the Fig. 6
    // VSSW 1.05 (both hyperfine, paired; docs/contributing/engines.md), and its error is then the sampling's size
    // (1.6e-4 against 1.1e-4 at 3e-6). It stays 3e-6.
    k.accuracy = r.positive("accuracy", 3e-6);
    // integrator 1 (CPodes, BDF): the contacts are stiff (friction slope mu N / vt); Runge-Kutta-Merson took 881k
    // steps and 141 s for a 3.6 s free vibration of the Fig. 6 VSSW (E 1e13, r 1e-3), CPodes 13k steps and 0.9 s, with
    // the same period and restitution to 2e-5.
    k.integrator = r.choice("integrator", 1, 2);
    // contact_subsystem 0: the corner pairs evaluated directly (corner_contacts.hpp), Simbody's force law without
    // its contact tracking; 1 keeps CompliantContactSubsystem + ContactTrackerSubsystem (the former route, kept to
    // check the two against each other: multibody/simbody/tests/test_simbody.cpp). Cost and agreement in
    // docs/contributing/engines.md "Simbody (3.7)".
    k.contact_subsystem = r.flag("contact_subsystem");
    // interpolate 1 (was 0): a report no longer ends a step, so the integrator is not held to 1 ms steps where the
    // wall is at rest or in flight, and the samples are CPodes' own interpolant, of the method's order. Cost: docs/contributing/engines.md "Simbody".
    k.interpolate = r.choice("interpolate", 1, 2) == 1;
    k.limits = FailureLimits::read(r);
    require(k.accuracy < 1.0, std::string(kName) + " setting accuracy", "below 1", k.accuracy);
    if (r.flag("moving_supports"))
        throw InputError(fmt::format("{} setting moving_supports = 1 is not supported: the compliant route drives the "
                                     "wall by pseudo-forces only (moving_supports = 0)",
                                     kName));
    return k;
}

class CompliantScene {
public:
    CompliantScene(const WallScene& scene, const Excitation& ex, const Knobs& k)
        : matter_(system_), forces_(system_), sizes_(block_sizes(scene)), r_(k.radius) {
        using namespace SimTK;
        SimTK::Force::UniformGravity(forces_, matter_, Vec3(0, -scene.gravity(), 0));
        lower_ = MobilizedBody::Planar(matter_.Ground(), Transform(), block_body(sizes_.h_lower, sizes_.m_lower),
                                       Transform());
        has_upper_ = scene.vssw.has_value();
        if (has_upper_)
            upper_ = MobilizedBody::Planar(matter_.Ground(), Transform(), block_body(sizes_.h_upper, sizes_.m_upper),
                                           Transform());
        if (k.contact_subsystem) add_subsystem_contacts(scene, k);
        else add_corner_contacts(scene, k);
        const double N = scene.overburden() * kDepth;
        // a_h at the integrator's own times: the error control follows a record between its samples.
        SimTK::Force::Custom(forces_, new WallLoads([&a_h = ex.horizontal](const State& st) { return a_h(st.getTime()); },
                                                    lower_, has_upper_ ? &upper_ : nullptr, sizes_, N,
                                                    scene.overburden_offset()));

        state_ = system_.realizeTopology();
        const WallPose pose = pose_at(scene, ex.theta0);
        // The spheres are centred on the corners: the wall stands r (lower) and 2r (upper) higher than the analytic
        // pose, touching without penetration (the hinge to r theta^2 / 2).
        place(lower_, pose.lower, r_);
        if (has_upper_) place(upper_, pose.upper, 2.0 * r_);
        system_.realize(state_, Stage::Position);
    }

    const SimTK::MultibodySystem& system() const { return system_; }
    const SimTK::State& initial_state() const { return state_; }
    const SimTK::MobilizedBody& lower() const { return lower_; }
    const SimTK::MobilizedBody& upper() const { return upper_; }
    bool has_upper() const { return has_upper_; }
    // Contacts pressing in a state realized to Velocity.
    int contacts(const SimTK::State& st) const {
        return contact_ ? contact_->getNumContactForces(st) : corners_->count_touching(st);
    }

private:
    // The pairs that can touch, each once: the lower block's base spheres on the ground, the upper block's bottom
    // spheres on the lower block's top face, each top sphere of the upper block on the guide on its own side (a top
    // sphere could reach the other guide only by crossing the wall's thickness). The subsystem also tests the pairs
    // that cannot touch (cliques aside) at every evaluation.
    void add_corner_contacts(const WallScene& scene, const Knobs& k) {
        using SimTK::Vec3;
        const double b = sizes_.b, mu = scene.base_mu(), mu_hinge = scene.hinge_mu();
        std::vector<CornerPair> pairs;
        const SimTK::MobilizedBody& ground = matter_.Ground();
        for (double side : {1.0, -1.0}) {
            pairs.push_back({ground, lower_, Vec3(0), Vec3(0, 1, 0), Vec3(side * b, -sizes_.h_lower, 0), mu});
            if (has_upper_) {
                pairs.push_back({lower_, upper_, Vec3(0, sizes_.h_lower, 0), Vec3(0, 1, 0),
                                 Vec3(side * b, -sizes_.h_upper, 0), mu_hinge});
                // The guide's face at x = side (b + r), its normal pointing back at the wall.
                pairs.push_back({ground, upper_, Vec3(side * (b + r_), 0, 0), Vec3(-side, 0, 0),
                                 Vec3(side * b, sizes_.h_upper, 0), 0.0});
            }
        }
        corners_ = new CornerContacts(std::move(pairs),
                                      {k.stiffness, k.radius, k.dissipation, k.transition_velocity});
        SimTK::Force::Custom(forces_, corners_);  // the force owns corners_
    }

    void add_subsystem_contacts(const WallScene& scene, const Knobs& k) {
        using namespace SimTK;
        tracker_ = std::make_unique<ContactTrackerSubsystem>(system_);
        contact_ = std::make_unique<CompliantContactSubsystem>(system_, *tracker_);
        const double b = sizes_.b, mu = scene.base_mu(), mu_hinge = scene.hinge_mu();
        // Equal materials on both sides combine as E_material / 2^1.5 (Simbody's 2/3-power rule), and equal
        // friction coefficients as themselves (Simbody's 2 mu1 mu2 / (mu1 + mu2)): the base's surfaces carry the
        // base's, the hinge's the hinge's.
        const double E = k.stiffness * std::pow(2.0, 1.5);
        const ContactMaterial rough(E, k.dissipation, mu, mu, 0.0);
        const ContactMaterial rough_hinge(E, k.dissipation, mu_hinge, mu_hinge, 0.0);
        const ContactMaterial smooth(E, k.dissipation, 0.0, 0.0, 0.0);
        contact_->setTransitionVelocity(k.transition_velocity);

        // Cliques: `guides` holds the guides and every sphere that must not meet them; `planes` the half-spaces.
        const ContactCliqueId guides = ContactSurface::createNewContactClique();
        const ContactCliqueId planes = ContactSurface::createNewContactClique();
        // A half-space occupies x > 0 of its frame: turned by -90 deg about z it is y < 0 (the ground).
        matter_.Ground().updBody().addContactSurface(
            Transform(Rotation(-0.5 * Pi, ZAxis), Vec3(0)),
            ContactSurface(ContactGeometry::HalfSpace(), rough).joinClique(planes));

        Body& lower_body = lower_.updBody();
        for (double side : {1.0, -1.0})
            lower_body.addContactSurface(Transform(Vec3(side * b, -sizes_.h_lower, 0)),
                                         ContactSurface(ContactGeometry::Sphere(r_), rough).joinClique(guides));
        if (!has_upper_) return;
        // the hinge: the lower block's top face, y < h1 in its frame
        lower_body.addContactSurface(Transform(Rotation(-0.5 * Pi, ZAxis), Vec3(0, sizes_.h_lower, 0)),
                                     ContactSurface(ContactGeometry::HalfSpace(), rough_hinge).joinClique(planes));
        Body& upper_body = upper_.updBody();
        for (double side : {1.0, -1.0}) {
            upper_body.addContactSurface(Transform(Vec3(side * b, -sizes_.h_upper, 0)),
                                         ContactSurface(ContactGeometry::Sphere(r_), rough_hinge).joinClique(guides));
            upper_body.addContactSurface(Transform(Vec3(side * b, sizes_.h_upper, 0)),
                                         ContactSurface(ContactGeometry::Sphere(r_), smooth));
        }
        // Roller guides: the half-space x > 0 moved to x > b + r, and turned by 180 deg about z to x < -(b + r).
        matter_.Ground().updBody().addContactSurface(
            Transform(Vec3(b + r_, 0, 0)),
            ContactSurface(ContactGeometry::HalfSpace(), smooth).joinClique(guides).joinClique(planes));
        matter_.Ground().updBody().addContactSurface(
            Transform(Rotation(Pi, ZAxis), Vec3(-(b + r_), 0, 0)),
            ContactSurface(ContactGeometry::HalfSpace(), smooth).joinClique(guides).joinClique(planes));
    }

    SimTK::Body::Rigid block_body(double half_h, double mass_per_depth) const {
        using namespace SimTK;
        // I_z = m (b^2 + h^2) / 3 = m R^2 / 3, as the analytic model's homogeneous blocks.
        return Body::Rigid(
            MassProperties(mass_per_depth * kDepth, Vec3(0), UnitInertia::brick(sizes_.b, half_h, 0.5 * kDepth)));
    }

    void place(SimTK::MobilizedBody& body, const BlockPose& p, double lift) {
        body.setQToFitTransform(
            state_, SimTK::Transform(SimTK::Rotation(-p.angle, SimTK::ZAxis), SimTK::Vec3(p.x, p.y + lift, 0)));
    }

    SimTK::MultibodySystem system_;
    SimTK::SimbodyMatterSubsystem matter_;
    SimTK::GeneralForceSubsystem forces_;
    std::unique_ptr<SimTK::ContactTrackerSubsystem> tracker_;    // contact_subsystem = 1 only
    std::unique_ptr<SimTK::CompliantContactSubsystem> contact_;  // contact_subsystem = 1 only
    CornerContacts* corners_ = nullptr;                          // contact_subsystem = 0; owned by its Force
    BlockSizes sizes_;
    double r_;
    SimTK::MobilizedBody lower_, upper_;
    bool has_upper_ = false;
    SimTK::State state_;
};

}  // namespace

void check_compliant_settings(const EngineSettings& settings) { (void)read_knobs(settings); }

Trajectory simulate_compliant(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) {
    // SimbodyEngine::simulate, the only caller, has checked dt and the scene.
    const Knobs knobs = read_knobs(settings);
    const double dt = settings.dt;
    const CompliantScene w(scene, ex, knobs);
    const BlockSizes s = block_sizes(scene);
    const double r = knobs.radius;
    const bool vssw = w.has_upper();
    const SimTK::MobilizedBody& lower = w.lower();
    const SimTK::MobilizedBody& upper = w.upper();
    // Rest positions: the analytic ones lifted by the spheres (r under the lower block, 2r under the upper one).
    const WallBodies bodies{lower, upper, vssw, s, WallEnergy(scene, kDepth, r), scene.overburden_offset()};

    const QuietStdout quiet;
    std::unique_ptr<SimTK::Integrator> integ;
    if (knobs.integrator == 1)
        integ = std::make_unique<SimTK::CPodesIntegrator>(w.system());
    else
        integ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(w.system());
    integ->setAccuracy(knobs.accuracy);
    integ->setAllowInterpolation(knobs.interpolate);
    integ->setFinalTime(ex.t_end);
    // CPodes stops after 500 internal steps per stepTo by default and then prints "[CPODES ERROR] mxstep steps
    // taken" on stderr: measured at the first impact of the Fig. 6 VSSW with accuracy 1e-8 or transition_velocity
    // 1e-5 (1 ms reports). A larger limit keeps stderr clean; the loop below still guards against no progress.
    integ->setInternalStepLimit(kStepsPerCall);
    try {
        integ->initialize(w.initial_state());
    } catch (const std::exception& e) {
        throw EngineFailure(fmt::format("{}: initialisation failed: {}", kName, e.what()));
    }

    Trajectory out;
    const long every = sample_every(settings, dt);
    auto record = [&](double t) {
        const SimTK::State& st = integ->getState();
        w.system().realize(st, SimTK::Stage::Velocity);
        if (ex.motion_only) {
            out.samples.push_back(motion_of(bodies, st, t));
            return;
        }
        TrajectorySample p = sample_of(bodies, st, t);
        p.contacts = w.contacts(st);
        out.samples.push_back(p);
    };

    // Not the stepping kit's loop (multibody/kit/step_loop.hpp): the integrator picks its own steps and sees the
    // ground motion (WallLoads) between reports, so there is no step to drive at its midpoint, no N to push per step
    // (a force element), and out.steps is the integrator's count; the samples use the kit's energy sum (sample_of).
    const long n_reports = std::lround(ex.t_end / dt);
    record(0.0);
    // dt is the reporting interval: CPodes sees the ground motion between reports at steps of its own choosing.
    // The corner spheres keep every contact r apart (the monitor's contact gap).
    RunMonitor monitor(kName, scene, ex, dt, knobs.limits, false, r);
    for (long i = 1; i <= n_reports; ++i) {
        const double t = std::min(static_cast<double>(i) * dt, ex.t_end);
        // stepTo returns early at the start of the run (StartOfContinuousInterval, nothing integrated) and when the
        // internal step limit is reached: step again until the report time is reached (a sample labelled with a
        // time the state has not reached moved the first impact of a tight-accuracy run by 0.4 ms).
        for (int call = 0; integ->getTime() < t && !integ->isSimulationOver(); ++call) {
            if (call == kMaxCallsPerReport)
                throw EngineFailure(fmt::format("{}: the integrator is stuck at t = {:.9g} s ({} steps taken)",
                                                kName, integ->getTime(), integ->getNumStepsTaken()));
            try {
                integ->stepTo(t);
            } catch (const std::exception& e) {
                throw EngineFailure(fmt::format("{}: {} at t = {:.6g} s", kName, e.what(), integ->getTime()));
            }
        }
        if (integ->isSimulationOver() &&
            integ->getTerminationReason() != SimTK::Integrator::ReachedFinalTime)
            throw EngineFailure(
                fmt::format("{}: the integrator stopped ({}) at t = {:.6g} s", kName,
                            SimTK::Integrator::getTerminationReasonString(integ->getTerminationReason()).c_str(),
                            integ->getTime()));
        out.steps = integ->getNumStepsTaken();

        const SimTK::State& now = integ->getState();
        w.system().realize(now, SimTK::Stage::Velocity);
        const auto verdict =
            monitor.check(t, {block_state(lower, now), vssw ? block_state(upper, now) : kNoBlock});
        if (RunMonitor::records(i, n_reports, every, verdict)) record(t);
        if (RunMonitor::ends_run(verdict, out)) break;
    }
    out.slip = monitor.slip();
    return out;
}

}  // namespace vssw::multibody

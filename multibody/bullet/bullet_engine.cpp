// Bullet adapter: the wall as boxes in a btDiscreteDynamicsWorld, constrained to the x-y plane.
//
// Scene (from the analytic description; depth 1 m, so masses and energies are per unit depth as in the paper):
//  - ground: a thick static box (box-box contact keeps sharp corners; a plane would not);
//  - lower and upper blocks: boxes (b, h1) and (b, h2) (one box (b, h) for a parapet);
//  - the roller (VSSW only): each top corner of the upper block may not cross the vertical line of its face, x <= +b
//    for the right corner and x >= -b for the left, and slides along it freely and without friction: two one-sided
//    point-on-line limits (btGeneric6DofSpring2Constraint, linear x limited on one side, y free). Only the one on the
//    pivot's side is enabled (the one whose corner is further out; see choose_roller): near theta1 = 0 the loop ground-hinge-both guides is
//    redundant and nearly singular, and with both enabled the solver pumps large opposing impulses into that null
//    space (measured: 4e6 N squeezing the top, whose friction at the hinge braked the wall and made the first impact
//    1-11 % late, worse with more iterations). A contact guide cannot do this job: below the held corner the upper block's face
//    leans outwards (it turns about that corner), so any guide surface covering the heights the corner rises through
//    is penetrated by the face;
//  - collision pairs that cannot touch are filtered out (ground-upper);
//  - N: a force at the centre of the top face, only when xi > 0;
//  - ground motion: by default pseudo-forces -m a_h(t) at the centres of mass on fixed supports; with the setting
//    moving_supports = 1 the ground (and the roller, anchored to it) moves instead, as a kinematic body following
//    x_g(t), the ground acceleration integrated twice. For rigid bodies the two are the same motion relative to the
//    ground; the cross-engine suite checks that they agree.
#include "multibody/bullet/bullet_engine.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/run_monitor.hpp"
#include "multibody/settings_reader.hpp"
#include "multibody/scene_geometry.hpp"

namespace vssw::multibody {
namespace {

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the boxes

// Collision groups: each body lists what it may touch.
enum Group : int { kGround = 1, kLower = 2, kUpper = 4 };

struct Knobs {
    int iterations;           // sequential-impulse iterations per step
    double erp;               // error reduction of penetration (used only by split impulse's position pass)
    FailureLimits limits;      // run_monitor.hpp
    bool moving_supports;      // move the ground instead of applying pseudo-forces
};

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("Bullet", s, {"erp", "slide_limit", "penetration_limit", "moving_supports"});
    Knobs k{};
    k.iterations = s.iterations > 0 ? s.iterations : 20;
    k.erp = r.non_negative("erp", 0.2);
    k.limits = FailureLimits::read(r);
    k.moving_supports = r.flag("moving_supports");
    return k;
}

btTransform pose_transform(const BlockPose& p) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(p.x, p.y, 0.0));
    t.setRotation(btQuaternion(btVector3(0, 0, 1), -p.angle));  // Bullet turns counter-clockwise
    return t;
}

// Clockwise angle of a body about z, from its basis.
double clockwise_angle(const btRigidBody& body) {
    const btMatrix3x3& r = body.getWorldTransform().getBasis();
    return -std::atan2(r[1][0], r[0][0]);
}

// Where a moving ground is: Bullet asks a kinematic body's motion state for its transform every step and derives
// the body's velocity from the change, which the contacts and the roller then see.
class GroundMotionState : public btMotionState {
public:
    explicit GroundMotionState(const btVector3& centre) : centre_(centre) {}
    void set_displacement(double x) { x_ = x; }
    void getWorldTransform(btTransform& t) const override {
        t.setIdentity();
        t.setOrigin(centre_ + btVector3(x_, 0, 0));
    }
    void setWorldTransform(const btTransform&) override {}

private:
    btVector3 centre_;
    double x_ = 0.0;
};

class BulletWorld {
public:
    BulletWorld(const WallScene& scene, const Knobs& knobs, double theta0)
        : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_), sizes_(block_sizes(scene)) {
        const double g = scene.gravity();
        world_.setGravity(btVector3(0, -g, 0));
        btContactSolverInfo& info = world_.getSolverInfo();
        // Settings from ../shared/DESIGN.md, each measured on a rocking block: no restitution below any velocity, no
        // warm start (a rocking contact jumps from corner to corner), no slop, split impulse so that position
        // correction adds no energy.
        info.m_numIterations = knobs.iterations;
        info.m_restitutionVelocityThreshold = 0;
        info.m_warmstartingFactor = 0;
        info.m_linearSlop = 0;
        info.m_splitImpulse = 1;
        info.m_splitImpulsePenetrationThreshold = -1e9;  // always split
        info.m_erp2 = knobs.erp;

        const double b = sizes_.b, h = sizes_.h_lower + sizes_.h_upper;
        // A moving ground travels with the record's displacement (metres, or tens of metres under a long constant
        // acceleration): make it wide enough that the wall never reaches its edge.
        const double half_width = knobs.moving_supports ? 1e4 : 4.0 * h + 10.0 * b;
        btRigidBody& ground = add_static(btVector3(half_width, h, kDepth), btVector3(0, -h, 0), 1.0, kGround, kLower);
        if (knobs.moving_supports) {
            ground_motion_ = std::make_unique<GroundMotionState>(btVector3(0, -h, 0));
            ground.setMotionState(ground_motion_.get());
            ground.setCollisionFlags(ground.getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
            ground.setActivationState(DISABLE_DEACTIVATION);
        }
        ground_ = &ground;
        lower_ = add_block(sizes_.b, sizes_.h_lower, sizes_.m_lower, scene.friction, kLower,
                           kGround | (scene.vssw ? kUpper : 0));
        if (scene.vssw) upper_ = add_block(sizes_.b, sizes_.h_upper, sizes_.m_upper, scene.friction, kUpper, kLower);
        set_pose(pose_at(scene, theta0));
        if (scene.vssw)
            for (double side : {-1.0, 1.0}) add_roller(ground, side, 2.0 * h);
    }

    btDiscreteDynamicsWorld& world() { return world_; }
    // Moves the ground (moving supports only) to x for the coming step.
    void move_ground(double x) {
        if (ground_motion_) ground_motion_->set_displacement(x);
    }
    double ground_velocity() const { return ground_ ? ground_->getLinearVelocity().x() : 0.0; }
    btRigidBody& lower() { return *lower_; }
    btRigidBody* upper() { return upper_; }
    // Enables the guide whose corner is further out (the pivot's side while rocking: the other corner is inside its
    // line by about b theta2^2). Deciding by the corners rather than by the sign of theta1 keeps a guide from being
    // enabled while its corner sits past its line: at rest theta1 jitters about zero, and switching by its sign let
    // the free corner drift out and then be yanked back (measured: an energy jump from 0.4 J to 4 kJ).
    void choose_roller() {
        if (rollers_.empty()) return;
        const btTransform& t = upper_->getWorldTransform();
        // The guides' lines move with the ground: compare the corners with where the ground is during the coming
        // step (a moving ground travels v dt per step, far more than the corners' offsets at rest).
        btTransform ground_now;
        if (ground_motion_) ground_motion_->getWorldTransform(ground_now);
        const double x0 = ground_motion_ ? ground_now.getOrigin().x() : 0.0;
        const bool left = left_guide_binds((t * btVector3(sizes_.b, sizes_.h_upper, 0)).x(),
                                           (t * btVector3(-sizes_.b, sizes_.h_upper, 0)).x(), x0, sizes_.b);
        rollers_[0]->setEnabled(left);
        rollers_[1]->setEnabled(!left);
    }

    int contact_points() {
        int n = 0;
        for (int i = 0; i < dispatcher_.getNumManifolds(); ++i) n += dispatcher_.getManifoldByIndexInternal(i)->getNumContacts();
        return n;
    }

private:
    // One-sided guide for the top corner on side `side`: side * (x_corner - side b) <= 0, y free, rotation free.
    // Frame A is the ground's (world axes) at the guide line; frame B the corner: Bullet measures B's origin from A's
    // in A's axes, so the x offset is x_corner - side b in world terms.
    void add_roller(btRigidBody& ground, double side, double top) {
        btTransform in_ground, in_upper;
        in_ground.setIdentity();
        in_ground.setOrigin(btVector3(side * sizes_.b, top, 0) - ground.getCenterOfMassPosition());
        in_upper.setIdentity();
        in_upper.setOrigin(btVector3(side * sizes_.b, sizes_.h_upper, 0));
        auto c = std::make_unique<btGeneric6DofSpring2Constraint>(ground, *upper_, in_ground, in_upper);
        constexpr double kFar = 1e3;  // [m] "no limit" on the slack side
        c->setLinearLowerLimit(btVector3(side > 0 ? -kFar : 0.0, 1.0, 1.0));  // y, z: lower > upper means free
        c->setLinearUpperLimit(btVector3(side > 0 ? 0.0 : kFar, -1.0, -1.0));
        c->setAngularLowerLimit(btVector3(1.0, 1.0, 1.0));  // all rotations free (the planar factors hold x, y)
        c->setAngularUpperLimit(btVector3(-1.0, -1.0, -1.0));
        world_.addConstraint(c.get(), true);  // the upper block and the ground do not collide anyway
        rollers_.push_back(std::move(c));
    }

    btRigidBody& add_static(const btVector3& half, const btVector3& centre, double friction, int group, int mask) {
        shapes_.push_back(std::make_unique<btBoxShape>(half));
        btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shapes_.back().get());
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody& body = *bodies_.back();
        btTransform t;
        t.setIdentity();
        t.setOrigin(centre);
        body.setWorldTransform(t);
        body.setFriction(friction);
        body.setRestitution(0.0);
        body.setContactProcessingThreshold(0.0);
        world_.addRigidBody(&body, group, mask);
        return body;
    }

    btRigidBody* add_block(double half_w, double half_h, double mass_per_depth, double friction, int group,
                           int mask) {
        shapes_.push_back(std::make_unique<btBoxShape>(btVector3(half_w, half_h, 0.5 * kDepth)));
        const double mass = mass_per_depth * kDepth;
        btVector3 inertia;
        shapes_.back()->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shapes_.back().get(), inertia);
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody& body = *bodies_.back();
        body.setFriction(friction);
        body.setRestitution(0.0);
        body.setContactProcessingThreshold(0.0);
        body.setActivationState(DISABLE_DEACTIVATION);  // a slowly rocking wall must not be put to sleep
        body.setLinearFactor(btVector3(1, 1, 0));         // planar motion
        body.setAngularFactor(btVector3(0, 0, 1));
        world_.addRigidBody(&body, group, mask);
        return &body;
    }

    void set_pose(const WallPose& pose) {
        lower_->setWorldTransform(pose_transform(pose.lower));
        if (upper_) upper_->setWorldTransform(pose_transform(pose.upper));
    }

    btDefaultCollisionConfiguration config_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    BlockSizes sizes_;
    std::vector<std::unique_ptr<btBoxShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
    std::vector<std::unique_ptr<btGeneric6DofSpring2Constraint>> rollers_;
    std::unique_ptr<GroundMotionState> ground_motion_;
    btRigidBody* ground_ = nullptr;
    btRigidBody* lower_ = nullptr;
    btRigidBody* upper_ = nullptr;

public:
    ~BulletWorld() {
        for (auto& c : rollers_) world_.removeConstraint(c.get());
        for (auto& body : bodies_) world_.removeRigidBody(body.get());
    }
};

class BulletEngine final : public Engine {
public:
    std::string name() const override { return "bullet"; }
    std::string version() const override {
        return fmt::format("Bullet {}.{:02d} (double precision)", btGetVersion() / 100, btGetVersion() % 100);
    }
    EngineSettings default_settings() const override {
        EngineSettings s;
        // Measured (README, "Bullet"): at 2e-4 s threshold and period are within 0.15 % and 0.05 % of the analytic
        // model on every wall of the issue, errors falling with the step; 20 iterations give the period and the
        // restitution of 100 and a threshold within 0.15 % (0.09 % at 100), 2-4 times faster.
        s.dt = 2e-4;
        s.iterations = 20;
        return s;
    }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { (void)read_knobs(settings); }
};

Trajectory BulletEngine::simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "Bullet time step dt (s)", "a positive finite number",
            settings.dt);
    const Knobs knobs = read_knobs(settings);
    BulletWorld w(scene, knobs, ex.theta0);
    const BlockSizes s = block_sizes(scene);
    const double g = scene.gravity();
    const double N = scene.overburden() * kDepth;
    const double h_total = s.h_lower + s.h_upper;
    btRigidBody& lower = w.lower();
    btRigidBody* upper = w.upper();
    btRigidBody& top_body = upper ? *upper : lower;
    const double top_half = upper ? s.h_upper : s.h_lower;

    auto top_centre = [&]() { return top_body.getWorldTransform() * btVector3(0, top_half, 0); };
    const double y_top0 = 2.0 * h_total;
    const double y_lower0 = s.h_lower, y_upper0 = 2.0 * s.h_lower + s.h_upper;

    Trajectory out;
    const long every = sample_every(settings, settings.dt);
    auto record = [&](double t) {
        TrajectorySample p{};
        p.t = t;
        p.theta1 = clockwise_angle(lower);
        p.theta1_dot = -lower.getAngularVelocity().z();
        p.theta2 = upper ? clockwise_angle(*upper) : 0.0;
        p.top_dy = top_centre().y() - y_top0;
        const double v_ground = w.ground_velocity();
        auto kinetic = [&](const btRigidBody& body) {
            const btVector3 v = body.getLinearVelocity() - btVector3(v_ground, 0, 0), wv = body.getAngularVelocity();
            const double m = 1.0 / body.getInvMass();
            const double I = 1.0 / body.getInvInertiaDiagLocal().z();
            return 0.5 * m * v.length2() + 0.5 * I * wv.z() * wv.z();
        };
        p.kinetic = (kinetic(lower) + (upper ? kinetic(*upper) : 0.0)) / kDepth;
        p.potential = (s.m_lower * kDepth * g * (lower.getCenterOfMassPosition().y() - y_lower0) +
                       (upper ? s.m_upper * kDepth * g * (upper->getCenterOfMassPosition().y() - y_upper0) : 0.0) +
                       N * p.top_dy) /
                      kDepth;
        p.contacts = w.contact_points();
        out.samples.push_back(p);
        return p;
    };

    const double dt = settings.dt;
    const long n_steps = std::lround(ex.t_end / dt);
    double x_g = 0.0, v_g = 0.0;  // the ground's displacement and velocity (moving supports)
    record(0.0);
    RunMonitor monitor("Bullet", scene, ex, dt, knobs.limits);
    for (long i = 1; i <= n_steps; ++i) {
        const double t0 = static_cast<double>(i - 1) * dt;
        // Pseudo-force of the ground motion at the step's midpoint (its impulse over the step to second order).
        const double a_h = ex.horizontal(t0 + 0.5 * dt);
        if (knobs.moving_supports) {
            // The ground's displacement at the end of the step: velocity and position by the midpoint rule, the
            // same impulse per step as the pseudo-forces get.
            const double v_next = v_g + dt * a_h;
            x_g += 0.5 * dt * (v_g + v_next);
            v_g = v_next;
            w.move_ground(x_g);
        } else if (a_h != 0.0) {
            lower.applyCentralForce(btVector3(-s.m_lower * kDepth * a_h, 0, 0));
            if (upper) upper->applyCentralForce(btVector3(-s.m_upper * kDepth * a_h, 0, 0));
        }
        if (N > 0.0) top_body.applyForce(btVector3(0, -N, 0), top_centre() - top_body.getCenterOfMassPosition());
        w.choose_roller();
        w.world().stepSimulation(dt, 0, dt);
        ++out.steps;

        const double t = static_cast<double>(i) * dt;
        const double theta = clockwise_angle(lower);
        const double rate = -lower.getAngularVelocity().z();
        const btVector3 right = lower.getWorldTransform() * btVector3(s.b, -s.h_lower, 0);
        const btVector3 left = lower.getWorldTransform() * btVector3(-s.b, -s.h_lower, 0);
        const auto verdict =  // corners relative to the (moving) ground
            monitor.check(t, theta, rate, {right.x() - x_g - s.b, right.y(), left.x() - x_g + s.b, left.y()});
        if (RunMonitor::records(i, n_steps, every, verdict)) record(t);
        if (RunMonitor::ends_run(verdict, out)) return out;
    }
    return out;
}

}  // namespace

std::unique_ptr<Engine> make_bullet_engine() { return std::make_unique<BulletEngine>(); }

}  // namespace vssw::multibody

// Bullet adapter: the wall as boxes in a btDiscreteDynamicsWorld, constrained to the x-y plane.
//
// Scene (from the analytic description; depth 1 m, so masses and energies are per unit depth as in the paper):
//  - ground: a thick static box whose top face is y = 0;
//  - lower and upper blocks: boxes (b, h1) and (b, h2) (one box (b, h) for a parapet), planar motion;
//  - contacts (corner_contacts.hpp): one point per corner that can touch, written into Bullet's manifolds every step
//    with its signed distance: the lower block's bottom corners on the ground, the upper block's bottom corners on
//    the lower block's top face, and (VSSW only) the roller: each top corner of the upper block on the vertical line
//    of its face, x <= +b for the right corner and x >= -b for the left, frictionless. A corner apart is a
//    speculative row, so every corner that closes within a step takes its share of an impact in that step. A contact
//    guide surface cannot be the roller: below the held corner the upper block's face leans outwards (it turns about
//    that corner), so any guide surface covering the heights the corner rises through is penetrated by the face;
//  - rounded corners (corner radius r > 0): the same manifolds from arcs instead of corners (corner_contacts.hpp:
//    each base arc's lowest point on the ground, each pair of hinge arcs by their centres' distance less 2 r); the
//    boxes only give the masses and inertias, the rectangles';
//  - no broadphase, narrowphase, islands or sleeping (planar_world.hpp);
//  - N: a force at the centre of the top face, only when xi > 0;
//  - ground motion: by default pseudo-forces -m a_h(t) at the centres of mass on fixed supports; with the setting
//    moving_supports = 1 the ground (and the roller, anchored to it) moves instead, as a kinematic body following
//    x_g(t), the ground acceleration integrated twice. For rigid bodies the two are the same motion relative to the
//    ground; the cross-engine suite checks that they agree;
//  - a flexible top support (WallScene::diaphragm, T_d > 0): the roller's lines on a kinematic carrier of their own,
//    moved to the ground's displacement plus u_d(t) of Eq. (9d) each step (docs/model/top-support.md).
#include "multibody/bullet/bullet_engine.hpp"

#include <btBulletDynamicsCommon.h>

#include "multibody/bullet/corner_contacts.hpp"
#include "multibody/bullet/planar_world.hpp"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/energy.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_angles.hpp"
#include "multibody/kit/step_loop.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw::multibody {
namespace {

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the boxes

constexpr int kDefaultIterations = 10;  // sequential-impulse iterations (default_settings)

struct Knobs {
    int iterations;           // sequential-impulse iterations per step
    double erp;               // error reduction of penetration (used only by split impulse's position pass)
    FailureLimits limits;      // run_monitor.hpp
    bool moving_supports;      // move the ground instead of applying pseudo-forces
};

// Ranges (SettingDescription::lo/hi): erp is a fraction of the penetration corrected per step, [0, 1].
const std::vector<SettingDescription>& setting_table() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.001", "s", "the step (docs/engines.md \"Bullet\": every target met at 1, 0.5 and 0.2 ms)"},
        {"iterations", std::to_string(kDefaultIterations), "",
         "sequential-impulse solver iterations per step (20 to 200 move the restitution by 0.13 % at most)"},
        {"erp", "0.2", "", "error reduction of penetration, used only by split impulse's position pass", 0.0, 1.0},
        {"moving_supports", "0", "0/1", "1: move the ground as a kinematic body instead of applying pseudo-forces", 0.0, 1.0},
    });
    return table;
}

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("Bullet", s, setting_table());
    Knobs k{};
    k.iterations = s.iterations > 0 ? s.iterations : kDefaultIterations;
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

// Bullet's collision pools sized for this scene: a few bodies, a few pairs. Its defaults (4096 manifolds, 4096
// collision algorithms) are pools of megabytes that its constructor links element by element, so every run, in a
// fresh child, faulted in and wrote them: measured with perf, 12 % of a free-vibration run of `vssw free --engine
// bullet` in the constructor and most of the run's 21 % in the kernel's page faults. A pool that runs out falls back
// to the heap (Bullet's dispatcher allows it by default), so the size changes where the memory comes from, never the
// physics: the outputs are byte-identical.
btDefaultCollisionConstructionInfo small_pools() {
    constexpr int kPoolSize = 64;  // elements; the wall has at most a handful of pairs at once
    btDefaultCollisionConstructionInfo info;
    info.m_defaultMaxPersistentManifoldPoolSize = kPoolSize;
    info.m_defaultMaxCollisionAlgorithmPoolSize = kPoolSize;
    return info;
}

class BulletWorld {
public:
    BulletWorld(const WallScene& scene, const Knobs& knobs, double theta0)
        : config_(small_pools()), dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_), sizes_(block_sizes(scene)) {
        const double g = scene.gravity();
        world_.setGravity(btVector3(0, -g, 0));
        btContactSolverInfo& info = world_.getSolverInfo();
        // Settings from docs/contributing/engines.md ("The libraries as Debian ships them"), each measured on a rocking
        // block: no restitution below any velocity, no warm start (a rocking contact jumps from corner to corner), no
        // slop, split impulse so that position correction adds no energy.
        info.m_numIterations = knobs.iterations;
        info.m_restitutionVelocityThreshold = 0;
        info.m_warmstartingFactor = 0;
        info.m_linearSlop = 0;
        info.m_splitImpulse = 1;
        // Bullet splits only a penetration deeper than this threshold (penetration is negative): +1e9 splits every
        // one. (It was -1e9, meant as "always" but meaning "never": penetration was pushed out through the velocity
        // with m_erp, energy in at every landing; measured in docs/contributing/engines.md, "Bullet".)
        info.m_splitImpulsePenetrationThreshold = 1e9;
        info.m_erp2 = knobs.erp;

        const double b = sizes_.b, h = sizes_.h_lower + sizes_.h_upper;
        // A moving ground travels with the record's displacement (metres, or tens of metres under a long constant
        // acceleration): make it wide enough that the wall never reaches its edge.
        const double half_width = knobs.moving_supports ? 1e4 : 4.0 * h + 10.0 * b;
        btRigidBody& ground = add_static(btVector3(half_width, h, kDepth), btVector3(0, -h, 0));
        if (knobs.moving_supports) {
            ground_motion_ = std::make_unique<GroundMotionState>(btVector3(0, -h, 0));
            ground.setMotionState(ground_motion_.get());
            ground.setCollisionFlags(ground.getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
            ground.setActivationState(DISABLE_DEACTIVATION);
        }
        ground_ = &ground;
        // A flexible top support: the guides' lines on a kinematic carrier of their own, its origin's x their offset.
        btRigidBody* carrier = nullptr;
        if (scene.vssw && !scene.diaphragm.is_rigid()) {
            carrier = &add_static(btVector3(b, b, kDepth), btVector3(0, 0, 0));
            carrier_motion_ = std::make_unique<GroundMotionState>(btVector3(0, 0, 0));
            carrier->setMotionState(carrier_motion_.get());
            carrier->setCollisionFlags(carrier->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
            carrier->setActivationState(DISABLE_DEACTIVATION);
        }
        lower_ = add_block(sizes_.b, sizes_.h_lower, sizes_.m_lower);
        if (scene.vssw) upper_ = add_block(sizes_.b, sizes_.h_upper, sizes_.m_upper);
        set_pose(pose_at(scene, theta0));
        contacts_ = std::make_unique<CornerContacts>(ground, *lower_, upper_, sizes_.b, sizes_.h_lower,
                                                     sizes_.h_upper, scene.base_mu(), scene.hinge_mu(),
                                                     scene.corner_radius(), carrier);
    }

    // One step of dt (forces applied before it act during it).
    void step(double dt) {
        world_.begin_step(dt);
        contacts_->update();
        world_.finish_step(dt, contacts_->manifolds(), contacts_->count());
    }
    // Moves the ground (moving supports only) to x for the coming step.
    void move_ground(double x) {
        if (ground_motion_) ground_motion_->set_displacement(x);
    }
    // Moves a flexible top support's carrier to x (the ground's displacement plus u_d) for the coming step.
    void move_top(double x) {
        if (carrier_motion_) carrier_motion_->set_displacement(x);
    }
    double ground_velocity() const { return ground_ ? ground_->getLinearVelocity().x() : 0.0; }
    btRigidBody& lower() { return *lower_; }
    btRigidBody* upper() { return upper_; }
    int contact_points() const { return contacts_->touching(); }

private:
    btRigidBody& add_static(const btVector3& half, const btVector3& centre) {
        shapes_.push_back(std::make_unique<btBoxShape>(half));
        btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shapes_.back().get());
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody& body = *bodies_.back();
        btTransform t;
        t.setIdentity();
        t.setOrigin(centre);
        body.setWorldTransform(t);
        world_.addRigidBody(&body, 0, 0);  // no broadphase pairs: the contacts come from the corners
        return body;
    }

    btRigidBody* add_block(double half_w, double half_h, double mass_per_depth) {
        shapes_.push_back(std::make_unique<btBoxShape>(btVector3(half_w, half_h, 0.5 * kDepth)));
        const double mass = mass_per_depth * kDepth;
        btVector3 inertia;
        shapes_.back()->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shapes_.back().get(), inertia);
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody& body = *bodies_.back();
        body.setActivationState(DISABLE_DEACTIVATION);  // a slowly rocking wall must not be put to sleep
        body.setLinearFactor(btVector3(1, 1, 0));         // planar motion
        body.setAngularFactor(btVector3(0, 0, 1));
        // Rotation about z only, with a diagonal inertia: the gyroscopic term is zero, so Bullet need not compute it.
        body.setFlags(body.getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
        world_.addRigidBody(&body, 0, 0);
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
    PlanarDynamicsWorld world_;
    BlockSizes sizes_;
    std::vector<std::unique_ptr<btBoxShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
    std::unique_ptr<CornerContacts> contacts_;
    std::unique_ptr<GroundMotionState> ground_motion_;
    std::unique_ptr<GroundMotionState> carrier_motion_;  // a flexible top support only
    btRigidBody* ground_ = nullptr;
    btRigidBody* lower_ = nullptr;
    btRigidBody* upper_ = nullptr;

public:
    ~BulletWorld() {
        for (auto& body : bodies_) world_.removeRigidBody(body.get());
    }
};

class BulletEngine final : public Engine {
public:
    std::string name() const override { return "bullet"; }
    std::string display_name() const override { return "Bullet"; }
    double cost_per_simulated_second() const override { return 2.5e-3; }  // at 1 ms, docs/measurements/speed.md
    std::string version() const override {
        return fmt::format("Bullet {}.{:02d} (double precision)", btGetVersion() / 100, btGetVersion() % 100);
    }
    EngineSettings default_settings() const override {
        EngineSettings s;
        // Measured (docs/contributing/engines.md, "Bullet"): at 1, 0.5 and 0.2 ms with 10 iterations every wall of the
        // issue is within the targets, errors in threshold and period falling with the step; 20 to 200 iterations move
        // the restitution by 0.13 % at most (Table 1 #1 at xi 0.5). 1 ms is the cheapest of them. The flight off the
        // roller that once kept the step at 0.2 ms (Table 1 #14, xi 0.5, from 0.8 alpha1: +3.16 % at 1 ms) was N's
        // torque missing from Bullet's friction rows (simulate()); with N as an impulse it is -0.063 % at 1 ms against
        // the analytic model with the unilateral roller, ODE's figure.
        s.dt = 1e-3;
        s.iterations = kDefaultIterations;
        return s;
    }
    std::vector<SettingDescription> setting_descriptions() const override { return setting_table(); }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { (void)read_knobs(settings); }
};

// The stepping kit's hooks (step_loop.hpp) on a BulletWorld.
class BulletStepping {
public:
    BulletStepping(BulletWorld& w, const WallScene& scene, const Knobs& knobs, double dt)
        : w_(w),
          knobs_(knobs),
          energy_(scene, kDepth),
          s_(block_sizes(scene)),
          N_(scene.overburden() * kDepth),
          lower_(w.lower()),
          upper_(w.upper()),
          top_body_(upper_ ? *upper_ : lower_),
          top_half_(upper_ ? s_.h_upper : s_.h_lower),
          load_x_(scene.overburden_offset()),
          dt_(dt) {}

    void drive(const GroundStep& g) {
        if (knobs_.moving_supports) {
            w_.move_ground(g.x);  // the supports' displacement at the end of the step (midpoint rule)
        } else if (g.a_h != 0.0) {
            lower_.applyCentralForce(btVector3(-s_.m_lower * kDepth * g.a_h, 0, 0));
            if (upper_) upper_->applyCentralForce(btVector3(-s_.m_upper * kDepth * g.a_h, 0, 0));
        }
        w_.move_top(g.x + g.top_u);  // u_d(t) from the ground at the step's end (step_loop.hpp)
    }
    // N as its impulse over the step, added to the velocities before the solve, not as a force: Bullet's solver adds a
    // force's torque to a body's spin only after the solve, and its friction rows leave that torque out of the
    // relative velocity they hold at zero (btSequentialImpulseConstraintSolver::setupFrictionConstraint reads the
    // force's linear impulse but not its angular one; the normal rows read both). N is the one force here with a
    // torque about a centre of mass, so the hinge slid every step by the spin N's torque gave in it (5.4 mm/s at 1 ms
    // on Table 1 #14 at xi 0.5 off the roller), friction doing work F v_t: a loss first order in the step
    // (docs/contributing/engines.md "Bullet"). As an impulse every row sees it; the same step of symplectic Euler.
    void push_overburden() {
        top_body_.applyImpulse(btVector3(0, -N_ * dt_, 0), load_point() - top_body_.getCenterOfMassPosition());
    }
    void step(const StepTimes& st, const GroundStep&) {
        angles_.forget();
        w_.step(st.dt);
    }
    WallState state(const GroundStep& g) const {
        auto block = [&](const btRigidBody& body, double angle) {  // relative to the (moving) ground
            const btVector3 c = body.getCenterOfMassPosition(), v = body.getLinearVelocity();
            const btMatrix3x3& r = body.getWorldTransform().getBasis();
            // The clockwise angle's cosine and sine as the basis holds them (clockwise_angle's two entries).
            return BlockState{c.x() - g.x, c.y(), angle, v.x() - g.v, v.y(), -body.getAngularVelocity().z(),
                              r[0][0], -r[1][0]};
        };
        return {block(lower_, lower_angle()), upper_ ? block(*upper_, upper_angle()) : kNoBlock};
    }
    Rocking rocking() const { return {lower_angle(), -lower_.getAngularVelocity().z()}; }
    void fill(TrajectorySample& p) const {
        p.theta2 = upper_ ? upper_angle() : 0.0;
        const double v_ground = w_.ground_velocity();
        auto kinetic = [&](const btRigidBody& body) {
            const btVector3 v = body.getLinearVelocity() - btVector3(v_ground, 0, 0), wv = body.getAngularVelocity();
            const double m = 1.0 / body.getInvMass();
            const double I = 1.0 / body.getInvInertiaDiagLocal().z();
            return 0.5 * m * v.length2() + 0.5 * I * wv.z() * wv.z();  // Bullet's own 3-D sum (v.z() is 0)
        };
        energy_.fill(p, {kinetic(lower_), upper_ ? kinetic(*upper_) : 0.0, lower_.getCenterOfMassPosition().y(),
                         upper_ ? upper_->getCenterOfMassPosition().y() : 0.0, load_point().y()});
        p.contacts = w_.contact_points();
    }
private:
    double lower_angle() const { return angles_.lower([&] { return clockwise_angle(lower_); }); }
    double upper_angle() const { return angles_.upper([&] { return clockwise_angle(*upper_); }); }
    // N's point: the top face's centre, or e from it toward theta1 > 0 (analytic/geometry.hpp).
    btVector3 load_point() const { return top_body_.getWorldTransform() * btVector3(load_x_, top_half_, 0); }

    BulletWorld& w_;
    const Knobs& knobs_;
    WallEnergy energy_;
    BlockSizes s_;
    double N_;
    btRigidBody& lower_;
    btRigidBody* upper_;
    btRigidBody& top_body_;
    double top_half_;
    double load_x_;  // N's point on the top face from its centre, toward theta1 > 0 [m]
    double dt_;
    mutable StepAngles angles_;  // read by state(), rocking() and fill() of one step
};

Trajectory BulletEngine::simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "Bullet time step dt (s)", "a positive finite number",
            settings.dt);
    const Knobs knobs = read_knobs(settings);
    BulletWorld w(scene, knobs, ex.theta0);
    BulletStepping stepping(w, scene, knobs, settings.dt);
    RunMonitor monitor("Bullet", scene, ex, settings.dt, knobs.limits);
    const StepLoop loop{settings.dt, sample_every(settings, settings.dt), knobs.moving_supports,
                        scene.overburden() > 0.0, scene.diaphragm};
    return run_fixed_steps(stepping, ex, loop, monitor);
}

}  // namespace

std::unique_ptr<Engine> make_bullet_engine() { return std::make_unique<BulletEngine>(); }

}  // namespace vssw::multibody

// DART adapter: the wall as boxes on planar joints in a dart::simulation::World, stepped by DART's boxed LCP solver
// (Dantzig, PGS fallback: the World's default).
//
// Scene (from the analytic description; depth 1 m, so masses and energies are per unit depth as in the paper):
//  - ground: a skeleton welded to the world, a box whose top face is y = 0; with moving_supports = 1 the skeleton is
//    on a prismatic joint along x driven at the ground's velocity (a VELOCITY actuator: DART treats it as kinematic);
//  - lower and upper blocks: one skeleton each, a BoxShape (b, h1) and (b, h2) (one box (b, h) for a parapet) on a
//    PlanarJoint in the XY plane, q = (x, y, theta_z counter-clockwise); the constructor checks that convention
//    against the body's transform. The blocks are loaded from the URDF text scene_file() gives (dart_urdf.hpp); the
//    rest of the scene below is added in code;
//  - contacts: the ODE collision detector of libdart-collision-ode (detector = 1, the default; 0 is DART's own) on the
//    shape pairs a collision filter allows, and only those: ground-lower box, lower-upper box and the roller's pairs
//    below. The two detectors give the same free vibrations, but under the record of `vssw bench` at 1 ms DART's own
//    gave a peak 14 % above the converged one where ODE's gave 1.3 % (docs/contributing/engines.md "DART");
//  - the roller (VSSW only), one-sided as in every other adapter: a small sphere on the upper block centred at each
//    top corner, meeting a frictionless vertical guide box whose face is the sphere's radius outside x = +-b, so that
//    the contact holds the corner itself on x <= +b (right) or x >= -b (left), y free. The force is horizontal through
//    the sphere's centre, the corner: the same line of action as a contact at the corner. A guide cannot meet the
//    upper block's box itself (below the held corner the face leans outwards: docs/contributing/engines.md "Bullet");
//  - rounded corners (corner radius r > 0): each block's box is its flat part, b - r wide, with capsules of radius r
//    along the depth at the arcs' centres (add_rounding): the base capsules meet the ground, each top capsule of the
//    lower block the bottom capsule of the upper block on its side; masses and inertias stay the rectangles';
//  - N: an external force on the top face each step (at its centre, or e from it; DART clears external forces after
//    each step), only when xi > 0; ground motion: the world's gravity (-a_h(t), -g) each step, a_h at the step's
//    midpoint (a uniform pseudo-force -m a_h on every block), or (moving_supports = 1) the ground and the guides
//    moving;
//  - a flexible top support (WallScene::diaphragm, T_d > 0): the guides on a velocity-driven skeleton of their own,
//    slid at the ground's velocity plus u_d's, so that they sit u_d(t) of Eq. (9d) from the ground at each step's end;
//
// Impacts: the LCP resolves a landing with every closing contact (new pivot, hinge, roller) at once, restitution 0:
// the whole new mechanism's plastic impact, as in every other engine (docs/contributing/engines.md "DART").
//
// Process-wide state: DART's ContactConstraint error reduction, its cap, constraint force mixing and error allowance
// are static members, shared by every world in the process: simulate() sets all four at the start of each run (each run
// of make_engine() is a forked child anyway).
#include "multibody/dart/dart_engine.hpp"
#include "multibody/dart/dart_urdf.hpp"

#include <algorithm>

#include <dart/collision/CollisionFilter.hpp>
#include <dart/collision/CollisionObject.hpp>
#include <dart/collision/dart/DARTCollisionDetector.hpp>
#include <dart/collision/ode/OdeCollisionDetector.hpp>
#include <dart/config.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/constraint/ContactConstraint.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/CapsuleShape.hpp>
#include <dart/dynamics/PlanarJoint.hpp>
#include <dart/dynamics/PrismaticJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/energy.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_angles.hpp"
#include "multibody/kit/step_loop.hpp"

namespace vssw::multibody {
namespace {

namespace dd = dart::dynamics;
using Eigen::Vector3d;

constexpr double kDepth = kDartDepth;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

// The detectors a run may use (setting "detector"; ODE's by default, above). DART's Bullet detector is not offered: it
// links Debian's single-precision Bullet, which aborted ("malloc(): invalid size") beside vssw's double-precision
// Bullet in one process. FCL, DART's default, is not offered either: it costs 4 times as much (docs/contributing/engines.md "DART").
enum Detector { kDartDetector = 0, kOdeDetector = 1, kDetectorCount = 2 };

// The roller sphere's radius, as a share of the half thickness b. Nothing depends on it (the guide's face stands the
// radius outside x = +-b and the force passes through the sphere's centre, the corner) as long as the sphere stays
// clear of the lower block and the ground, which the collision filter ensures anyway.
constexpr double kRollerRadiusShare = 0.1;

struct Knobs {
    Detector detector;
    // DART's ContactConstraint statics (docs/contributing/engines.md "DART" for the measurements): error reduction
    // parameter, the cap on the velocity it may give, constraint force mixing, and the penetration allowed before erp acts.
    double erp, erv, cfm, allowance;
    FailureLimits limits;  // slide_limit, penetration_limit (run_monitor.hpp)
    bool moving_supports;
};

// DART's defaults for the four statics, kept (docs/contributing/engines.md "DART": measured on the parapet and the VSSWs).
constexpr double kDefaultErp = 0.01, kDefaultErv = 1e-3, kDefaultCfm = 1e-5, kDefaultAllowance = 0.0;

// Ranges (SettingDescription::lo/hi). erp is a share in [0, 1]. cfm: DART clamps values below 1e-9 to 1e-9 (with a
// warning on stderr), and 1 already makes a contact softer than the wall's weight can hold. The correcting velocity
// and the allowance: up to 1 m/s and 1 cm, far beyond anything measured and below the blocks' size.
constexpr double kMinCfm = 1e-9;
constexpr double kMaxErv = 1.0;        // [m/s]
constexpr double kMaxAllowance = 1e-2;  // [m]

const std::vector<SettingDescription>& setting_table() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.001", "s", "the step (docs/engines.md \"DART\": every target met at 1 ms)"},
        {"iterations", "none", "", "not used: the boxed LCP solver is Dantzig's pivoting (PGS only as its fallback)"},
        {"detector", "1", "choice", "collision detector: 1 ODE's (libdart-collision-ode), 0 DART's own", 0.0, 1.0},
        {"erp", "0.01", "", "ContactConstraint error reduction: the share of a penetration corrected per step", 0.0, 1.0},
        {"erv", "0.001", "m/s", "cap on the velocity the error reduction may give", 0.0, kMaxErv},
        {"cfm", "1e-05", "", "ContactConstraint constraint force mixing: the contacts' softness", kMinCfm, 1.0},
        {"allowance", "0", "m", "penetration allowed before the error reduction acts", 0.0, kMaxAllowance},
        {"moving_supports", "0", "0/1", "1: move the ground as a kinematic body instead of applying pseudo-forces", 0.0, 1.0},
    });
    return table;
}

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("DART", s, setting_table());
    Knobs k{};
    k.detector = static_cast<Detector>(r.choice("detector", kOdeDetector, kDetectorCount));
    // Each range (setting_table) is checked by the SettingsReader, naming the setting and its value.
    k.erp = r.number("erp", kDefaultErp);
    k.erv = r.number("erv", kDefaultErv);
    k.cfm = r.number("cfm", kDefaultCfm);
    k.allowance = r.number("allowance", kDefaultAllowance);
    k.limits = FailureLimits::read(r);
    k.moving_supports = r.flag("moving_supports");
    return k;
}

// Clockwise angle of a body about z, from its transform.
double clockwise_angle(const dd::BodyNode& body) {
    const Eigen::Matrix3d r = body.getWorldTransform().linear();
    return -std::atan2(r(1, 0), r(0, 0));
}

// A point given in a body's frame, in world coordinates.
Vector3d world_point(const dd::BodyNode& body, double lx, double ly) {
    return body.getWorldTransform() * Vector3d(lx, ly, 0.0);
}

// Lets the detector pass only the listed pairs of shapes (DART's own filters work per BodyNode; the roller needs
// per-shape pairs: a sphere meets its guide, and the upper block's box, on the same BodyNode, must not).
class PairFilter final : public dart::collision::CollisionFilter {
public:
    void allow(const dd::ShapeFrame* a, const dd::ShapeFrame* b) { pairs_.emplace_back(a, b); }
    bool ignoresCollision(const dart::collision::CollisionObject* o1,
                          const dart::collision::CollisionObject* o2) const override {
        const dd::ShapeFrame* a = o1->getShapeFrame();
        const dd::ShapeFrame* b = o2->getShapeFrame();
        for (const auto& p : pairs_)
            if ((p.first == a && p.second == b) || (p.first == b && p.second == a)) return false;
        return true;
    }

private:
    std::vector<std::pair<const dd::ShapeFrame*, const dd::ShapeFrame*>> pairs_;
};

dd::ShapeNode* add_shape(dd::BodyNode* body, const dd::ShapePtr& shape, const Vector3d& offset, double friction) {
    dd::ShapeNode* node = body->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(shape);
    node->setRelativeTranslation(offset);
    node->getDynamicsAspect()->setFrictionCoeff(friction);
    node->getDynamicsAspect()->setRestitutionCoeff(0.0);
    return node;
}

class DartScene {
public:
    DartScene(const WallScene& scene, const Knobs& knobs, double theta0, double dt)
        : sizes_(block_sizes(scene)), g_(scene.gravity()) {
        world_ = dart::simulation::World::create("vssw");
        world_->setTimeStep(dt);
        world_->setGravity(Vector3d(0.0, -g_, 0.0));
        dart::constraint::ConstraintSolver* solver = world_->getConstraintSolver();
        if (knobs.detector == kOdeDetector)
            solver->setCollisionDetector(dart::collision::OdeCollisionDetector::create());
        else
            solver->setCollisionDetector(dart::collision::DARTCollisionDetector::create());
        auto filter = std::make_shared<PairFilter>();
        solver->getCollisionOption().collisionFilter = filter;

        const UrdfBlocks blocks = load_wall_urdf(wall_urdf(scene, theta0), scene.is_vssw());
        const double b = sizes_.b, h = sizes_.h_lower + sizes_.h_upper;
        // Ground. A moving ground travels with the record's displacement: wide enough that the wall never reaches
        // its edge.
        const double half_width = knobs.moving_supports ? 1e4 : 4.0 * h + 10.0 * b;
        dd::SkeletonPtr ground = dd::Skeleton::create("ground");
        if (knobs.moving_supports) {
            std::tie(ground_joint_, ground_body_) = x_slider(ground);
        } else {
            ground_body_ = ground->createJointAndBodyNodePair<dd::WeldJoint>().second;
        }
        dd::ShapeNode* ground_box = add_shape(
            ground_body_, std::make_shared<dd::BoxShape>(Vector3d(2.0 * half_width, 2.0 * h, 4.0 * kDepth)),
            Vector3d(0.0, -h, 0.0), scene.base_mu());

        dd::ShapeNode* lower_box = nullptr;
        // DART 6 takes the smaller of two shapes' coefficients: the lower block carries the larger of the base's and
        // the hinge's, so that the ground's sets the base's and the upper block's the hinge's.
        const double lower_mu = std::max(scene.base_mu(), scene.hinge_mu());
        lower_ = add_block(blocks.lower, lower_mu, lower_box);
        filter->allow(ground_box, lower_box);
        const double rc = scene.corner_radius();
        if (rc > 0.0)  // the base arcs (see add_rounding)
            for (dd::ShapeNode* arc : add_rounding(lower_, sizes_.h_lower, rc, lower_mu, -1.0))
                filter->allow(ground_box, arc);
        if (scene.vssw) {
            dd::ShapeNode* upper_box = nullptr;
            upper_ = add_block(blocks.upper, scene.hinge_mu(), upper_box);
            filter->allow(lower_box, upper_box);
            if (rc > 0.0) {  // the hinge's arcs, each rolling on the one of its side
                const auto lower_top = add_rounding(lower_, sizes_.h_lower, rc, lower_mu, 1.0);
                const auto upper_bottom = add_rounding(upper_, sizes_.h_upper, rc, scene.hinge_mu(), -1.0);
                for (std::size_t i = 0; i < lower_top.size(); ++i) filter->allow(lower_top[i], upper_bottom[i]);
            }
            // A flexible top support: the guides on a skeleton of their own, slid at the ground's velocity plus
            // u_d's (docs/model/top-support.md), kinematic as the moving ground is.
            dd::BodyNode* guide_body = ground_body_;
            if (!scene.diaphragm.is_rigid()) {
                dd::SkeletonPtr top = dd::Skeleton::create("top support");
                std::tie(top_joint_, guide_body) = x_slider(top);
                world_->addSkeleton(top);
            }
            // The roller: a sphere centred at each top corner, a guide whose face is the radius outside x = +-b.
            const double r = kRollerRadiusShare * b, guide_half = b;
            for (double side : {-1.0, 1.0}) {
                dd::ShapeNode* sphere =
                    add_shape(upper_, std::make_shared<dd::SphereShape>(r), Vector3d(side * b, sizes_.h_upper, 0.0), 0.0);
                dd::ShapeNode* guide = add_shape(
                    guide_body, std::make_shared<dd::BoxShape>(Vector3d(2.0 * guide_half, 4.0 * h, 2.0 * kDepth)),
                    Vector3d(side * (b + r + guide_half), 2.0 * h, 0.0), 0.0);
                filter->allow(sphere, guide);
            }
        }
        world_->addSkeleton(ground);
        const WallPose pose = pose_at(scene, theta0);
        place(lower_, pose.lower);
        if (upper_) place(upper_, pose.upper);
    }

    dd::BodyNode* lower() const { return lower_; }
    dd::BodyNode* upper() const { return upper_; }
    double ground_x() const { return ground_joint_ ? ground_joint_->getPosition(0) : 0.0; }
    double ground_velocity() const { return ground_joint_ ? ground_joint_->getVelocity(0) : 0.0; }
    int contacts() const { return static_cast<int>(world_->getLastCollisionResult().getNumContacts()); }

    // One step: the pseudo-force as gravity (-a_h, -g), or the ground's velocity for the step (moving supports); a
    // flexible top support's guides at the ground's velocity plus u_d's. External forces must have been added
    // before; DART clears them after the step.
    void step(double a_h, double ground_velocity, double top_velocity) {
        if (top_joint_) top_joint_->setCommand(0, ground_velocity + top_velocity);
        if (ground_joint_) {
            ground_joint_->setCommand(0, ground_velocity);
        } else {
            world_->setGravity(Vector3d(-a_h, -g_, 0.0));
        }
        world_->step();
    }

private:
    // A body slid along x by a velocity-driven prismatic joint: kinematic, as a velocity joint's body takes no
    // impulse; its mass only keeps the articulated inertia regular.
    static std::pair<dd::PrismaticJoint*, dd::BodyNode*> x_slider(const dd::SkeletonPtr& skeleton) {
        dd::PrismaticJoint::Properties slide;
        slide.mAxis = Vector3d::UnitX();
        auto pair = skeleton->createJointAndBodyNodePair<dd::PrismaticJoint>(nullptr, slide);
        pair.first->setActuatorType(dd::Joint::VELOCITY);
        pair.second->setMass(1.0);
        return {pair.first, pair.second};
    }

    // A block loaded from the URDF (its mass, inertia, box and planar joint), given what URDF cannot hold: its box's
    // friction and restitution 0.
    dd::BodyNode* add_block(const dd::SkeletonPtr& skeleton, double friction, dd::ShapeNode*& box_node) {
        dd::BodyNode* body = skeleton->getRootBodyNode();
        box_node = body->getShapeNode(0);
        box_node->getDynamicsAspect()->setFrictionCoeff(friction);
        box_node->getDynamicsAspect()->setRestitutionCoeff(0.0);
        world_->addSkeleton(skeleton);
        return body;
    }

    // Rounded corners (kit/rounded_corners.hpp): capsules of radius r along the depth (DART's capsule axis, z) at the
    // arcs' centres of one face (end -1: the bottom, +1: the top), left then right; no mass of their own (the body's
    // inertia is set, the rectangle's). With the box b - r wide they make the block's rounded outline.
    std::vector<dd::ShapeNode*> add_rounding(dd::BodyNode* body, double half_h, double r, double friction, double end) {
        std::vector<dd::ShapeNode*> arcs;
        for (double side : {-1.0, 1.0})
            arcs.push_back(add_shape(body, std::make_shared<dd::CapsuleShape>(r, kDepth),
                                     Vector3d(side * (sizes_.b - r), end * (half_h - r), 0.0), friction));
        return arcs;
    }

    // q = (x, y, counter-clockwise angle), checked against the transform DART derives from it: a plane or sign
    // convention other than the one assumed would place the wall wrongly, silently.
    static void place(dd::BodyNode* body, const BlockPose& p) {
        body->getParentJoint()->setPositions(Vector3d(p.x, p.y, -p.angle));
        const Vector3d c = body->getWorldTransform().translation();
        constexpr double kPlacement = 1e-12;  // the transform's rounding
        if (std::abs(c.x() - p.x) > kPlacement || std::abs(c.y() - p.y) > kPlacement ||
            std::abs(clockwise_angle(*body) - p.angle) > kPlacement)
            throw EngineFailure(fmt::format(
                "DART: the planar joint's coordinates are not (x, y, counter-clockwise angle): asked ({}, {}, {}), got "
                "({}, {}, {})",
                p.x, p.y, p.angle, c.x(), c.y(), clockwise_angle(*body)));
    }

    BlockSizes sizes_;
    double g_;
    dart::simulation::WorldPtr world_;
    dd::BodyNode* ground_body_ = nullptr;
    dd::PrismaticJoint* ground_joint_ = nullptr;
    dd::PrismaticJoint* top_joint_ = nullptr;  // a flexible top support's guides
    dd::BodyNode* lower_ = nullptr;
    dd::BodyNode* upper_ = nullptr;
};

Knobs checked_knobs(const WallScene& scene, const EngineSettings& settings);

class DartEngine final : public Engine {
public:
    std::string name() const override { return "dart"; }
    std::string display_name() const override { return "DART"; }
    // At 1 ms, the Fig. 6 VSSW (the parapet: 1.1e-2), docs/contributing/engines.md "DART".
    double cost_per_simulated_second() const override { return 3.4e-2; }
    std::string version() const override { return fmt::format("DART {}", DART_VERSION); }
    EngineSettings default_settings() const override {
        EngineSettings s;
        // Measured (docs/contributing/engines.md "DART"): 1 ms meets every target of the cross-engine suite and `vssw
        // bench`; the period error is first order in the step, as Bullet's and ODE's (the same symplectic Euler).
        s.dt = 1e-3;
        s.iterations = 0;
        return s;
    }
    std::vector<SettingDescription> setting_descriptions() const override { return setting_table(); }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { (void)read_knobs(settings); }
    // The blocks' URDF a run loads (dart_urdf.hpp), after the checks a run makes.
    std::optional<SceneFile> scene_file(const WallScene& scene, const Excitation& ex,
                                        const EngineSettings& settings) const override {
        (void)checked_knobs(scene, settings);
        return SceneFile{"URDF", ".urdf", wall_urdf(scene, ex.theta0)};
    }
    // The ContactConstraint statics are process-wide: one run at a time in a process (make_engine() forks each run).
    bool runs_concurrently() const override { return false; }
};

// The stepping kit's hooks (step_loop.hpp) on a DartScene.
class DartStepping {
public:
    DartStepping(DartScene& w, const WallScene& scene)
        : w_(w),
          energy_(scene, kDepth),
          N_(scene.overburden() * kDepth),
          lower_(w.lower()),
          upper_(w.upper()),
          top_body_(upper_ ? upper_ : lower_),
          top_half_(upper_ ? block_sizes(scene).h_upper : block_sizes(scene).h_lower),
          load_x_(scene.overburden_offset()) {}

    void drive(const GroundStep&) {}  // the ground motion goes to DartScene::step (gravity or the ground's command)
    void push_overburden() {
        top_body_->addExtForce(Vector3d(0.0, -N_, 0.0), Vector3d(load_x_, top_half_, 0.0), false, true);
    }
    void step(const StepTimes&, const GroundStep& g) {
        angles_.forget();
        w_.step(g.a_h, g.v, g.top_v);
    }
    WallState state(const GroundStep& g) const {
        const double x_g = w_.ground_x();
        auto block = [&](const dd::BodyNode& body, double angle) {  // relative to the (moving) ground
            const Vector3d c = body.getCOM(), v = body.getCOMLinearVelocity();
            const Eigen::Isometry3d& r = body.getWorldTransform();
            // The clockwise angle's cosine and sine as the transform holds them (clockwise_angle's two entries).
            return BlockState{c.x() - x_g, c.y(), angle, v.x() - g.v, v.y(), rate_of(body), r(0, 0), -r(1, 0)};
        };
        return {block(*lower_, lower_angle()), upper_ ? block(*upper_, upper_angle()) : kNoBlock};
    }
    Rocking rocking() const { return {lower_angle(), rate_of(*lower_)}; }
    void fill(TrajectorySample& p) const {
        p.theta2 = upper_ ? upper_angle() : 0.0;
        const double v_ground = w_.ground_velocity();
        auto kinetic = [&](const dd::BodyNode& body) {  // DART's own 3-D sum with its inertia tensor
            const Vector3d v = body.getCOMLinearVelocity() - Vector3d(v_ground, 0.0, 0.0);
            const Vector3d wv = body.getAngularVelocity();
            return 0.5 * body.getMass() * v.squaredNorm() + 0.5 * wv.dot(body.getInertia().getMoment() * wv);
        };
        energy_.fill(p, {kinetic(*lower_), upper_ ? kinetic(*upper_) : 0.0, lower_->getCOM().y(),
                         upper_ ? upper_->getCOM().y() : 0.0, world_point(*top_body_, load_x_, top_half_).y()});
        p.contacts = w_.contacts();
    }

private:
    static double rate_of(const dd::BodyNode& body) { return -body.getAngularVelocity()[2]; }
    double lower_angle() const { return angles_.lower([&] { return clockwise_angle(*lower_); }); }
    double upper_angle() const { return angles_.upper([&] { return clockwise_angle(*upper_); }); }

    DartScene& w_;
    WallEnergy energy_;
    double N_;
    dd::BodyNode* lower_;
    dd::BodyNode* upper_;
    dd::BodyNode* top_body_;
    double top_half_;
    double load_x_;  // N's point on the top face from its centre, toward theta1 > 0 [m]
    mutable StepAngles angles_;  // read by state(), rocking() and fill() of one step
};

// The checks a run and a scene file share, then the knobs: InputError on a bad scene, step or setting.
Knobs checked_knobs(const WallScene& scene, const EngineSettings& settings) {
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "DART time step dt (s)", "a positive finite number",
            settings.dt);
    require_one_description(scene);
    return read_knobs(settings);
}

Trajectory DartEngine::simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    const Knobs knobs = checked_knobs(scene, settings);
    const double dt = settings.dt;
    RunMonitor monitor("DART", scene, ex, dt, knobs.limits);
    // The statics, set for this run (see the top of the file).
    dart::constraint::ContactConstraint::setErrorReductionParameter(knobs.erp);
    dart::constraint::ContactConstraint::setMaxErrorReductionVelocity(knobs.erv);
    dart::constraint::ContactConstraint::setConstraintForceMixing(knobs.cfm);
    dart::constraint::ContactConstraint::setErrorAllowance(knobs.allowance);
    DartScene w(scene, knobs, ex.theta0, dt);
    DartStepping stepping(w, scene);
    const StepLoop loop{dt, sample_every(settings, dt), knobs.moving_supports, scene.overburden() > 0.0,
                        scene.diaphragm};
    return run_fixed_steps(stepping, ex, loop, monitor);
}

}  // namespace

std::unique_ptr<Engine> make_dart_engine() { return std::make_unique<DartEngine>(); }

}  // namespace vssw::multibody

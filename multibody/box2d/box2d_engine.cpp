// Box2D adapter: the wall as polygon bodies in a b2World (2D, single precision), stepped by Box2D's sequential
// impulses (velocity iterations) and its nonlinear position pass (position iterations).
//
// Scene (from the analytic description; depth 1 m, so a body's mass is the block's mass per unit depth, as in the
// paper; units metres, kilograms, seconds: the Fig. 6 wall is 4 m tall and ~1.4e3 kg per block, well inside float's
// range, and its corners are known to ~4e-7 m, float's resolution at 4 m):
//  - ground: a static body (kinematic with moving_supports = 1) with one edge along y = 0 (y = -2 skin with a skin);
//  - lower and upper blocks: dynamic bodies with one box polygon each, (b, h1) and (b, h2) (one (b, h) for a
//    parapet); density m / (4 b h), so Box2D's mass and central inertia are the block's, m (b^2 + h^2) / 3;
//  - with a corner radius r (WallScene::corner_radius, kit/rounded_corners.hpp) each block is a rounded box: the core
//    polygon (b - r, h_i - r) with m_radius = r, Box2D's own rounded polygon (b2MakeRoundedBox of Box2D 3), its outline
//    the rectangle's with every corner an exact arc; its mass data set to the rectangle's (Box2D leaves the skin out);
//  - every polygon and the edge with m_radius = 0 (unless the skin setting puts it back). Box2D gives polygons and edges a skin of b2_polygonRadius = 1 cm
//    by default: the block then rolls on rounded corners, which raises its effective I_O by 2 r h / (4/3 R^2) and
//    the period by 0.37 % (measured on the 4 x 0.4 m parapet: +0.30 % at 1 ms against -0.072 % with radius 0;
//    docs/contributing/engines.md "Box2D");
//  - contacts: Box2D's own (polygon-edge at the base, polygon-polygon at the hinge, at most 2 points per pair);
//    collision filters keep the roller's parts apart from the blocks and the ground (the upper block and the ground
//    may meet, but never come near each other);
//  - the roller (VSSW only), unilateral by default, as every other adapter's: a circle fixture of radius r centred on
//    each top corner of the upper block (density 0: no mass), frictionless, meeting only a frictionless vertical
//    edge of the ground body at x = +-(b + r). A circle against a line holds its centre r from the line, so the
//    corner is held on x <= +b (right) and x >= -b (left) exactly, with y free. Only the circles touch the guides:
//    a guide surface the block's face could reach would be penetrated by it (the face below the held corner leans
//    outwards; docs/contributing/engines.md "Bullet"). With roller = 1, the paper's bilateral roller instead: a
//    b2WheelJoint (stiffness 0, damping 0: a point of the block held on a vertical line, rotation free) at the top
//    corner whose guide binds (left_guide_binds), moved to the other corner when the other guide binds;
//  - N: a force on the top face each step (at its centre, or e from it), only when xi > 0 (Box2D adds a force's
//    linear and angular impulse to the velocities before the solve, so every row sees it: Bullet's trap,
//    docs/contributing/engines.md "Bullet", does not arise);
//  - ground motion: by default the pseudo-forces -m a_h(t) as a tilt of gravity, (-a_h, -g), set before each step
//    at its midpoint; with moving_supports = 1 the ground body (edge and guides) is kinematic, its velocity for the
//    step V_k = V_{k-1} + dt a_h(t_{k-1/2}) (ODE's rule: the same impulse per step as the pseudo-forces);
//  - a flexible top support (WallScene::diaphragm, T_d > 0): the guides (or the wheel joint) on a kinematic carrier
//    of their own, moved at the ground's velocity plus u_d's, so that it sits u_d(t) of Eq. (9d) from the ground at
//    each step's end (docs/model/top-support.md);
//  - sleeping off (a slowly rocking wall must not be put to sleep), continuous collision off (nothing here moves a
//    body's size in a step; docs/contributing/engines.md "Box2D"), restitution 0 at every contact.
#include "multibody/box2d/box2d_engine.hpp"

#include <box2d/box2d.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/energy.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_loop.hpp"

namespace vssw::multibody {
namespace {

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

constexpr int kDefaultVelocityIterations = 8;  // Box2D's recommended value (b2World::Step's comment)
constexpr int kDefaultPositionIterations = 3;  // likewise
constexpr int kMaxPositionIterations = kMaxIterations;  // engine.hpp's: the cost grows linearly with them

// The roller's circles: radius as a share of b. The guide sits r further out, so the value does not move the corner's
// line (exact); it only has to exceed what a corner can pass its line by in one step (v dt: 1e-4 m for 0.1 m/s at
// 1 ms) so that the circle's centre never crosses the two-sided guide, and stay well inside the block's width.
constexpr double kRollerRadiusShare = 0.05;

// Collision categories: which fixtures can meet (b2Filter).
constexpr uint16_t kGroundBits = 0x1, kBlockBits = 0x2, kRollerCornerBits = 0x4, kGuideBits = 0x8;

struct Knobs {
    int velocity_iterations;  // --iterations
    int position_iterations;
    bool warm_starting;
    bool continuous;
    int roller;  // 0: unilateral (circles on guides), 1: the paper's bilateral roller (a wheel joint)
    double skin;  // m_radius of the blocks' polygons and the ground's edge [m] (Box2D's default: b2_polygonRadius)
    FailureLimits limits;
    bool moving_supports;
};

// The largest skin a setting may give: 5 cm, five times Box2D's own b2_polygonRadius (1 cm), a quarter of the
// Fig. 6 wall's half thickness; a skin near b would round the block into a disc.
constexpr double kMaxSkin = 0.05;

// Ranges (SettingDescription::lo/hi): switches 0/1; the skin as kMaxSkin says; position iterations from 0 (no position
// pass) to kMaxPositionIterations.
const std::vector<SettingDescription>& setting_table() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.001", "s",
         "the step (docs/engines.md \"Box2D\": every target met at 1 ms; Box2D's usual 1/60 s gives the parapet's "
         "restitution -16 %)"},
        {"iterations", std::to_string(kDefaultVelocityIterations), "", "velocity (sequential-impulse) iterations per step"},
        {"position_iterations", std::to_string(kDefaultPositionIterations), "",
         "position-correction iterations per step (they act only on a penetration past b2_linearSlop, 5 mm)", 0.0,
         static_cast<double>(kMaxPositionIterations)},
        {"warm_starting", "1", "0/1", "1: start each step's impulses from the last step's (Box2D's default)", 0.0, 1.0},
        {"continuous", "0", "0/1", "1: Box2D's continuous collision (time of impact) against the ground", 0.0, 1.0},
        {"roller", "0", "choice",
         "0: a unilateral roller (corner circles on frictionless guides, as the other engines); 1: the paper's "
         "bilateral roller (a wheel joint)",
         0.0, 1.0, /*parapet_only=*/false, /*vssw_only=*/true},
        {"moving_supports", "0", "0/1", "1: move the ground as a kinematic body instead of tilting gravity", 0.0, 1.0},
        {"skin", "0", "m",
         "Box2D's polygon radius on the block and the ground (Box2D's default 0.01 rounds the corners: period "
         "+0.37 %)",
         0.0, kMaxSkin, /*parapet_only=*/true},
    });
    return table;
}

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("Box2D", s, setting_table());
    Knobs k{};
    k.velocity_iterations = s.iterations > 0 ? s.iterations : kDefaultVelocityIterations;
    k.position_iterations = r.whole_number("position_iterations", kDefaultPositionIterations, kMaxPositionIterations);
    k.warm_starting = r.choice("warm_starting", 1, 2) == 1;
    k.continuous = r.flag("continuous");
    k.roller = r.choice("roller", 0, 2);
    k.limits = FailureLimits::read(r);
    k.moving_supports = r.flag("moving_supports");
    k.skin = r.non_negative("skin", 0.0);
    return k;
}

b2Vec2 vec(double x, double y) { return b2Vec2(static_cast<float>(x), static_cast<float>(y)); }

// A point given in a body's frame, in world coordinates.
b2Vec2 world_point(const b2Body& body, double lx, double ly) { return body.GetWorldPoint(vec(lx, ly)); }

// The fixtures' friction: Box2D mixes two fixtures' coefficients as sqrt(mu1 mu2) (b2MixFriction). One coefficient
// for all three gives itself at both contacts (the default scene, as before); a hinge of its own takes the lower
// block at 1, the ground at mu_base^2 and the upper block at mu_hinge^2, which mix to mu_base and mu_hinge.
struct Frictions {
    double ground, lower, upper;
};
Frictions fixture_frictions(const WallScene& scene) {
    if (!scene.hinge_friction) return {scene.friction, scene.friction, scene.friction};
    return {scene.base_mu() * scene.base_mu(), 1.0, scene.hinge_mu() * scene.hinge_mu()};
}

class Box2dScene {
public:
    Box2dScene(const WallScene& scene, const Knobs& knobs, double theta0)
        : world_(vec(0.0, -scene.gravity())), knobs_(knobs), sizes_(block_sizes(scene)),
          corner_radius_(scene.corner_radius()) {
        world_.SetAllowSleeping(false);
        world_.SetWarmStarting(knobs.warm_starting);
        world_.SetContinuousPhysics(knobs.continuous);
        world_.SetSubStepping(false);

        const double b = sizes_.b, h = sizes_.h_lower + sizes_.h_upper;
        b2BodyDef ground_def;
        ground_def.type = knobs.moving_supports ? b2_kinematicBody : b2_staticBody;
        ground_ = world_.CreateBody(&ground_def);
        // A moving ground travels with the record's displacement: wide enough that the wall never reaches its end.
        const double half_width = knobs.moving_supports ? 1e4 : 4.0 * h + 10.0 * b;
        b2EdgeShape edge;
        // With a skin the edge's core sits two skins down, so that the block's skin rests on the edge's at rest.
        const double y_edge = -2.0 * knobs.skin;
        edge.SetTwoSided(vec(-half_width, y_edge), vec(half_width, y_edge));
        edge.m_radius = static_cast<float>(knobs.skin);  // 0 by default: no skin (see the top of the file)
        const Frictions mu = fixture_frictions(scene);
        add_fixture(*ground_, edge, 0.0, mu.ground, kGroundBits, kBlockBits);

        if (scene.vssw && !scene.diaphragm.is_rigid()) {  // a flexible top support: the roller's own carrier
            b2BodyDef carrier_def;
            carrier_def.type = b2_kinematicBody;
            carrier_ = world_.CreateBody(&carrier_def);
        }
        const WallPose pose = pose_at(scene, theta0);
        lower_ = add_block(sizes_.h_lower, sizes_.m_lower, pose.lower, mu.lower);
        if (scene.vssw) {
            upper_ = add_block(sizes_.h_upper, sizes_.m_upper, pose.upper, mu.upper);
            add_roller(2.0 * h);
        }
    }

    b2World& world() { return world_; }
    b2Body& lower() { return *lower_; }
    b2Body* upper() { return upper_; }
    b2Body& ground() { return *ground_; }
    // What holds the roller: the ground, or with a flexible top support its carrier, moved by u_d from the ground.
    b2Body& carrier() { return carrier_ ? *carrier_ : *ground_; }
    bool has_carrier() const { return carrier_ != nullptr; }

    // One step of dt; forces and gravity for it must have been set.
    void step(double dt) {
        if (knobs_.roller == 1) place_wheel();
        world_.Step(static_cast<float>(dt), knobs_.velocity_iterations, knobs_.position_iterations);
    }

    // Contact points in touch (Box2D's manifolds: points at or inside the surfaces).
    int contact_points() {
        int n = 0;
        for (b2Contact* c = world_.GetContactList(); c; c = c->GetNext())
            if (c->IsTouching()) n += c->GetManifold()->pointCount;
        return n + (wheel_ ? 1 : 0);
    }

private:
    b2Fixture* add_fixture(b2Body& body, const b2Shape& shape, double density, double friction, uint16_t category,
                           uint16_t mask) {
        b2FixtureDef def;
        def.shape = &shape;
        def.density = static_cast<float>(density);
        def.friction = static_cast<float>(friction);
        def.restitution = 0.0f;
        def.filter.categoryBits = category;
        def.filter.maskBits = mask;
        return body.CreateFixture(&def);
    }

    b2Body* add_block(double half_h, double mass_per_depth, const BlockPose& p, double friction) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position = vec(p.x, p.y);
        def.angle = static_cast<float>(-p.angle);  // Box2D turns counter-clockwise
        def.allowSleep = false;
        b2Body* body = world_.CreateBody(&def);
        b2PolygonShape box;
        const double density = mass_per_depth * kDepth / (4.0 * sizes_.b * half_h);
        if (corner_radius_ > 0.0) {  // a rounded box: the core r inside each face, its skin r (top of the file)
            box.SetAsBox(static_cast<float>(sizes_.b - corner_radius_), static_cast<float>(half_h - corner_radius_));
            box.m_radius = static_cast<float>(corner_radius_);
            add_fixture(*body, box, density, friction, kBlockBits, kGroundBits | kBlockBits);
            // Box2D's polygon mass leaves the skin out: the rectangle's mass and inertia, set (rounded_corners.hpp).
            b2MassData mass{};
            mass.mass = static_cast<float>(mass_per_depth * kDepth);
            mass.center = vec(0.0, 0.0);
            mass.I = static_cast<float>(mass_per_depth * kDepth * (sizes_.b * sizes_.b + half_h * half_h) / 3.0);
            body->SetMassData(&mass);
            return body;
        }
        box.SetAsBox(static_cast<float>(sizes_.b), static_cast<float>(half_h));
        box.m_radius = static_cast<float>(knobs_.skin);  // 0 by default: no skin (see the top of the file)
        add_fixture(*body, box, density, friction, kBlockBits, kGroundBits | kBlockBits);
        return body;
    }

    // The unilateral roller's parts: circles on the upper block's top corners, guides on the ground (see the top of
    // the file). Both guides are always there: the corner off the pivot's side sits inside its line by about
    // b theta2^2 and its contact stays idle. With the bilateral roller (roller = 1) neither is made.
    void add_roller(double y_top) {
        if (knobs_.roller == 1) return;
        const double b = sizes_.b, r = kRollerRadiusShare * b, reach = sizes_.h_upper;
        for (double side : {-1.0, 1.0}) {
            b2CircleShape corner;
            corner.m_p = vec(side * b, sizes_.h_upper);
            corner.m_radius = static_cast<float>(r);
            add_fixture(*upper_, corner, 0.0, 0.0, kRollerCornerBits, kGuideBits);
            b2EdgeShape guide;
            guide.SetTwoSided(vec(side * (b + r), y_top - reach), vec(side * (b + r), y_top + reach));
            guide.m_radius = 0.0f;
            add_fixture(carrier(), guide, 0.0, 0.0, kGuideBits, kRollerCornerBits);
        }
    }

    // The bilateral roller: a wheel joint holding the top corner whose guide binds on the vertical line x = +-b of
    // the ground, rotation free, no spring (stiffness 0 and damping 0, b2WheelJointDef's defaults). Moved to the
    // other corner when that one's guide binds (the corners' rule of every adapter, left_guide_binds).
    void place_wheel() {
        const double b = sizes_.b, x0 = carrier().GetPosition().x;
        const b2Vec2 right = world_point(*upper_, b, sizes_.h_upper), left = world_point(*upper_, -b, sizes_.h_upper);
        const int side = left_guide_binds(right.x, left.x, x0, b) ? -1 : 1;
        if (wheel_ && side == wheel_side_) return;
        if (wheel_) world_.DestroyJoint(wheel_);
        b2WheelJointDef def;
        const b2Vec2 corner = side > 0 ? right : left;
        // The anchor on the line itself (x = x0 +- b), at the corner's height: the joint then holds the corner there.
        def.Initialize(&carrier(), upper_, vec(x0 + side * b, corner.y), b2Vec2(0.0f, 1.0f));
        def.localAnchorB = vec(side * b, sizes_.h_upper);
        def.stiffness = 0.0f;
        def.damping = 0.0f;
        def.collideConnected = true;  // the joint must not switch off the blocks' other contacts with the ground
        wheel_ = world_.CreateJoint(&def);
        wheel_side_ = side;
    }

    b2World world_;
    Knobs knobs_;
    BlockSizes sizes_;
    double corner_radius_;  // r [m] of every block corner (0: sharp boxes)
    b2Body* ground_ = nullptr;
    b2Body* carrier_ = nullptr;  // a flexible top support only
    b2Body* lower_ = nullptr;
    b2Body* upper_ = nullptr;
    b2Joint* wheel_ = nullptr;
    int wheel_side_ = 0;
};

class Box2dEngine final : public Engine {
public:
    std::string name() const override { return "box2d"; }
    std::string display_name() const override { return "Box2D"; }
    double cost_per_simulated_second() const override { return 1.6e-3; }  // at 1 ms, docs/contributing/engines.md "Box2D"
    std::string version() const override {
        return fmt::format("Box2D {}.{}.{} (single precision)", b2_version.major, b2_version.minor,
                           b2_version.revision);
    }
    EngineSettings default_settings() const override {
        EngineSettings s;
        s.dt = 1e-3;  // measured: docs/contributing/engines.md "Box2D"
        s.iterations = kDefaultVelocityIterations;
        return s;
    }
    std::vector<SettingDescription> setting_descriptions() const override { return setting_table(); }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { (void)read_knobs(settings); }
};

// Clockwise angle of a body (Box2D's angle is counter-clockwise).
double clockwise_angle(const b2Body& body) { return -static_cast<double>(body.GetAngle()); }
double clockwise_rate(const b2Body& body) { return -static_cast<double>(body.GetAngularVelocity()); }

// The stepping kit's hooks (step_loop.hpp) on a Box2dScene.
class Box2dStepping {
public:
    Box2dStepping(Box2dScene& w, const WallScene& scene, const Knobs& knobs)
        : w_(w),
          knobs_(knobs),
          energy_(scene, kDepth),
          g_(scene.gravity()),
          N_(scene.overburden() * kDepth),
          lower_(w.lower()),
          upper_(w.upper()),
          top_body_(upper_ ? *upper_ : lower_),
          top_half_(upper_ ? block_sizes(scene).h_upper : block_sizes(scene).h_lower),
          load_x_(scene.overburden_offset()) {}

    void drive(const GroundStep& g) {
        if (knobs_.moving_supports) {
            w_.ground().SetLinearVelocity(vec(g.v, 0.0));
        } else {
            w_.world().SetGravity(vec(-g.a_h, -g_));  // -m a_h at every centre of mass: gravity tilted
        }
        // The roller's carrier sits u_d(t) from the ground at the step's end (step_loop.hpp, GroundStep::top_v).
        if (w_.has_carrier()) w_.carrier().SetLinearVelocity(vec(g.v + g.top_v, 0.0));
    }
    void push_overburden() { top_body_.ApplyForce(vec(0.0, -N_), world_point(top_body_, load_x_, top_half_), true); }
    void step(const StepTimes& st, const GroundStep&) { w_.step(st.dt); }
    WallState state(const GroundStep&) {
        const double x_g = w_.ground().GetPosition().x, v_ground = w_.ground().GetLinearVelocity().x;
        auto block = [&](const b2Body& body) {  // relative to the (moving) ground
            const b2Vec2 c = body.GetPosition(), v = body.GetLinearVelocity();
            return BlockState{c.x - x_g, c.y, clockwise_angle(body), v.x - v_ground, v.y, clockwise_rate(body)};
        };
        return {block(lower_), upper_ ? block(*upper_) : kNoBlock};
    }
    Rocking rocking() const { return {clockwise_angle(lower_), clockwise_rate(lower_)}; }
    void fill(TrajectorySample& p) {
        p.theta2 = upper_ ? clockwise_angle(*upper_) : 0.0;
        const double v_ground = w_.ground().GetLinearVelocity().x;
        auto kinetic = [&](const b2Body& body) {
            const b2Vec2 v = body.GetLinearVelocity();
            // The inertia about the body origin, which is the centre of mass here.
            return block_kinetic_energy(body.GetMass(), body.GetInertia(), v.x - v_ground, v.y,
                                        body.GetAngularVelocity());
        };
        energy_.fill(p, {kinetic(lower_), upper_ ? kinetic(*upper_) : 0.0, lower_.GetPosition().y,
                         upper_ ? upper_->GetPosition().y : 0.0, world_point(top_body_, load_x_, top_half_).y});
        p.contacts = w_.contact_points();
    }

private:
    Box2dScene& w_;
    const Knobs& knobs_;
    WallEnergy energy_;
    double g_, N_;
    b2Body& lower_;
    b2Body* upper_;
    b2Body& top_body_;
    double top_half_;
    double load_x_;  // N's point on the top face from its centre, toward theta1 > 0 [m]
};

Trajectory Box2dEngine::simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "Box2D time step dt (s)", "a positive finite number",
            settings.dt);
    require_one_description(scene);
    const Knobs knobs = read_knobs(settings);
    // A skin on the hinge's two faces would make the blocks overlap by two skins at rest (Box2D pushes that out,
    // energy in): the setting is for the single block (parapet_only), where it shows what Box2D's default does to
    // the period.
    require_settings_fit_wall("Box2D", settings, setting_table(), scene);
    if (knobs.skin > 0.0 && scene.corner_radius() > 0.0)
        throw InputError(fmt::format("Box2D: the setting skin = {:g} m and the corner radius {:g} m both set the "
                                     "blocks' polygon radius: give one",
                                     knobs.skin, scene.corner_radius()));
    Box2dScene w(scene, knobs, ex.theta0);
    Box2dStepping stepping(w, scene, knobs);
    RunMonitor monitor("Box2D", scene, ex, settings.dt, knobs.limits);
    const StepLoop loop{settings.dt, sample_every(settings, settings.dt), knobs.moving_supports,
                        scene.overburden() > 0.0, scene.diaphragm};
    return run_fixed_steps(stepping, ex, loop, monitor);
}

}  // namespace

std::unique_ptr<Engine> make_box2d_engine() { return std::make_unique<Box2dEngine>(); }

}  // namespace vssw::multibody

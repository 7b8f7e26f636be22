// ODE adapter: the wall as boxes in a dWorld, kept in the x-y plane, stepped by ODE's direct solver (dWorldStep).
//
// Scene (from the analytic description; depth 1 m, so masses and energies are per unit depth as in the paper):
//  - ground: a static box geom (box-box contact keeps sharp corners); with moving_supports = 1 a kinematic body
//    carries it;
//  - lower and upper blocks: box bodies (b, h1) and (b, h2) (one box (b, h) for a parapet), free bodies that stay in
//    the plane because no load leaves it: every contact point lies on z = 0 with an in-plane normal (see add_pair).
// Until the speed work each was also held by a dJointCreatePlane2D (zeroing v_z, w_x and w_y each step); measured with
//    it over 10 s of free vibration of the Fig. 6 VSSW, of T1 #11 from 0.8 alpha1 and of the Fig. 6 parapet, w_x, w_y,
//    the tilt of the z axes and z itself stayed exactly 0, so its six rows were dropped from every solve (setting
//    plane_joints = 1 puts them back). The run still fails loudly if a body ever tilts out of the plane;
//  - contacts: dCollide on the pairs that can touch only (ground-lower, lower-upper; never ground-upper), up to 8
//    points for box-box, turned into planar contact joints each step (add_pair), speculative within `margin`;
//  - the roller (VSSW only): a frictionless contact joint between the upper block and the ground (body 0, or the
//    kinematic ground) at the top corner on the pivot's side, holding x <= +b (right corner) or x >= -b (left);
//    y is free. A guide surface cannot be the roller (the face below the held corner leans outwards; docs/contributing/engines.md,
//    "Bullet"). Only the guide whose corner is further out is given to the solver (Bullet gives both: with one, its xi 0.5
//    restitution was up to 2.8 % low; ODE with one meets every `vssw bench` target, docs/contributing/engines.md "ODE");
//  - rounded corners (corner radius r > 0): each box is its block's flat part, b - r wide, with capsules of radius r
//    along the depth at the arcs' centres (add_rounding), the base ones on the ground, each top one of the lower
//    block on the upper block's bottom one of its side; the masses stay the rectangles';
//  - N: a force at the centre of the top face, only when xi > 0; ground motion: pseudo-forces -m a_h(t) at the centres
//    of mass at each step's midpoint, or (moving_supports = 1) the ground and the roller's anchor moving;
//  - a flexible top support (WallScene::diaphragm, T_d > 0): the roller's contact is made with a kinematic body of its
//    own, moved each step at the ground's velocity plus u_d's (GroundStep::top_v), so that it sits u_d(t) of
//    Eq. (9d) from the ground at every step's end; ODE's contact row sees the body's velocity (docs/model/top-support.md).
//
// Impacts: ODE resolves a landing with every closing contact and the roller in one LCP, perfectly plastic (no
// dContactBounce). That is the plastic impact of the whole new mechanism (pivot, hinge, roller), not Eq. (19), which
// assumes the roller carries no impulse. Measured, ODE's restitution is the mechanism's plastic impact
// ((V+' M V-)/(V+' M V+), V the velocity fields either side of theta1 = 0, M the bodies' masses and inertias):
// 0.8250 against 0.8252 (Fig. 6 VSSW), 0.9499 against 0.9509 (T1 #7), 0.9114 against 0.9117 (T1 #15) at 0.2 ms, where
// Eq. (19) gives 0.9508, 0.9867, 0.9750; on every VSSW of bench/engine_accuracy.cpp within 0.6 % of it at 1 ms,
// 0.3 % at 0.2 ms and 0.1 % at 0.05 ms. The parapet's impact is Housner's (within 0.14 % at 0.2 ms).
//
// Defaults, each measured (vssw compare, bench/engine_accuracy.cpp; numbers in the comments where they are set).
#include "multibody/ode/ode_engine.hpp"

#include <ode/ode.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
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

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

// ODE's non-fatal complaints (dMessage, e.g. "LCP internal error"): counted, and a run that provokes one fails with
// it, rather than continuing on a step whose forces ODE zeroed.
int g_ode_messages = 0;
std::string g_ode_last_message;

void on_ode_message(int number, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    ++g_ode_messages;
    g_ode_last_message = fmt::format("ODE message {}: {}", number, text);
}

// dInitODE2 once per process and dCloseODE at exit (a function-local static). ODE keeps global state (the library's
// initialisation, the message handler above, per-thread collision data) and is not re-entrant across threads:
// simulate() must not run on two threads at once. A thread that calls it gets its collision data here
// (dAllocateODEDataForThread is idempotent).
void ensure_ode() {
    struct Library {
        Library() {
            dInitODE2(0);
            dSetMessageHandler(&on_ode_message);
        }
        ~Library() { dCloseODE(); }
        Library(const Library&) = delete;
        Library& operator=(const Library&) = delete;
    };
    static Library library;
    dAllocateODEDataForThread(dAllocateMaskAll);
}

// Settings (EngineSettings::knobs), each with its default and the measurement that chose it. The ODE contact row is a
// spring and damper in disguise: erp = h kp / (h kp + kd), cfm = 1 / (h kp + kd), i.e. kp = erp / (h cfm) and
// kd = (1 - erp) / cfm.
struct Knobs {
    // erp (default 0.2, ODE's): share of a contact's penetration removed per step. With speculative contacts a
    // penetration is only what the solver's compliance lets through (~1e-8 m), so erp barely acts: at 0.2 ms the Fig. 6
    // VSSW's period and restitution are the same to 1e-4 for erp 0.05, 0.2 and 0.8; at 1 ms 0.2 is the closest to the
    // mechanism's plastic impact (0.8256 against 0.8252; 0.8212 at 0.05, 0.8399 at 0.8, which pushes out what the
    // coarse step let in).
    double erp;
    // cfm (default 1e-10 m/(N s), ODE's in double precision): the contact's compliance. With erp 0.2 at 0.2 ms it is a
    // spring of kp = 1e13 N/m and a damper of kd = 8e9 N s/m per contact: rigid, as the paper's blocks are (the
    // solver's relative give, cfm m / h, is 1e-3 for a 2 t block at 0.2 ms). Measured on the Fig. 6 VSSW: 1e-12 and
    // 1e-10 give the same period and restitution at 1 and 0.2 ms (at 0.05 ms 0.830 against 0.825, the impact's
    // order within the step); at 1e-8 an impact spreads over more steps than the metric's window (restitution from
    // velocities +5 % at 0.05 ms while the amplitude estimate is unchanged); at 1e-6 the wall bounces (e ~ 1).
    double cfm;
    // surface_layer (default 0 m, ODE's): penetration allowed before erp acts. max_correcting_vel (default inf, ODE's):
    // cap on the velocity erp may give. Both exist for contacts found only after penetrating, whose push-out adds
    // energy (measured with margin = 0: restitution 0.806 on the Fig. 6 VSSW at 0.2 ms, against 0.825, repaired in
    // part by a layer of 1e-4 m or a cap of 1e-3 m/s). With speculative contacts nothing penetrates: a layer of 1e-6 or
    // 1e-4 m or a cap of 1e-3 or 0.1 m/s changes period and restitution by less than 1e-4 at 0.2 ms.
    double surface_layer;
    double max_correcting_vel;
    // margin (default 1e-3 m): how far apart a corner and a face are still given to the solver, as a speculative
    // contact that may close the gap within the step and no further (motionN = gap / h). ODE's dCollide reports only
    // touching or overlapping boxes, so the ground box's top and the lower block's top are extended by the margin
    // for collision, and the physical gap is read back from the depth. It must cover what a corner closes in one
    // step: 1e-5 m did not at 1 ms (T1 #7's restitution 0.966 instead of 0.950, a penetration pushed out); from
    // 1e-4 to 1e-2 m every period and restitution is the same to 1e-4 at 0.2 and 0.05 ms. 1e-3 m covers closing
    // speeds up to 1 m/s at 1 ms.
    double margin;
    // quickstep (default 0): 1 steps with dWorldQuickStep (SOR) and `iterations` iterations (default 20) instead of
    // dWorldStep (Dantzig LCP). Same period and restitution (to 1e-4, 20 to 500 iterations) and about the same
    // speed, but SOR stops short under a heavy load: T1 #1 at xi 0.5, threshold -1.7e-4 (20 iterations) and
    // -3.9e-4 (5) where the direct solver gives the analytic bracket exactly.
    int quickstep_iterations;
    FailureLimits limits;  // slide_limit, penetration_limit (run_monitor.hpp)
    // moving_supports (default 0): 1 moves the ground (and the roller's anchor) as a kinematic body instead of
    // applying pseudo-forces. The ground's velocity for step k is V_k = V_{k-1} + h a_h(t_{k-1/2}), the impulse the
    // pseudo-forces give, and ODE moves the kinematic body with the velocity the contacts see in the same step: the
    // motion relative to the ground is the same as with pseudo-forces to rounding (measured: the same threshold
    // bracket, peak responses to a pulse equal to 1e-13, parapet and VSSW).
    bool moving_supports;
    // plane_joints (default 0): 1 holds each block in the plane with a dJointCreatePlane2D, as before the speed work.
    // Nothing needs it: no force leaves the plane (contact points on z = 0, in-plane normals and friction directions,
    // gravity along -y), so v_z, w_x and w_y stay exactly 0 without it, and the tilt check in simulate() would fail a
    // run that left the plane. Without its three rows per body the solve is smaller: measured with callgrind on 2 s of
    // the Fig. 6 VSSW's free vibration at 0.2 ms, 314 M instructions -> about 223 M (-29 %); every ODE test passes
    // either way.
    bool plane_joints;
};

// The largest contact gap (margin, surface_layer) a setting may give, 1 m: five times the Fig. 6 wall's half
// thickness, a thousand times the default margin. A margin of 1e300 m made ODE's collision normalise a vector of
// infinities and abort the process (assertion in dxNormalize4; docs/contributing/engines.md "Isolation").
constexpr double kMaxContactGap = 1.0;

// Ranges (SettingDescription::lo/hi): erp and cfm are fractions in ODE's own terms (ODE's manual: erp in [0, 1]; a
// cfm of 1 already makes a contact softer than the wall's weight can hold); the gaps as kMaxContactGap says; a
// correcting velocity below 1 um/s leaves a penetration uncorrected for the whole run.
const std::vector<SettingDescription>& setting_table() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.001", "s", "the step (docs/engines.md \"ODE\": every target met at 1 ms; the error grows as dt over the period)"},
        {"iterations", "none", "",
         "not used by the direct solver (dWorldStep); with quickstep = 1 the SOR iterations (20 unless given)"},
        {"erp", "0.2", "", "error reduction parameter in [0, 1]: the share of a penetration corrected per step", 0.0, 1.0},
        {"cfm", "1e-10", "", "constraint force mixing: the contacts' softness (0 is rigid)", 0.0, 1.0},
        {"surface_layer", "0", "m", "penetration allowed before erp acts", 0.0, kMaxContactGap},
        {"max_correcting_vel", "inf", "m/s", "cap on the velocity erp may give (inf: no cap)", 1e-6, INFINITY},
        {"margin", "0.001", "m", "gap within which a corner and a face are given to the solver as a speculative contact", 0.0, kMaxContactGap},
        {"quickstep", "0", "0/1", "1: dWorldQuickStep (SOR, --iterations) instead of dWorldStep (Dantzig LCP)", 0.0, 1.0},
        {"moving_supports", "0", "0/1", "1: move the ground as a kinematic body instead of applying pseudo-forces", 0.0, 1.0},
        {"plane_joints", "0", "0/1", "1: hold each block in the plane with a Plane2D joint (nothing needs it)", 0.0, 1.0},
    });
    return table;
}

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("ODE", s, setting_table());
    Knobs k{};
    k.erp = r.number("erp", 0.2);
    require(k.erp >= 0.0 && k.erp <= 1.0, "ODE setting erp", "in [0, 1]", k.erp);
    k.cfm = r.non_negative("cfm", 1e-10);
    k.surface_layer = r.non_negative("surface_layer", 0.0);
    k.max_correcting_vel = r.number("max_correcting_vel", INFINITY);
    require(k.max_correcting_vel > 0.0, "ODE setting max_correcting_vel (m/s)", "> 0 (inf: no cap)",
            k.max_correcting_vel);
    k.margin = r.non_negative("margin", 1e-3);
    k.quickstep_iterations = r.flag("quickstep") ? (s.iterations > 0 ? s.iterations : 20) : 0;
    k.limits = FailureLimits::read(r);
    k.moving_supports = r.flag("moving_supports");
    k.plane_joints = r.flag("plane_joints");
    return k;
}

struct Vec2 {
    double x, y;
};

// A point given in a body's frame, in world coordinates (x, y).
Vec2 world_point(dBodyID body, double lx, double ly) {
    dVector3 p;
    dBodyGetRelPointPos(body, lx, ly, 0.0, p);
    return {p[0], p[1]};
}

// Clockwise angle of a body about z, from its rotation matrix (ODE's dMatrix3 is row-major, 3 x 4).
double clockwise_angle(dBodyID body) {
    const dReal* r = dBodyGetRotation(body);
    return -std::atan2(r[4], r[0]);
}

// How far a body's z axis has turned away from the world's z (sine of the angle), squared: checked every step, so
// compared as a square (hypot is a slow call of the C library; the root only for the message).
double out_of_plane_tilt_squared(dBodyID body) {
    const dReal* r = dBodyGetRotation(body);
    return r[2] * r[2] + r[6] * r[6];
}

class OdeScene {
public:
    OdeScene(const WallScene& scene, const Knobs& knobs, double theta0, double dt)
        : knobs_(knobs), dt_(dt), sizes_(block_sizes(scene)), friction_(scene.base_mu()),
          hinge_friction_(scene.hinge_mu()), corner_radius_(scene.corner_radius()) {
        ensure_ode();
        world_ = dWorldCreate();
        group_ = dJointGroupCreate(0);
        dWorldSetGravity(world_, 0.0, -scene.gravity(), 0.0);
        dWorldSetContactSurfaceLayer(world_, knobs.surface_layer);
        dWorldSetContactMaxCorrectingVel(world_, knobs.max_correcting_vel);
        dWorldSetAutoDisableFlag(world_, 0);  // a slowly rocking wall must never be put to sleep
        if (knobs.quickstep_iterations > 0) dWorldSetQuickStepNumIterations(world_, knobs.quickstep_iterations);

        const double b = sizes_.b, h = sizes_.h_lower + sizes_.h_upper;
        const double m = knobs.margin;
        // Ground: a box whose top face is `margin` above the physical ground (y = 0; see add_pair). A moving ground
        // travels with the record's displacement: wide enough that the wall never reaches its edge.
        const double half_width = knobs.moving_supports ? 1e4 : 4.0 * h + 10.0 * b;
        ground_geom_ = dCreateBox(nullptr, 2.0 * half_width, 2.0 * h, 4.0 * kDepth);
        if (knobs.moving_supports) {
            ground_body_ = dBodyCreate(world_);
            dBodySetKinematic(ground_body_);
            dGeomSetBody(ground_geom_, ground_body_);
            dGeomSetOffsetPosition(ground_geom_, 0.0, -h + m, 0.0);
        } else {
            dGeomSetPosition(ground_geom_, 0.0, -h + m, 0.0);
        }
        // Lower block; for a VSSW its collision box reaches `margin` above its top face (speculative hinge contacts).
        // Collision boxes are deeper than the blocks (upper 1 m, lower 2 m, ground 4 m): contact points are projected
        // onto z = 0 anyway, and no two faces end on the same edge, where clipping could keep or drop a point by
        // rounding.
        lower_ = add_block(sizes_.b, sizes_.h_lower, sizes_.m_lower);
        const double top_skin = scene.vssw ? m : 0.0;
        // Rounded corners: the boxes are the flat parts, b - r wide (add_rounding); r = 0: b, as always.
        const double box_b = b - corner_radius_;
        lower_geom_ = dCreateBox(nullptr, 2.0 * box_b, 2.0 * sizes_.h_lower + top_skin, 2.0 * kDepth);
        dGeomSetBody(lower_geom_, lower_);
        dGeomSetOffsetPosition(lower_geom_, 0.0, 0.5 * top_skin, 0.0);
        if (scene.vssw) {
            upper_ = add_block(sizes_.b, sizes_.h_upper, sizes_.m_upper);
            upper_geom_ = dCreateBox(nullptr, 2.0 * box_b, 2.0 * sizes_.h_upper, kDepth);
            dGeomSetBody(upper_geom_, upper_);
        }
        if (scene.vssw && !scene.diaphragm.is_rigid()) {  // the roller's own carrier, at the ground's place at rest
            top_body_ = dBodyCreate(world_);
            dBodySetKinematic(top_body_);
        }
        if (corner_radius_ > 0.0) add_rounding();
        const WallPose pose = pose_at(scene, theta0);
        place(lower_, pose.lower);
        if (upper_) place(upper_, pose.upper);
    }

    ~OdeScene() {
        dJointGroupDestroy(group_);
        for (dGeomID g : {ground_geom_, lower_geom_, upper_geom_})
            if (g) dGeomDestroy(g);
        for (dGeomID g : arcs_) dGeomDestroy(g);
        dWorldDestroy(world_);  // the bodies and the plane joints with it
    }
    OdeScene(const OdeScene&) = delete;
    OdeScene& operator=(const OdeScene&) = delete;

    dBodyID lower() const { return lower_; }
    dBodyID upper() const { return upper_; }
    double ground_x() const { return ground_body_ ? dBodyGetPosition(ground_body_)[0] : 0.0; }
    double ground_velocity() const { return ground_body_ ? dBodyGetLinearVel(ground_body_)[0] : 0.0; }
    int contacts() const { return contacts_; }

    // One step: the ground's velocity for the step (moving supports) and the top support's relative to it (a
    // flexible one), the contacts at the start of the step, the solver. Forces other than gravity must have been
    // added before.
    void step(double ground_velocity, double top_velocity) {
        if (ground_body_) dBodySetLinearVel(ground_body_, ground_velocity, 0.0, 0.0);
        if (top_body_) dBodySetLinearVel(top_body_, ground_velocity + top_velocity, 0.0, 0.0);
        dJointGroupEmpty(group_);
        contacts_ = 0;
        add_pair(ground_geom_, lower_geom_, {0.0, 1.0}, {ground_x(), 0.0}, friction_);
        // Rounded corners: the base arcs on the ground (its box raised by the margin, as for the block's box); each
        // top arc of the lower block on the upper block's bottom arc of its side (no margin: skin 0).
        if (!arcs_.empty())
            for (std::size_t i : {0u, 1u}) add_pair(ground_geom_, arcs_[i], {0.0, 1.0}, {ground_x(), 0.0}, friction_);
        if (upper_) {
            const dReal* r = dBodyGetRotation(lower_);
            // The lower block's top face: its centre and its y axis, along which its collision box reaches past it.
            add_pair(lower_geom_, upper_geom_, {r[1], r[5]}, world_point(lower_, 0.0, sizes_.h_lower),
                     hinge_friction_);
            if (!arcs_.empty())
                for (std::size_t i : {2u, 3u})
                    add_pair(arcs_[i], arcs_[i + 2], {0.0, 0.0}, {0.0, 0.0}, hinge_friction_);
            add_roller();
        }
        if (knobs_.quickstep_iterations > 0)
            dWorldQuickStep(world_, dt_);
        else
            dWorldStep(world_, dt_);
    }

private:
    dBodyID add_block(double half_w, double half_h, double mass_per_depth) {
        dBodyID body = dBodyCreate(world_);
        dMass mass;
        dMassSetBoxTotal(&mass, mass_per_depth * kDepth, 2.0 * half_w, 2.0 * half_h, kDepth);  // I_z = m R^2 / 3
        dBodySetMass(body, &mass);
        dBodySetAutoDisableFlag(body, 0);
        if (knobs_.plane_joints) {
            dJointID plane = dJointCreatePlane2D(world_, nullptr);
            dJointAttach(plane, body, nullptr);
        }
        return body;
    }

    // Rounded corners (kit/rounded_corners.hpp): capsules of radius r along the depth (ODE's capsule axis, z) at the
    // arcs' centres, no mass of their own (the body's mass is set, the rectangle's). arcs_: the lower block's bottom
    // left and right, then (VSSW) its top left and right, then the upper block's bottom left and right.
    void add_rounding() {
        const double r = corner_radius_, in = sizes_.b - r;
        auto arc = [&](dBodyID body, double x, double y) {
            dGeomID g = dCreateCapsule(nullptr, r, kDepth);
            dGeomSetBody(g, body);
            dGeomSetOffsetPosition(g, x, y, 0.0);
            arcs_.push_back(g);
        };
        for (double side : {-1.0, 1.0}) arc(lower_, side * in, -(sizes_.h_lower - r));
        if (!upper_) return;
        for (double side : {-1.0, 1.0}) arc(lower_, side * in, sizes_.h_lower - r);
        for (double side : {-1.0, 1.0}) arc(upper_, side * in, -(sizes_.h_upper - r));
    }

    static void place(dBodyID body, const BlockPose& p) {
        dBodySetPosition(body, p.x, p.y, 0.0);
        dMatrix3 r;
        dRFromAxisAndAngle(r, 0.0, 0.0, 1.0, -p.angle);  // ODE turns counter-clockwise
        dBodySetRotation(body, r);
    }

    // Contacts between two geoms: at most 8 points from dCollide (box-box), projected onto z = 0 and merged by
    // position (a corner edge gives one point at each end, z = +-depth/2: one planar contact, no indeterminate split
    // between two points that only the plane joint's rows could tell apart). g1's collision box reaches `margin` past
    // its physical face (through `surface`, outward normal `skin`): the physical penetration is
    // depth - margin |n . skin|; negative means a gap, and the contact is speculative. A point dCollide puts on the
    // enlarged face rather than at the other body's corner (the enlarged box is then the incident one) is moved back
    // onto the physical face: left there it sat `margin` off the corner, and the friction row held that point rather
    // than the corner (measured: +2.8e-4 on the Fig. 6 VSSW's period with a 1 mm margin, not falling with the step;
    // with the point moved back, margins from 1e-4 to 1e-2 m give the same period to 1e-6 at 0.2 and 0.05 ms).
    //
    // Friction: the coefficient bounds the friction force by the normal force of the same solve (dContactApprox1),
    // along the in-plane tangent only (dContactFDir1 and mu2 = 0: the plane joint holds z). mu = dInfinity, the
    // other choice, makes a speculative contact's friction row bilateral even while its normal row is idle: measured,
    // the lifting corner of the 0.9 m x 0.11 m parapet was held sideways and its period came out 9 % long.
    //
    // Out of line, as add_roller: a profile tells this contact generation, the engine's scheme done by the adapter, from
    // the rest of the adapter's work (bench/adapter_share.py).
    [[gnu::noinline]] void add_pair(dGeomID g1, dGeomID g2, Vec2 skin, Vec2 surface, double mu) {
        // Left uninitialised: dCollide writes the first n, the merge the first `count`, and only those are read.
        // Zeroing both (1.5 kB a pair, three pairs a step) was a fifth of the adapter's own time in a run (perf).
        std::array<dContactGeom, 8> found;
        const int n = dCollide(g1, g2, static_cast<int>(found.size()), found.data(), sizeof(dContactGeom));
        std::array<dContactGeom, 8> merged;
        int count = 0;
        for (int i = 0; i < n; ++i) {
            dContactGeom c = found[static_cast<std::size_t>(i)];
            c.pos[2] = 0.0;
            // hypot(x, 0) is |x| exactly (C's Annex F): an axis-aligned normal, the ground's face, needs no call.
            const double len = c.normal[0] == 0.0   ? std::abs(c.normal[1])
                               : c.normal[1] == 0.0 ? std::abs(c.normal[0])
                                                    : std::hypot(c.normal[0], c.normal[1]);
            if (!(len > 0.5)) continue;  // an out-of-plane normal: not a planar contact (none measured)
            c.normal[0] /= len;
            c.normal[1] /= len;
            c.normal[2] = 0.0;
            bool duplicate = false;
            for (int j = 0; j < count && !duplicate; ++j) {
                dContactGeom& d = merged[static_cast<std::size_t>(j)];
                const double dx = d.pos[0] - c.pos[0], dy = d.pos[1] - c.pos[1];
                if (dx * dx + dy * dy < kMergeDistance * kMergeDistance) {  // squares: no hypot call per pair
                    d.depth = std::max(d.depth, c.depth);
                    duplicate = true;
                }
            }
            if (!duplicate) merged[static_cast<std::size_t>(count++)] = c;
        }
        for (int i = 0; i < count; ++i) {
            const dContactGeom& g = merged[static_cast<std::size_t>(i)];
            const double penetration = g.depth - knobs_.margin * std::abs(g.normal[0] * skin.x + g.normal[1] * skin.y);
            dContact c{};
            c.geom = g;
            // Height of the point above the physical face: the other body's corner stands at the gap, a point of the
            // enlarged face at the margin.
            const double height = (g.pos[0] - surface.x) * skin.x + (g.pos[1] - surface.y) * skin.y;
            if (std::abs(height - knobs_.margin) < std::abs(height + penetration)) {
                c.geom.pos[0] -= knobs_.margin * skin.x;
                c.geom.pos[1] -= knobs_.margin * skin.y;
            }
            c.surface.mode = dContactMu2 | dContactFDir1 | dContactApprox1_1;
            c.surface.mu = mu;
            c.surface.mu2 = 0.0;
            c.fdir1[0] = -g.normal[1];
            c.fdir1[1] = g.normal[0];
            c.fdir1[2] = 0.0;
            add_contact(c, penetration, dGeomGetBody(g1), dGeomGetBody(g2));
        }
    }

    // The roller: a frictionless contact between the upper block and the ground at the top corner on the pivot's
    // side, normal (-side, 0, 0) pointing back into the allowed side. Only the guide whose corner is further out is
    // given to the solver (docs/contributing/engines.md, "Bullet": switching by the sign of theta1 let the free corner
    // drift at rest, both at once made a redundant loop near theta1 = 0). It is given every step, speculative while its
    // corner is inside the line: the solver lets the corner reach the line within the step and no further, so the
    // roller engages in the very step the guides switch sides at an impact (measured on the Fig. 6 VSSW at 0.05 ms: in
    // the impact step the new guide's corner starts within 1e-10 m of its line and the guide takes its share of the
    // impulse).
    [[gnu::noinline]] void add_roller() {
        const double b = sizes_.b, x0 = top_body_ ? dBodyGetPosition(top_body_)[0] : ground_x();
        const Vec2 right = world_point(upper_, b, sizes_.h_upper), left = world_point(upper_, -b, sizes_.h_upper);
        const double right_out = right.x - x0 - b, left_out = -b - (left.x - x0);  // also the guides' gaps
        const bool use_left = left_out > right_out;  // left_guide_binds (scene_geometry.hpp), with the gaps kept
        const Vec2 corner = use_left ? left : right;
        dContact c{};
        c.geom.pos[0] = corner.x;
        c.geom.pos[1] = corner.y;
        c.geom.normal[0] = use_left ? 1.0 : -1.0;
        c.surface.mode = 0;
        c.surface.mu = 0.0;  // frictionless: y free
        add_contact(c, (use_left ? left_out : right_out) - kRollerGap, upper_, top_body_ ? top_body_ : ground_body_);
    }

    // A contact joint for the solver: a penetration as ODE's depth (pushed out by erp beyond the surface layer), a
    // gap as a speculative row (J v >= -gap / h: the bodies may close the gap within the step and no further).
    void add_contact(dContact& c, double penetration, dBodyID b1, dBodyID b2) {
        c.geom.depth = std::max(penetration, 0.0);
        c.surface.mode |= dContactSoftERP | dContactSoftCFM;
        c.surface.soft_erp = knobs_.erp;
        c.surface.soft_cfm = knobs_.cfm;
        if (penetration < 0.0) {
            c.surface.mode |= dContactMotionN;
            c.surface.motionN = penetration / dt_;
        }
        dJointID j = dJointCreateContact(world_, group_, &c);
        dJointAttach(j, b1, b2);
        ++contacts_;
    }

    // Two points of one corner edge (z = +-depth/2) project onto the same point to rounding; distinct corners are
    // at least the wall's thickness apart.
    static constexpr double kMergeDistance = 1e-7;  // [m]
    // The roller's line sits this far outside the face's line. The roller is the one contact nothing loads at rest
    // (no horizontal force on the upper block, no torque about its centre): with its corner exactly on the line, as
    // pose_at() can put it, the row's right-hand side is exactly zero and Dantzig's pivoting takes a zero step ("LCP
    // internal error, s <= 0"), zeroing every force of the step (measured: T1 #1 released at 0.5 and 0.8 alpha1 fell
    // through the ground, the error on every step). 1e-12 m keeps the row regular and is far below anything measured.
    static constexpr double kRollerGap = 1e-12;  // [m]

    Knobs knobs_;
    double dt_;
    BlockSizes sizes_;
    double friction_, hinge_friction_;  // the base's and the hinge's Coulomb coefficients
    double corner_radius_;       // r [m] of every block corner (0: sharp boxes)
    std::vector<dGeomID> arcs_;  // the rounded corners' capsules (add_rounding)
    dWorldID world_ = nullptr;
    dJointGroupID group_ = nullptr;
    dGeomID ground_geom_ = nullptr, lower_geom_ = nullptr, upper_geom_ = nullptr;
    dBodyID ground_body_ = nullptr, lower_ = nullptr, upper_ = nullptr;
    dBodyID top_body_ = nullptr;  // the roller's carrier: a flexible top support only
    int contacts_ = 0;
};

class OdeEngine final : public Engine {
public:
    // The library is initialised with the engine, on the thread that makes it, before any pool starts: a worker
    // process forked later inherits it whole, never half done by another thread (whose lock the child would wait on
    // for ever), and pays no dInitODE2 per run.
    OdeEngine() { ensure_ode(); }
    std::string name() const override { return "ode"; }
    std::string display_name() const override { return "ODE"; }
    double cost_per_simulated_second() const override { return 2.0e-3; }  // at 1 ms, docs/measurements/speed.md
    std::string version() const override {
        ensure_ode();
        return fmt::format("ODE {} ({} precision)", dODE_VERSION,
                           dCheckConfiguration("ODE_double_precision") ? "double" : "single");
    }
    EngineSettings default_settings() const override {
        EngineSettings s;
        // Measured (bench/engine_accuracy.cpp over the reference walls at 1, 0.2 and 0.05 ms): thresholds equal the
        // analytic model's bisection bracket at every step (1e-4; with a bracket of 1e-6 they are within 1.6e-6 of
        // Eq. 12 at 1 ms: the direct solver holds a wall at rest exactly); period errors are first order, -0.07 to
        // -0.19 % at 1 ms, -0.015 to -0.038 % at 0.2 ms, -0.004 to -0.009 % at 0.05 ms. 1 ms meets every target
        // in `vssw bench` and on the full validation suite (docs/contributing/engines.md "Defaults, by measurement")
        // for a fifth of 0.2 ms's cost. The error grows as dt over the period: a wall much smaller (faster) than Table
        // 1's needs a smaller step (docs/contributing/engines.md, "ODE"). It is also the Bullet adapter's step.
        s.dt = 1e-3;
        s.iterations = 0;  // the direct solver has none; dWorldQuickStep (quickstep = 1) takes 20 unless set
        return s;
    }
    std::vector<SettingDescription> setting_descriptions() const override { return setting_table(); }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { (void)read_knobs(settings); }
    // ODE's library state is process-wide (ensure_ode(): the initialisation, the message handler and its count,
    // per-thread collision data): one run at a time in a process. make_engine() runs each run in a child of its own
    // (isolated_engine.hpp), where its only process-wide state, the message count and the random seed, is set per
    // run: the run is the same as in this process, and runs go side by side.
    bool runs_concurrently() const override { return false; }
};

// The stepping kit's hooks (step_loop.hpp) on an OdeScene.
class OdeStepping {
public:
    OdeStepping(OdeScene& w, const WallScene& scene, const Knobs& knobs)
        : w_(w),
          knobs_(knobs),
          energy_(scene, kDepth),
          s_(block_sizes(scene)),
          N_(scene.overburden() * kDepth),
          lower_(w.lower()),
          upper_(w.upper()),
          top_body_(upper_ ? upper_ : lower_),
          top_half_(upper_ ? s_.h_upper : s_.h_lower),
          load_x_(scene.overburden_offset()),
          lower_mass_(mass_of(lower_)),
          upper_mass_(upper_ ? mass_of(upper_) : dMass{}) {}

    void drive(const GroundStep& g) {
        if (knobs_.moving_supports || g.a_h == 0.0) return;  // moving supports: the ground's velocity goes to step()
        dBodyAddForce(lower_, -s_.m_lower * kDepth * g.a_h, 0.0, 0.0);
        if (upper_) dBodyAddForce(upper_, -s_.m_upper * kDepth * g.a_h, 0.0, 0.0);
    }
    void push_overburden() {
        const Vec2 top = world_point(top_body_, load_x_, top_half_);
        dBodyAddForceAtPos(top_body_, 0.0, -N_, 0.0, top.x, top.y, 0.0);
    }
    void step(const StepTimes&, const GroundStep& g) {
        angles_.forget();
        w_.step(g.v, g.top_v);
    }
    // ODE's messages (its error and debug handlers) and a block leaving the plane fail the run.
    void check_step(double t) const {
        if (g_ode_messages != messages_before_)
            throw EngineFailure(fmt::format("ODE: {} at t = {:.6g} s", g_ode_last_message, t));
        constexpr double kTilt = 1e-9;  // measured: exactly 0 (see the top of the file)
        const double tilt2 =
            std::max(out_of_plane_tilt_squared(lower_), upper_ ? out_of_plane_tilt_squared(upper_) : 0.0);
        if (tilt2 > kTilt * kTilt)
            throw EngineFailure(
                fmt::format("ODE: a block turned {:.3g} rad out of the plane at t = {:.6g} s", std::sqrt(tilt2), t));
    }
    WallState state(const GroundStep& g) const {
        const double x_g = w_.ground_x();
        auto block = [&](dBodyID body, double angle) {  // relative to the (moving) ground
            const dReal *c = dBodyGetPosition(body), *v = dBodyGetLinearVel(body), *r = dBodyGetRotation(body);
            // The clockwise angle's cosine and sine as the rotation holds them (clockwise_angle's two entries).
            return BlockState{c[0] - x_g, c[1], angle, v[0] - g.v, v[1], -dBodyGetAngularVel(body)[2], r[0], -r[4]};
        };
        return {block(lower_, lower_angle()), upper_ ? block(upper_, upper_angle()) : kNoBlock};
    }
    Rocking rocking() const { return {lower_angle(), -dBodyGetAngularVel(lower_)[2]}; }
    void fill(TrajectorySample& p) const {
        p.theta2 = upper_ ? upper_angle() : 0.0;
        const double v_ground = w_.ground_velocity();
        // ODE's full 3-D sum: the out-of-plane terms are 0 (see check_step).
        auto kinetic = [&](dBodyID body, const dMass& m) {
            const dReal* v = dBodyGetLinearVel(body);
            const dReal* wv = dBodyGetAngularVel(body);
            const double vx = v[0] - v_ground;
            return 0.5 * m.mass * (vx * vx + v[1] * v[1] + v[2] * v[2]) +
                   0.5 * (m.I[0] * wv[0] * wv[0] + m.I[5] * wv[1] * wv[1] + m.I[10] * wv[2] * wv[2]);
        };
        energy_.fill(p, {kinetic(lower_, lower_mass_), upper_ ? kinetic(upper_, upper_mass_) : 0.0,
                         dBodyGetPosition(lower_)[1],
                         upper_ ? dBodyGetPosition(upper_)[1] : 0.0, world_point(top_body_, load_x_, top_half_).y});
        p.contacts = w_.contacts();
    }

private:
    // A body's mass and inertia, read once: they do not change over a run (read per sample, dMass's constructor
    // zeroing it first, they cost 0.35 % of a free vibration's run, callgrind).
    static dMass mass_of(dBodyID body) {
        dMass m;
        dBodyGetMass(body, &m);
        return m;
    }
    double lower_angle() const { return angles_.lower([&] { return clockwise_angle(lower_); }); }
    double upper_angle() const { return angles_.upper([&] { return clockwise_angle(upper_); }); }

    OdeScene& w_;
    const Knobs& knobs_;
    WallEnergy energy_;
    BlockSizes s_;
    double N_;
    dBodyID lower_, upper_, top_body_;
    double top_half_;
    double load_x_;  // N's point on the top face from its centre, toward theta1 > 0 [m]
    dMass lower_mass_, upper_mass_;
    const int messages_before_ = g_ode_messages;
    mutable StepAngles angles_;  // read by state(), rocking() and fill() of one step
};

Trajectory OdeEngine::simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "ODE time step dt (s)", "a positive finite number",
            settings.dt);
    require_one_description(scene);
    const Knobs knobs = read_knobs(settings);
    const double dt = settings.dt;
    // dWorldQuickStep reorders its constraint rows with ODE's process-wide random generator: seeded at every run, so
    // that a run's result does not depend on the runs before it in the process (threads, shards, MPI processes).
    dRandSetSeed(0);
    OdeScene w(scene, knobs, ex.theta0, dt);
    OdeStepping stepping(w, scene, knobs);
    RunMonitor monitor("ODE", scene, ex, dt, knobs.limits);
    const StepLoop loop{dt, sample_every(settings, dt), knobs.moving_supports, scene.overburden() > 0.0,
                        scene.diaphragm};
    return run_fixed_steps(stepping, ex, loop, monitor);
}

}  // namespace

std::unique_ptr<Engine> make_ode_engine() { return std::make_unique<OdeEngine>(); }

}  // namespace vssw::multibody

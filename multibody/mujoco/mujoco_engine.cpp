// MuJoCo adapter: the wall as bodies of an mjModel compiled from an XML text held in memory (MuJoCo's virtual file
// system: no file is written), each block on slide-x, slide-z and hinge-y joints, so that the motion is exactly
// planar. MuJoCo's world has z up: the engine's (x, y) plane is MuJoCo's (x, z) plane, and the engine's clockwise
// rotation (the wall tipping towards +x) is a positive rotation about MuJoCo's +y axis: theta = the hinge's qpos.
//
// Scene (from the analytic description; depth 1 m, so masses and energies are per unit depth as in the paper):
//  - ground: a plane z = 0 in the world body (MuJoCo allows planes only in static bodies);
//  - lower and upper blocks: box geoms (b, h1) and (b, h2) (one box (b, h) for a parapet) with their masses and
//    inertias given (not from the geoms), both children of the world body: MuJoCo drops contacts between a body and
//    its parent by default (mjDSBL_FILTERPARENT), so an upper block nested in the lower would lose the hinge;
//  - contacts: only the pairs the wall can touch, declared as <pair>s (every geom's contype and conaffinity are 0):
//    ground-lower (box-plane: the corners), the upper block's bottom-corner spheres on the lower block's face box
//    (the hinge; flush box-box contact is broken in 2.2.2, below) with friction, and (VSSW only) the roller;
//  - the roller, one-sided as in the other adapters (docs/contributing/engines.md "Bullet"): a tiny sphere at each top
//    corner of the upper block, set in by its radius so that its outer point is the corner's line, against a frictionless
//    (condim 1) plane at x = +b (normal -x) and one at x = -b (normal +x). Both guides are in every step; a sphere inside
//    its line is a contact that is not active. Sphere-plane distances are exact to rounding at any depth;
//  - N: a force and its moment about the centre of mass (xfrc_applied), the force acting on the top face at its point
//    (the centre, or e from it), set every step;
//  - ground motion: pseudo-forces, the x component of gravity set to -a_h at each step's midpoint (a uniform field:
//    -m a_h at every centre of mass). No moving supports: MuJoCo's planes must be static, and a mocap ground moves
//    without a velocity the contacts would see (docs/contributing/engines.md "MuJoCo").
//
// Contact: MuJoCo's contacts are soft (a spring-damper reference acceleration, solref, mixed with the constraint by
// an impedance, solimp). At its defaults (solref 0.02 s, solimp 0.9/0.95) a rocking block loses 5.5 % too much
// velocity at each impact, whatever the step; with the time constant at 2 dt (the smallest MuJoCo accepts: its
// refsafe floor) and the impedance near 1 the impacts are those of rigid bodies (docs/contributing/engines.md "MuJoCo").
#include "multibody/mujoco/mujoco_engine.hpp"

#include <mujoco/mujoco.h>

#include <stdexcept>
#include <array>
#include <iterator>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/energy.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_loop.hpp"
#include "multibody/kit/top_support.hpp"

namespace vssw::multibody {
namespace {

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

// MuJoCo's error handler must not return (MuJoCo would go on past the error; without a handler it calls exit()): it
// throws, and simulate() turns the text into an EngineFailure. Warnings (mju_warning: "Nan, Inf or huge value in
// QACC", after which mj_step resets the simulation to its initial state and goes on, or a full contact buffer) are
// recorded for the thread that ran into them; simulate() fails the run on any warning MuJoCo counts in mjData.
struct MujocoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
thread_local std::string t_last_warning;

void on_mujoco_error(const char* text) { throw MujocoError(text ? text : "(no text)"); }
void on_mujoco_warning(const char* text) { t_last_warning = text ? text : "(no text)"; }

// The handlers are process-wide function pointers: set once (they hold no state but the thread's last warning).
void ensure_handlers() {
    static const bool set = [] {
        mju_user_error = &on_mujoco_error;
        mju_user_warning = &on_mujoco_warning;
        return true;
    }();
    (void)set;
}

// The integrators of MuJoCo 2.2.2 (mjtIntegrator): semi-implicit Euler, RK4, implicit in the velocity.
constexpr const char* kIntegrators[] = {"Euler", "RK4", "implicit"};
constexpr int kIntegratorCount = static_cast<int>(std::size(kIntegrators));

// The sphere that stands for a top corner of the upper block at the roller [m]: a point, set in from the corner by
// its radius (sphere-plane distances are exact whatever the radius).
constexpr double kRollerSphereRadius = 1e-6;

// The spheres that stand for the upper block's bottom corners at the hinge [m], their lowest points at the corners.
// MuJoCo 2.2.2's box-box contact kicked the flush blocks at random (a trial's wall launched upwards at 1 m/s in its
// third step), and its sphere-box distance stops at minus the radius once the centre is inside the box, so the radius
// must exceed every penetration (about 1e-5 m at rest, 1e-4 m in an impact at 1 ms). The rounding is a bias: 1 mm gave
// a period -1.5 % off on T1 #14 at xi 0.5 flying off the roller (0.2 mm: -0.31 %), docs/contributing/engines.md "MuJoCo".
constexpr double kHingeSphereRadius = 2e-4;

struct Knobs {
    int iterations;  // Newton iterations per step
    double tolerance;
    int integrator;  // kIntegrators
    int noslip_iterations;
    // solref (time constant, damping ratio): the time constant in steps (MuJoCo raises anything below 2 dt to 2 dt).
    double solref_steps, dampratio;
    // solimp (dmin, dmax, width, midpoint 0.5, power 2).
    double solimp_dmin, solimp_dmax, solimp_width;
    FailureLimits limits;  // slide_limit, penetration_limit (run_monitor.hpp)
};

constexpr int kDefaultIterations = 100;
constexpr int kMaxNoslipIterations = 1000;  // noslip_iterations' range: a pass of 1000 is far past any that converges

// Ranges (SettingDescription::lo/hi): solref's time constant from MuJoCo's floor (2 steps) to 1000 steps (a contact
// of a second's time constant at 1 ms: the wall sinks); the impedances within MuJoCo's own clamp [1e-4, 0.9999]
// (mjMINIMP, mjMAXIMP); the tolerance from 1e-15 (rounding) to 1e-2.
const std::vector<SettingDescription>& setting_table() {
    // Built once per process: each run reads it at its start, and a forked run inherits the parent's.
    static const std::vector<SettingDescription> table = FailureLimits::described_after({
        {"dt", "0.001", "s", "the step (docs/engines.md \"MuJoCo\": every target met at 1 ms)"},
        {"iterations", std::to_string(kDefaultIterations), "", "Newton solver iterations per step (at most)"},
        {"tolerance", "1e-08", "", "Newton solver tolerance (relative improvement of the cost)", 1e-15, 1e-2},
        {"integrator", "0", "choice", "0 semi-implicit Euler, 1 RK4, 2 implicit (in the velocity)", 0.0, 2.0},
        {"noslip_iterations", "0", "", "iterations of MuJoCo's noslip pass (hard friction after the soft solve)", 0.0,
         static_cast<double>(kMaxNoslipIterations)},
        {"solref_steps", "2", "", "contacts' time constant (solref) in steps; 2 is MuJoCo's floor (refsafe)", 2.0,
         1000.0},
        {"dampratio", "1", "", "contacts' damping ratio (solref's second number)", 0.1, 10.0},
        {"solimp_dmin", "0.99", "", "contacts' impedance at zero penetration (solimp's first number)", 1e-4, 0.9999},
        {"solimp_dmax", "0.999", "", "contacts' impedance past solimp_width (solimp's second number)", 1e-4, 0.9999},
        // Above 0: MuJoCo takes a width of 0 (below mjMINVAL) as a flat impedance at (dmin + dmax) / 2, not a step.
        {"solimp_width", "0.001", "m", "penetration over which the impedance goes from dmin to dmax", 1e-9, 1.0},
    });
    return table;
}

Knobs read_knobs(const EngineSettings& s) {
    const SettingsReader r("MuJoCo", s, setting_table());
    Knobs k{};
    k.iterations = s.iterations > 0 ? s.iterations : kDefaultIterations;
    k.tolerance = r.positive("tolerance", 1e-8);
    k.integrator = r.choice("integrator", 0, kIntegratorCount);
    k.noslip_iterations = r.whole_number("noslip_iterations", 0, kMaxNoslipIterations);
    k.solref_steps = r.positive("solref_steps", 2.0);
    k.dampratio = r.positive("dampratio", 1.0);
    k.solimp_dmin = r.positive("solimp_dmin", 0.99);
    k.solimp_dmax = r.positive("solimp_dmax", 0.999);
    k.solimp_width = r.positive("solimp_width", 1e-3);
    k.limits = FailureLimits::read(r);
    return k;
}

std::string num(double v) { return fmt::format("{:.17g}", v); }
std::string short_num(double v) { return fmt::format("{:.6g}", v); }  // for the reader of the file's comment

// A block's <body>: at its place at rest, on slide-x, slide-z and hinge-y joints at its centre (the slides first, so
// that their axes stay the world's), with its mass and inertia per depth kDepth, and a box geom.
std::string block_xml(const std::string& name, double b, double h, double mass_per_depth, double z_rest,
                      const std::string& extra_geoms, double box_b = -1.0) {
    const double m = mass_per_depth * kDepth, w = 2.0 * b, H = 2.0 * h, d = kDepth;
    if (box_b < 0.0) box_b = b;  // the box geom's half-width: b, or b - r for a rounded block (its flat part)
    return fmt::format(
        "<body name='{0}' pos='0 0 {1}'>"
        "<joint name='{0}_x' type='slide' axis='1 0 0'/><joint name='{0}_z' type='slide' axis='0 0 1'/>"
        "<joint name='{0}_r' type='hinge' axis='0 1 0'/>"
        "<inertial pos='0 0 0' mass='{2}' diaginertia='{3} {4} {5}'/>"
        "<geom name='{0}' type='box' size='{6} {7} {8}'/>{9}</body>\n",
        name, num(z_rest), num(m), num(m * (d * d + H * H) / 12.0), num(m * (w * w + H * H) / 12.0),
        num(m * (w * w + d * d) / 12.0), num(box_b), num(0.5 * d), num(h), extra_geoms);
}

// Rounded corners (kit/rounded_corners.hpp): each block's outline as MuJoCo's convex pieces, a box of half-width b - r
// (its bottom face the flat part, on the ground) and capsules of radius r along the depth at the arcs' centres
// (capsule-plane, capsule-box and capsule-capsule are MuJoCo's analytic pairs; a capsule's caps stick out of the
// depth, where nothing is). The hinge: the upper block's bottom capsules on the lower block's face box, now b - r wide
// (the flats), and on the lower block's top capsules (the arcs rolling on each other). The roller's spheres stay at
// the nominal top corners. Names: "<block>_<b|t><r|l>" (bottom/top, right/left).
std::string capsule_xml(const std::string& name, double r, double x, double z) {
    return fmt::format("<geom name='{}' type='capsule' size='{} {}' pos='{} 0 {}' zaxis='0 1 0'/>", name, num(r),
                       num(0.5 * kDepth), num(x), num(z));
}

// The roller (VSSW only): a plane at x = +b and one at x = -b, each pushing on the sphere at the upper block's top
// corner on its side (one-sided each), and the pairs that make them meet.
std::string guides_xml(const BlockSizes& s) {
    return fmt::format("<geom name='guide_right' type='plane' size='100 100 1' pos='{} 0 0' zaxis='-1 0 0'/>\n"
                       "<geom name='guide_left' type='plane' size='100 100 1' pos='{} 0 0' zaxis='1 0 0'/>\n",
                       num(s.b), num(-s.b));
}
std::string top_spheres_xml(const BlockSizes& s) {
    return fmt::format("<geom name='top_right' type='sphere' size='{0}' pos='{1} 0 {3}'/>"
                       "<geom name='top_left' type='sphere' size='{0}' pos='{2} 0 {3}'/>",
                       num(kRollerSphereRadius), num(s.b - kRollerSphereRadius), num(-(s.b - kRollerSphereRadius)),
                       num(s.h_upper));
}
std::string roller_pairs_xml(const std::string& contact) {
    return fmt::format("<pair geom1='guide_right' geom2='top_right' condim='1' {0}/>\n"
                       "<pair geom1='guide_left' geom2='top_left' condim='1' {0}/>\n",
                       contact);
}

// friction, hinge_friction: the base's and the hinge's pair attributes (model_xml).
std::string rounded_model_xml(const WallScene& scene, const std::string& head, const std::string& friction,
                              const std::string& hinge_friction, const std::string& contact) {
    const BlockSizes s = block_sizes(scene);
    const double r = scene.corner_radius(), in = s.b - r;
    std::string xml = head;
    std::string lower_extra = capsule_xml("lower_br", r, in, -(s.h_lower - r)) +
                              capsule_xml("lower_bl", r, -in, -(s.h_lower - r));
    if (scene.vssw)
        lower_extra += fmt::format("<geom name='hinge_face' type='box' size='{0} {1} {2}' pos='0 0 {3}'/>", num(in),
                                   num(0.5 * kDepth), num(s.b), num(s.h_lower - s.b)) +
                       capsule_xml("lower_tr", r, in, s.h_lower - r) + capsule_xml("lower_tl", r, -in, s.h_lower - r);
    // The box geom is the flat part's: b - r wide; the block's mass and inertia are given, the rectangle's.
    xml += block_xml("lower", s.b, s.h_lower, s.m_lower, s.h_lower, lower_extra, in);
    if (scene.vssw) {
        xml += guides_xml(s);
        const std::string upper_extra = top_spheres_xml(s) + capsule_xml("upper_br", r, in, -(s.h_upper - r)) +
                                        capsule_xml("upper_bl", r, -in, -(s.h_upper - r));
        xml += block_xml("upper", s.b, s.h_upper, s.m_upper, 2.0 * s.h_lower + s.h_upper, upper_extra, in);
    }
    xml += "</worldbody>\n<contact>\n";
    for (const char* geom : {"lower", "lower_br", "lower_bl"})
        xml += fmt::format("<pair geom1='ground' geom2='{}' condim='3' {} {}/>\n", geom, friction, contact);
    if (scene.vssw) {
        for (const char* pair : {"geom1='hinge_face' geom2='upper_br'", "geom1='hinge_face' geom2='upper_bl'",
                                 "geom1='lower_tr' geom2='upper_br'", "geom1='lower_tl' geom2='upper_bl'"})
            xml += fmt::format("<pair {} condim='3' {} {}/>\n", pair, hinge_friction, contact);
        xml += roller_pairs_xml(contact);
    }
    xml += "</contact>\n";
    return xml;
}

// The model for a scene and settings, as MuJoCo's XML, up to its contacts (scene_xml closes it).
std::string model_xml(const WallScene& scene, const Knobs& k, double dt) {
    const BlockSizes s = block_sizes(scene);
    const double tc = k.solref_steps * dt;
    const std::string contact = fmt::format("solref='{} {}' solimp='{} {} {} 0.5 2'", num(tc), num(k.dampratio),
                                            num(k.solimp_dmin), num(k.solimp_dmax), num(k.solimp_width));
    // A pair's friction overrides the geoms' mixing: the base's pair carries the base's, the hinge's the hinge's.
    auto friction_of = [](double mu) { return fmt::format("friction='{0} {0} 0.005 0.0001 0.0001'", num(mu)); };
    const std::string friction = friction_of(scene.base_mu()), hinge_friction = friction_of(scene.hinge_mu());
    std::string xml = fmt::format(
        "<mujoco model='vssw'>\n<compiler angle='radian' inertiafromgeom='false'/>\n"
        "<option timestep='{}' gravity='0 0 {}' integrator='{}' cone='pyramidal' impratio='1' "
        "noslip_iterations='{}' solver='Newton' iterations='{}' tolerance='{}'/>\n"
        "<default><geom contype='0' conaffinity='0'/></default>\n<worldbody>\n"
        "<geom name='ground' type='plane' size='100 100 1'/>\n",
        num(dt), num(-scene.gravity()), kIntegrators[k.integrator], k.noslip_iterations, k.iterations,
        num(k.tolerance));
    if (scene.corner_radius() > 0.0) return rounded_model_xml(scene, xml, friction, hinge_friction, contact);
    // The hinge's face: a box on the lower block whose top face is the block's, twice as wide, so that the upper
    // block's corner spheres always meet that face and never the box's sides.
    const std::string face = scene.vssw ? fmt::format("<geom name='hinge_face' type='box' size='{0} {1} {2}' pos='0 0 {3}'/>",
                                                      num(2.0 * s.b), num(0.5 * kDepth), num(s.b), num(s.h_lower - s.b))
                                        : std::string();
    xml += block_xml("lower", s.b, s.h_lower, s.m_lower, s.h_lower, face);
    if (scene.vssw) {
        xml += guides_xml(s);
        const std::string top = top_spheres_xml(s) +
                                fmt::format("<geom name='bottom_right' type='sphere' size='{0}' pos='{1} 0 {2}'/>"
                                            "<geom name='bottom_left' type='sphere' size='{0}' pos='{3} 0 {2}'/>",
                                            num(kHingeSphereRadius), num(s.b), num(-s.h_upper + kHingeSphereRadius),
                                            num(-s.b));
        xml += block_xml("upper", s.b, s.h_upper, s.m_upper, 2.0 * s.h_lower + s.h_upper, top);
    }
    xml += "</worldbody>\n<contact>\n";
    xml += fmt::format("<pair geom1='ground' geom2='lower' condim='3' {} {}/>\n", friction, contact);
    if (scene.vssw) {
        for (const char* corner : {"bottom_right", "bottom_left"})
            xml += fmt::format("<pair geom1='hinge_face' geom2='{}' condim='3' {} {}/>\n", corner, hinge_friction,
                               contact);
        xml += roller_pairs_xml(contact);
    }
    xml += "</contact>\n";
    return xml;
}

// The joints' positions at the release, in the model's order (each block's x, z, angle; the lower block first): the
// blocks placed by the kit (pose_at), their heights from their places at rest. An angle within rounding of zero is 0.
std::vector<double> release_qpos(const WallScene& scene, double theta0) {
    const BlockSizes s = block_sizes(scene);
    const WallPose pose = pose_at(scene, theta0);
    auto joints = [](const BlockPose& p, double z_rest) {
        return std::array<double, 3>{p.x, p.y - z_rest, std::abs(p.angle) < 1e-12 ? 0.0 : p.angle};
    };
    std::vector<double> q;
    for (double v : joints(pose.lower, s.h_lower)) q.push_back(v);
    if (scene.vssw)
        for (double v : joints(pose.upper, 2.0 * s.h_lower + s.h_upper)) q.push_back(v);
    return q;
}

// What a reader of the file needs and the file cannot hold: vssw applies the ground motion and N at every step.
std::string scene_comment(const WallScene& scene, const Excitation& ex) {
    const BlockSizes s = block_sizes(scene);
    return fmt::format(
        "<!-- The wall as vssw's MuJoCo adapter builds and steps it ({}). Units m, kg, s; depth {} m, so masses are "
        "per unit depth. vssw's plane (x, y) is MuJoCo's (x, z); a block's rotation is its hinge joint (lower_r, "
        "upper_r), positive tipping towards +x. Half-thickness b = {} m; the blocks' half-heights {} m (lower) and "
        "{} m (upper). The keyframe 'release' is the start: theta1 = {} rad. Not in the file, applied by vssw at every "
        "step: the ground motion a_h(t) as gravity's x component, -a_h at the step's midpoint (none in free "
        "vibration), and the overburden N = {} N on the top face, {} m from its centre towards +x (xfrc_applied). "
        "-->\n",
        scene.vssw ? "a VSSW: two blocks, the roller at the top" : "a parapet: one block", short_num(kDepth),
        short_num(s.b), short_num(s.h_lower), scene.vssw ? short_num(s.h_upper) : std::string("(none)"),
        short_num(ex.theta0), short_num(scene.overburden() * kDepth), short_num(scene.overburden_offset()));
}

// The whole text the run compiles and scene_file() gives: the comment, the model, and the release as the keyframe
// 'release', which the run starts from as a reader of the file would.
std::string scene_xml(const WallScene& scene, const Excitation& ex, const Knobs& k, double dt) {
    std::string qpos;
    for (double v : release_qpos(scene, ex.theta0)) qpos += (qpos.empty() ? "" : " ") + num(v);
    return scene_comment(scene, ex) + model_xml(scene, k, dt) +
           fmt::format("<keyframe><key name='release' time='0' qpos='{}'/></keyframe>\n</mujoco>\n", qpos);
}

// The checks a run and a scene file share, then the knobs: InputError on a bad scene, step or setting.
Knobs checked_knobs(const WallScene& scene, const EngineSettings& settings) {
    require_rigid_top(scene, "MuJoCo",
                      "a moving support needs a body whose velocity its contacts see, which "
                      "the adapter cannot build (as for moving_supports)");
    require(std::isfinite(settings.dt) && settings.dt > 0.0, "MuJoCo time step dt (s)", "a positive finite number",
            settings.dt);
    require_one_description(scene);
    return read_knobs(settings);
}

// mjModel and mjData of one run, freed with it.
struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
    void operator()(mjVFS* v) const {
        mj_deleteVFS(v);
        delete v;
    }
};

// Compiles the XML from memory: one file in a virtual file system (mjVFS is 2 MB of names: on the heap).
std::unique_ptr<mjModel, ModelDeleter> compile(const std::string& xml) {
    std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
    mj_defaultVFS(vfs.get());
    const char* file = "vssw_wall.xml";
    if (const int made = mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size())); made != 0)
        throw EngineFailure(fmt::format("MuJoCo: could not make the model's file in its virtual file system "
                                        "(mj_makeEmptyFileVFS returned {}: 1 full, 2 a name repeated)",
                                        made));
    const int index = mj_findFileVFS(vfs.get(), file);
    if (index < 0) throw EngineFailure("MuJoCo: the model's file is not in its virtual file system");
    std::memcpy(vfs->filedata[index], xml.data(), xml.size());
    std::array<char, 1024> error{};
    mjModel* m = mj_loadXML(file, vfs.get(), error.data(), static_cast<int>(error.size()));
    if (!m) throw EngineFailure(fmt::format("MuJoCo: the model did not compile: {}", error.data()));
    return std::unique_ptr<mjModel, ModelDeleter>(m);
}

struct Block {
    int q = -1;     // index of its slide-x joint's qpos (and qvel): x, z, angle follow
    int body = -1;  // body id
    double z_rest = 0.0, half_h = 0.0, mass = 0.0, inertia = 0.0;
};

class MujocoEngine final : public Engine {
public:
    MujocoEngine() { ensure_handlers(); }
    std::string name() const override { return "mujoco"; }
    std::string display_name() const override { return "MuJoCo"; }
    double cost_per_simulated_second() const override { return 7.5e-3; }  // at 1 ms, docs/contributing/engines.md "MuJoCo"
    std::string version() const override { return fmt::format("MuJoCo {}", mj_versionString()); }
    EngineSettings default_settings() const override {
        EngineSettings s;
        s.dt = 1e-3;  // docs/contributing/engines.md "MuJoCo": every target met at 1 ms, errors first order in the step
        s.iterations = kDefaultIterations;
        return s;
    }
    std::vector<SettingDescription> setting_descriptions() const override { return setting_table(); }
    Trajectory simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { (void)read_knobs(settings); }
    // Each run has its own mjModel and mjData; the process-wide state is the two handlers (set once, a warning's
    // text kept per thread) and the XML compiler's, which MuJoCo guards with its own lock.
    bool runs_concurrently() const override { return true; }
    // The text run() compiles (scene_xml), as MJCF.
    std::optional<SceneFile> scene_file(const WallScene& scene, const Excitation& ex,
                                        const EngineSettings& settings) const override {
        const Knobs knobs = checked_knobs(scene, settings);
        return SceneFile{"MJCF", ".xml", scene_xml(scene, ex, knobs, settings.dt)};
    }

private:
    Trajectory run(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const;
};

Trajectory MujocoEngine::simulate(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    try {
        return run(scene, ex, settings);
    } catch (const MujocoError& e) {
        throw EngineFailure(fmt::format("MuJoCo: {}", e.what()));
    }
}

// The stepping kit's hooks (step_loop.hpp) on one run's mjModel and mjData: the blocks' joints are the only degrees
// of freedom (no free joints), so qpos and qvel share their indices.
class MujocoStepping {
public:
    MujocoStepping(mjModel* m, mjData* d, const WallScene& scene, const Block& lower, const Block& upper)
        : m_(m),
          d_(d),
          energy_(scene, kDepth),
          N_(scene.overburden() * kDepth),
          vssw_(scene.vssw.has_value()),
          lower_(lower),
          upper_(upper),
          top_(vssw_ ? upper_ : lower_),
          load_x_(scene.overburden_offset()) {}

    // The ground motion as a uniform field.
    void drive(const GroundStep& g) { m_->opt.gravity[0] = -g.a_h; }
    // N on the top face (its centre, or load_x_ from it): the force at the centre of mass and its moment about it (about +y: r_z F_x -
    // r_x F_z with r the arm from the centre, F = (0, 0, -N)).
    void push_overburden() {
        const double arm_x = point_of(block_state(top_), load_x_, top_.half_h).x - centre_x(top_);
        double* f = d_->xfrc_applied + 6 * top_.body;
        f[2] = -N_;
        f[4] = arm_x * N_;
    }
    void step(const StepTimes&, const GroundStep&) { mj_step(m_, d_); }
    // A MuJoCo warning (its counters, the text from the handler) fails the run.
    void check_step(double t) const {
        for (int w = 0; w < mjNWARNING; ++w)
            if (d_->warning[w].number > 0)
                throw EngineFailure(fmt::format("MuJoCo warned at t = {:.6g} s: {}", t,
                                                t_last_warning.empty() ? std::string("(no text)") : t_last_warning));
    }
    WallState state(const GroundStep&) const { return {block_state(lower_), vssw_ ? block_state(upper_) : kNoBlock}; }
    Rocking rocking() const { return {angle(lower_), d_->qvel[lower_.q + 2]}; }
    void fill(TrajectorySample& p) const {
        p.theta2 = vssw_ ? angle(upper_) : 0.0;
        auto kinetic = [&](const Block& k) {
            return block_kinetic_energy(k.mass, k.inertia, d_->qvel[k.q], d_->qvel[k.q + 1], d_->qvel[k.q + 2]);
        };
        energy_.fill(p, {kinetic(lower_), vssw_ ? kinetic(upper_) : 0.0, centre_y(lower_),
                         vssw_ ? centre_y(upper_) : 0.0, point_of(block_state(top_), load_x_, top_.half_h).y});
        p.contacts = d_->ncon;
    }

private:
    double centre_x(const Block& k) const { return d_->qpos[k.q]; }
    double centre_y(const Block& k) const { return k.z_rest + d_->qpos[k.q + 1]; }
    double angle(const Block& k) const { return d_->qpos[k.q + 2]; }
    BlockState block_state(const Block& k) const {
        return BlockState{centre_x(k), centre_y(k), angle(k), d_->qvel[k.q], d_->qvel[k.q + 1], d_->qvel[k.q + 2]};
    }

    mjModel* m_;
    mjData* d_;
    WallEnergy energy_;
    double N_;
    bool vssw_;
    const Block& lower_;
    const Block& upper_;
    const Block& top_;
    double load_x_;  // N's point on the top face from its centre, toward theta1 > 0 [m]
};

Trajectory MujocoEngine::run(const WallScene& scene, const Excitation& ex, const EngineSettings& settings) const {
    const Knobs knobs = checked_knobs(scene, settings);
    const double dt = settings.dt;
    const BlockSizes s = block_sizes(scene);
    const auto model = compile(scene_xml(scene, ex, knobs, dt));
    mjModel* m = model.get();
    const std::unique_ptr<mjData, DataDeleter> data(mj_makeData(m));
    mjData* d = data.get();
    if (!d) throw EngineFailure("MuJoCo: mj_makeData failed");

    auto block = [&](const char* name, double z_rest, double half_h) {
        Block k;
        k.body = mj_name2id(m, mjOBJ_BODY, name);
        const std::string joint = std::string(name) + "_x";
        const int joint_id = mj_name2id(m, mjOBJ_JOINT, joint.c_str());
        if (k.body < 0 || joint_id < 0)  // the scene's text and this reader disagree: a bug, not a run's failure
            throw EngineFailure(fmt::format("MuJoCo: the compiled model has no body '{}' or joint '{}'", name, joint));
        k.q = m->jnt_qposadr[joint_id];
        k.z_rest = z_rest;
        k.half_h = half_h;
        // As the compiled model holds them (block_xml's inertial: the rectangle's mass and its inertia about y), so
        // that the sample's kinetic energy is of the bodies MuJoCo steps.
        k.mass = m->body_mass[k.body];
        k.inertia = m->body_inertia[3 * k.body + 1];
        return k;
    };
    const Block lower = block("lower", s.h_lower, s.h_lower);
    const bool vssw = scene.vssw.has_value();
    const Block upper = vssw ? block("upper", 2.0 * s.h_lower + s.h_upper, s.h_upper) : Block{};
    // The release is the file's keyframe 'release' (17 digits: the positions release_qpos computed, to the bit).
    mj_resetDataKeyframe(m, d, 0);

    MujocoStepping stepping(m, d, scene, lower, upper);
    RunMonitor monitor("MuJoCo", scene, ex, dt, knobs.limits);
    t_last_warning.clear();
    // No moving supports: MuJoCo's planes must be static (see the top of the file).
    const StepLoop loop{dt, sample_every(settings, dt), false, scene.overburden() > 0.0};
    return run_fixed_steps(stepping, ex, loop, monitor);
}

}  // namespace

std::unique_ptr<Engine> make_mujoco_engine() { return std::make_unique<MujocoEngine>(); }

}  // namespace vssw::multibody

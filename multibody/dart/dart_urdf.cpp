// The wall's blocks as URDF and back (dart_urdf.hpp). Numbers are written with 17 significant digits, which urdfdom
// reads back to the same double: the loaded blocks are the ones the adapter built through DART's calls, bit for bit.
#include "multibody/dart/dart_urdf.hpp"

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

#include <iostream>
#include <sstream>
#include <streambuf>

#include <fmt/format.h>

#include "multibody/kit/scene_geometry.hpp"

namespace vssw::multibody {
namespace {

std::string num(double v) { return fmt::format("{:.17g}", v); }
std::string short_num(double v) { return fmt::format("{:.6g}", v); }  // for the reader of the comment

// A block's link and its planar joint. The inertia is the whole rectangle's (2b x 2h x depth), also for rounded
// corners, whose box is only the flat part; DART's own box formula, as the adapter used before it read URDF.
std::string block_urdf(const std::string& name, double b, double half_h, double mass_per_depth, double box_b) {
    const double m = mass_per_depth * kDartDepth;
    const Eigen::Matrix3d I =
        dart::dynamics::BoxShape::computeInertia(Eigen::Vector3d(2.0 * b, 2.0 * half_h, kDartDepth), m);
    return fmt::format(
        "  <link name='{0}'>\n"
        "    <inertial><origin xyz='0 0 0' rpy='0 0 0'/><mass value='{1}'/>"
        "<inertia ixx='{2}' ixy='0' ixz='0' iyy='{3}' iyz='0' izz='{4}'/></inertial>\n"
        "    <collision name='{0}_box'><origin xyz='0 0 0' rpy='0 0 0'/>"
        "<geometry><box size='{5} {6} {7}'/></geometry></collision>\n"
        "  </link>\n"
        "  <joint name='{0}_plane' type='planar'><parent link='world'/><child link='{0}'/>"
        "<axis xyz='0 0 1'/></joint>\n",
        name, num(m), num(I(0, 0)), num(I(1, 1)), num(I(2, 2)), num(2.0 * box_b), num(2.0 * half_h), num(kDartDepth));
}

// What a reader needs and URDF cannot hold: vssw adds it in code, as for every other engine.
std::string urdf_comment(const WallScene& scene, double theta0) {
    const BlockSizes s = block_sizes(scene);
    const WallPose p = pose_at(scene, theta0);
    auto q = [](const BlockPose& b) {
        return fmt::format("({}, {}, {})", short_num(b.x), short_num(b.y), short_num(-b.angle));
    };
    return fmt::format(
        "<!-- The wall's blocks as vssw's DART adapter loads them with DART's URDF loader ({}). Units m, kg, s; depth "
        "{} m, so masses are per unit depth. Each block is a skeleton of its own on DART's PlanarJoint in its XY "
        "plane, q = (x, y, counter-clockwise angle); vssw's plane is (x, y), y up. Half-thickness b = {} m; the "
        "blocks' half-heights {} m (lower) and {} m (upper); corner radius {} m. Not in the file, added by vssw: the "
        "release, theta1 = {} rad, q = {} (lower){}; the ground (a box whose top face is y = 0, welded, or slid along "
        "x with moving_supports = 1); the roller's spheres and guides; the rounded corners' capsules (URDF has no "
        "capsule); each box's friction (base {}, hinge {}) and restitution 0; the contacts' pairs; the ground motion "
        "and the overburden N = {} N on the top face, at every step. -->\n",
        scene.vssw ? "a VSSW: two blocks" : "a parapet: one block", short_num(kDartDepth), short_num(s.b),
        short_num(s.h_lower), scene.vssw ? short_num(s.h_upper) : std::string("(none)"),
        short_num(scene.corner_radius()), short_num(theta0), q(p.lower),
        scene.vssw ? fmt::format(" and {} (upper)", q(p.upper)) : std::string(), short_num(scene.base_mu()),
        scene.vssw ? short_num(scene.hinge_mu()) : std::string("(none)"), short_num(scene.overburden() * kDartDepth));
}

// Holds std::cout's and std::cerr's text while DART's loader runs: it prints a warning for the two trees under
// "world" and a note on its joints' names on every load, which would land in vssw's own output. The text is given
// back for a failure's message.
class HeldOutput {
public:
    HeldOutput() : out_(std::cout.rdbuf(held_.rdbuf())), err_(std::cerr.rdbuf(held_.rdbuf())) {}
    ~HeldOutput() {
        std::cout.rdbuf(out_);
        std::cerr.rdbuf(err_);
    }
    HeldOutput(const HeldOutput&) = delete;
    HeldOutput& operator=(const HeldOutput&) = delete;
    std::string text() const { return held_.str(); }

private:
    std::ostringstream held_;
    std::streambuf* out_;
    std::streambuf* err_;
};

}  // namespace

std::string wall_urdf(const WallScene& scene, double theta0) {
    const BlockSizes s = block_sizes(scene);
    const double box_b = s.b - scene.corner_radius();
    std::string text = "<?xml version='1.0'?>\n" + urdf_comment(scene, theta0) + "<robot name='vssw_wall'>\n" +
                       "  <link name='world'/>\n" + block_urdf("lower", s.b, s.h_lower, s.m_lower, box_b);
    if (scene.vssw) text += block_urdf("upper", s.b, s.h_upper, s.m_upper, box_b);
    return text + "</robot>\n";
}

UrdfBlocks load_wall_urdf(const std::string& text, bool vssw) {
    HeldOutput held;
    dart::utils::DartLoader loader;
    const dart::dynamics::SkeletonPtr wall = loader.parseSkeletonString(text, dart::common::Uri());
    auto block = [&](const char* name) -> dart::dynamics::SkeletonPtr {
        dart::dynamics::BodyNode* body = wall ? wall->getBodyNode(name) : nullptr;
        return body ? body->split(name) : nullptr;
    };
    UrdfBlocks blocks{block("lower"), block("upper")};
    if (!blocks.lower)
        throw EngineFailure(fmt::format("DART: its URDF loader did not give the wall's lower block: {}", held.text()));
    if (vssw && !blocks.upper)
        throw EngineFailure(fmt::format("DART: its URDF loader did not give the wall's upper block: {}", held.text()));
    return blocks;
}

}  // namespace vssw::multibody

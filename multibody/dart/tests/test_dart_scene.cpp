// The DART scene `vssw scene --engine dart` writes (Engine::scene_file: the URDF the adapter loads its blocks from),
// loaded back from the file by DART's own URDF loader: the blocks it holds are the wall asked for. A program of its
// own, since it links DART and its URDF loader (multibody/dart/engine.cmake); it is built only when DART is.
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/PlanarJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "multibody/engine.hpp"
#include "tests/temp_files.hpp"

namespace vssw {
namespace {

namespace dd = dart::dynamics;
using multibody::WallScene;

// Numbers written with 17 significant digits and read back: exact to a few units of rounding on the products below.
constexpr double kRoundTrip = 1e-12;
constexpr double kDepth = 1.0;  // [m] the scene's depth (masses per unit depth)

// The wall of Fig. 6 as typed: full height 4 m, thickness 0.4 m, hinge 0.7 (blocks 2.8 m and 1.2 m); sharp corners.
struct WallAsTyped {
    double height = 4.0, thickness = 0.4, hinge = 0.7;
    double corner_share = 0.0;  // r / b
    bool parapet = false;
};

WallScene scene_of(const WallAsTyped& w) {
    return w.parapet ? WallScene::of(with_corner_radius(make_parapet(w.height, w.thickness), w.corner_share))
                     : WallScene::of(with_corner_radius(make_vssw(w.height, w.thickness, w.hinge), w.corner_share));
}

double density_of(const WallAsTyped& w) {
    const WallScene scene = scene_of(w);
    return scene.vssw ? scene.vssw->density : scene.parapet->density;
}

// The scene for `w` released at 0.5 alpha1, as `vssw scene` writes it.
std::string exported_text(const WallAsTyped& w) {
    const auto engine = multibody::make_engine("dart");
    const WallScene scene = scene_of(w);
    multibody::Excitation ex;
    ex.theta0 = 0.5 * scene.alpha();
    const std::optional<multibody::SceneFile> file = engine->scene_file(scene, ex, engine->default_settings());
    if (!file) throw std::runtime_error("DART gave no scene file");
    EXPECT_EQ(file->format, "URDF");
    EXPECT_EQ(file->extension, ".urdf");
    return file->text;
}

// A URDF text written to a file and loaded by DART's URDF loader.
dd::SkeletonPtr loaded(const std::string& text, const testing::TempDir& dir) {
    const std::string path = (dir / "wall.urdf").string();
    std::ofstream(path) << text;
    dd::SkeletonPtr skeleton = dart::utils::DartLoader().parseSkeleton("file://" + path);
    if (!skeleton) throw std::runtime_error("DART's URDF loader did not load " + path);
    return skeleton;
}

dd::SkeletonPtr exported_blocks(const WallAsTyped& w, const testing::TempDir& dir) {
    return loaded(exported_text(w), dir);
}

// What the wall as typed requires of one block (its height h, its place from the ground y0), one line per property it
// breaks: its mass rho 2b h depth, its inertia the whole rectangle's, its box (2(b - r), h, depth) at its centre, and
// its planar joint in the XY plane from the world.
void check_block(const dd::Skeleton& s, const char* name, double b, double h, double density, double r,
                 std::vector<std::string>& bad) {
    auto near = [](double a, double x) { return std::abs(a - x) <= kRoundTrip * std::max(1.0, std::abs(x)); };
    auto check = [&](bool holds, const std::string& what) {
        if (!holds) bad.push_back(std::string(name) + ": " + what);
    };
    const dd::BodyNode* body = s.getBodyNode(name);
    if (!body) return check(false, "no such link");
    const double m = density * 2.0 * b * h * kDepth;
    check(near(body->getMass(), m), "mass rho 2b h depth");
    check(near(body->getInertia().getMoment()(2, 2), m * (4.0 * b * b + h * h) / 12.0), "inertia m (4b^2 + h^2) / 12");
    const auto* joint = dynamic_cast<const dd::PlanarJoint*>(body->getParentJoint());
    check(joint && joint->getPlaneType() == dd::PlanarJoint::PlaneType::XY && !body->getParentBodyNode(),
          "planar joint in the XY plane from the world");
    const dd::ShapeNode* node = body->getNumShapeNodes() == 1 ? body->getShapeNode(0) : nullptr;
    const auto* box = node ? dynamic_cast<const dd::BoxShape*>(node->getShape().get()) : nullptr;
    if (!box) return check(false, "one box");
    check(near(box->getSize().x(), 2.0 * (b - r)), "box width 2(b - r)");
    check(near(box->getSize().y(), h), "box height h");
    check(near(box->getSize().z(), kDepth), "box depth");
    check(node->getRelativeTransform().isApprox(Eigen::Isometry3d::Identity()), "box at the body's centre");
}

std::vector<std::string> mismatches(const dd::Skeleton& s, const WallAsTyped& w) {
    std::vector<std::string> bad;
    const double b = 0.5 * w.thickness, r = w.corner_share * b, density = density_of(w);
    const double lower_h = w.parapet ? w.height : w.hinge * w.height;
    check_block(s, "lower", b, lower_h, density, r, bad);
    if (!w.parapet) check_block(s, "upper", b, w.height - lower_h, density, r, bad);
    if (s.getNumBodyNodes() != (w.parapet ? 1u : 2u)) bad.push_back("the number of blocks");
    return bad;
}

TEST(dart_scene, TheFileDartLoadsHoldsTheWallAsTyped) {
    const testing::TempDir dir;
    const WallAsTyped parapet{0.9, 0.11, 0.0, 0.0, true}, rounded{4.0, 0.4, 0.7, 0.2};
    for (const WallAsTyped& w : {WallAsTyped{}, parapet, rounded}) {
        const dd::SkeletonPtr s = exported_blocks(w, dir);
        EXPECT_TRUE(mismatches(*s, w).empty()) << ::testing::PrintToString(mismatches(*s, w));
    }
}

// The check above can fail: another wall's file (another hinge and thickness, rounded corners, a parapet) against
// the Fig. 6 wall.
TEST(dart_scene, AnotherWallsFileFailsTheCheck) {
    const testing::TempDir dir;
    const WallAsTyped w;
    auto bad_for = [&](const WallAsTyped& other) { return mismatches(*exported_blocks(other, dir), w); };
    auto has = [](const std::vector<std::string>& bad, const std::string& what) {
        return std::find(bad.begin(), bad.end(), what) != bad.end();
    };
    const std::vector<std::string> hinge = bad_for(WallAsTyped{4.0, 0.4, 0.6});
    for (const char* what : {"lower: mass rho 2b h depth", "lower: box height h", "upper: inertia m (4b^2 + h^2) / 12"})
        EXPECT_TRUE(has(hinge, what)) << what;
    EXPECT_TRUE(has(bad_for(WallAsTyped{4.0, 0.3, 0.7}), "upper: box width 2(b - r)"));
    EXPECT_TRUE(has(bad_for(WallAsTyped{4.0, 0.4, 0.7, 0.2}), "lower: box width 2(b - r)"));
    EXPECT_TRUE(has(bad_for(WallAsTyped{4.0, 0.4, 0.7, 0.0, true}), "upper: no such link"));
}

// The joint and the box checks can fail too: the Fig. 6 wall's file with the lower block on a floating joint, and its
// box deeper and off its centre.
TEST(dart_scene, AnAlteredFileFailsTheCheck) {
    const testing::TempDir dir;
    const WallAsTyped w;
    std::string text = exported_text(w);
    auto replace_first = [&](const std::string& from, const std::string& to) {
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace_first("type='planar'", "type='floating'");
    replace_first("<collision name='lower_box'><origin xyz='0 0 0'",
                  "<collision name='lower_box'><origin xyz='0 0.1 0'");
    replace_first(" 1'/></geometry>", " 2'/></geometry>");
    const std::vector<std::string> bad = mismatches(*loaded(text, dir), w);
    for (const char* what : {"lower: planar joint in the XY plane from the world", "lower: box at the body's centre",
                             "lower: box depth"})
        EXPECT_NE(std::find(bad.begin(), bad.end(), what), bad.end()) << what;
}

// A bad step is refused as a run refuses it, before any file is written.
TEST(dart_scene, ABadStepIsRefused) {
    const auto engine = multibody::make_engine("dart");
    multibody::EngineSettings s = engine->default_settings();
    s.dt = -1.0;
    EXPECT_THROW((void)engine->scene_file(scene_of(WallAsTyped{}), multibody::Excitation{}, s), InputError);
}

}  // namespace
}  // namespace vssw

// The MuJoCo scene `vssw scene` writes (Engine::scene_file: the text the adapter compiles for its runs), loaded back by
// MuJoCo's own parser (mj_loadXML from the file): the wall it holds is the one asked for, and the reloaded model,
// stepped by MuJoCo alone, runs as the harness's run of that wall. A program of its own, since it links MuJoCo
// (multibody/mujoco/engine.cmake); it is built only when MuJoCo is.
#include <mujoco/mujoco.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analytic/wall.hpp"
#include "compare/experiments.hpp"
#include "compare/targets.hpp"
#include "multibody/engine.hpp"
#include "tests/temp_files.hpp"

namespace vssw {
namespace {

using multibody::WallScene;

// Numbers written with 17 significant digits and read back: exact to a few units of rounding on the products below.
constexpr double kRoundTrip = 1e-12;
// The reloaded model is the harness's model stepped from the harness's start: the rotations differ by rounding at
// most (they were equal to the bit when measured; the ground motion is absent in both, -0 against +0 in gravity's x).
constexpr double kSameRun = 1e-12;  // [rad]

// The wall of Fig. 6 as typed: full height 4 m, thickness 0.4 m, hinge 0.7 (blocks 2.8 m and 1.2 m).
struct WallAsTyped {
    double height = 4.0, thickness = 0.4, hinge = 0.7;
    double friction = 0.8, hinge_friction = 0.6;  // distinct, so that each pair's own is checked
    double dampratio = 0.5;                       // the contacts' damping ratio, MuJoCo's say in the impact's loss
};

WallScene scene_of(const WallAsTyped& w) {
    WallScene scene = WallScene::of(make_vssw(w.height, w.thickness, w.hinge));
    scene.friction = w.friction;
    scene.hinge_friction = w.hinge_friction;
    return scene;
}

multibody::EngineSettings settings_of(const multibody::Engine& engine, const WallAsTyped& w) {
    multibody::EngineSettings s = engine.default_settings();
    s.knobs["dampratio"] = w.dampratio;
    return s;
}

struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using Model = std::unique_ptr<mjModel, ModelDeleter>;

// The scene for `w` released at r alpha1, written to a file and loaded by MuJoCo's parser.
Model exported_model(const WallAsTyped& w, double r, const testing::TempDir& dir) {
    const auto engine = multibody::make_engine("mujoco");
    const WallScene scene = scene_of(w);
    multibody::Excitation ex;
    ex.theta0 = r * scene.alpha();
    const std::optional<multibody::SceneFile> file = engine->scene_file(scene, ex, settings_of(*engine, w));
    if (!file) throw std::runtime_error("MuJoCo gave no scene file");
    EXPECT_EQ(file->format, "MJCF");
    const std::string path = (dir / ("wall" + file->extension)).string();
    std::ofstream(path) << file->text;
    std::array<char, 1024> error{};
    mjModel* m = mj_loadXML(path.c_str(), nullptr, error.data(), static_cast<int>(error.size()));
    if (!m) throw std::runtime_error(std::string("mj_loadXML: ") + error.data());
    return Model(m);
}

int id_of(const mjModel* m, mjtObj type, const char* name) {
    const int id = mj_name2id(m, type, name);
    if (id < 0) throw std::runtime_error(std::string("no ") + name + " in the model");
    return id;
}
// A geom's centre height in the world at rest (its body's place plus its own offset) [m].
double rest_z(const mjModel* m, int geom) { return m->body_pos[3 * m->geom_bodyid[geom] + 2] + m->geom_pos[3 * geom + 2]; }
double rest_x(const mjModel* m, int geom) { return m->body_pos[3 * m->geom_bodyid[geom]] + m->geom_pos[3 * geom]; }

// The contact pair of two geoms (either order).
int pair_of(const mjModel* m, int g1, int g2) {
    for (int p = 0; p < m->npair; ++p)
        if ((m->pair_geom1[p] == g1 && m->pair_geom2[p] == g2) || (m->pair_geom1[p] == g2 && m->pair_geom2[p] == g1))
            return p;
    throw std::runtime_error("no such contact pair");
}

// What the wall as typed requires of the model, one line per property it breaks (empty: it holds the wall).
std::vector<std::string> mismatches(const mjModel* m, const WallAsTyped& w, double density, double dt) {
    std::vector<std::string> bad;
    auto check = [&](bool holds, const std::string& what) {
        if (!holds) bad.push_back(what);
    };
    auto near = [](double a, double b) { return std::abs(a - b) <= kRoundTrip * std::max(1.0, std::abs(b)); };
    const double b = 0.5 * w.thickness, lower_h = w.hinge * w.height, upper_h = w.height - lower_h;
    constexpr double kDepth = 1.0;  // [m] the scene's depth (masses per unit depth)
    const int lower = id_of(m, mjOBJ_BODY, "lower"), upper = id_of(m, mjOBJ_BODY, "upper");
    check(near(m->body_mass[lower], density * 2.0 * b * lower_h * kDepth), "lower block's mass rho 2b h1 depth");
    check(near(m->body_mass[upper], density * 2.0 * b * upper_h * kDepth), "upper block's mass rho 2b h2 depth");
    const int lower_box = id_of(m, mjOBJ_GEOM, "lower"), upper_box = id_of(m, mjOBJ_GEOM, "upper");
    check(near(m->geom_size[3 * lower_box], b) && near(m->geom_size[3 * upper_box], b), "blocks' half-thickness b");
    check(near(2.0 * m->geom_size[3 * lower_box + 2], lower_h) && near(2.0 * m->geom_size[3 * upper_box + 2], upper_h),
          "blocks' heights");
    check(near(rest_z(m, lower_box), 0.5 * lower_h) && near(rest_z(m, upper_box), lower_h + 0.5 * upper_h),
          "blocks stacked from the ground");
    // The hinge at h1: the lower block's face the upper block's corners stand on, and those corners' lowest points.
    const int face = id_of(m, mjOBJ_GEOM, "hinge_face"), corner = id_of(m, mjOBJ_GEOM, "bottom_right");
    check(near(rest_z(m, face) + m->geom_size[3 * face + 2], lower_h), "hinge face at h1");
    check(near(rest_z(m, corner) - m->geom_size[3 * corner], lower_h) && near(rest_x(m, corner), b),
          "upper block's corner on the hinge at (b, h1)");
    // The roller at the top: the top corners' outer points on guides at x = +b and x = -b.
    const int guide = id_of(m, mjOBJ_GEOM, "guide_right"), top = id_of(m, mjOBJ_GEOM, "top_right");
    check(near(rest_x(m, guide), b) && near(rest_x(m, top) + m->geom_size[3 * top], b) &&
              near(rest_z(m, top), w.height),
          "roller at the top corner (b, h)");
    check(near(rest_x(m, id_of(m, mjOBJ_GEOM, "guide_left")), -b), "left guide at x = -b");
    // The contacts as set: each pair's friction and the damping ratio (solref's second number).
    const int base = pair_of(m, id_of(m, mjOBJ_GEOM, "ground"), lower_box), hinge = pair_of(m, face, corner);
    check(near(m->pair_friction[5 * base], w.friction), "base friction");
    check(near(m->pair_friction[5 * hinge], w.hinge_friction), "hinge friction");
    check(near(m->pair_solref[mjNREF * base + 1], w.dampratio) && near(m->pair_solref[mjNREF * hinge + 1], w.dampratio),
          "contacts' damping ratio");
    check(near(m->opt.timestep, dt), "step");
    return bad;
}

TEST(mujoco_scene, TheFileMujocoLoadsHoldsTheWallAsTyped) {
    const testing::TempDir dir;
    const WallAsTyped w;
    const Model m = exported_model(w, 0.5, dir);
    const double density = scene_of(w).vssw->density, dt = multibody::make_engine("mujoco")->default_settings().dt;
    EXPECT_TRUE(mismatches(m.get(), w, density, dt).empty())
        << ::testing::PrintToString(mismatches(m.get(), w, density, dt));
    // The release: the keyframe's lower_r is theta1,0.
    ASSERT_EQ(m->nkey, 1);
    EXPECT_NEAR(m->key_qpos[m->jnt_qposadr[id_of(m.get(), mjOBJ_JOINT, "lower_r")]], 0.5 * scene_of(w).alpha(),
                kRoundTrip);
}

// The check above can fail: another wall's scene (another hinge, other friction and damping) against this one.
TEST(mujoco_scene, AnotherWallsFileFailsTheCheck) {
    const testing::TempDir dir;
    WallAsTyped other;
    other.hinge = 0.6;
    other.friction = 0.5;
    other.dampratio = 1.0;
    const Model m = exported_model(other, 0.5, dir);
    const WallAsTyped w;
    const std::vector<std::string> bad =
        mismatches(m.get(), w, scene_of(w).vssw->density, multibody::make_engine("mujoco")->default_settings().dt);
    for (const char* what : {"lower block's mass rho 2b h1 depth", "blocks' heights", "hinge face at h1",
                             "base friction", "contacts' damping ratio"})
        EXPECT_NE(std::find(bad.begin(), bad.end(), what), bad.end()) << what;
}

// The reloaded model stepped by MuJoCo from its keyframe: theta1 step by step as the harness's run, and its quarter
// period the analytic model's within the period target.
TEST(mujoco_scene, TheReloadedModelRunsAsTheHarness) {
    const testing::TempDir dir;
    const WallAsTyped w;
    constexpr double r = 0.5;
    const Model m = exported_model(w, r, dir);
    const std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
    mj_resetDataKeyframe(m.get(), d.get(), 0);

    const auto engine = multibody::make_engine("mujoco");
    const WallScene scene = scene_of(w);
    multibody::EngineSettings s = settings_of(*engine, w);
    s.sample_dt = 0.0;  // every step
    multibody::Excitation ex;
    ex.theta0 = r * scene.alpha();
    ex.t_end = 1.0;
    ex.stop_at_rest = false;
    const multibody::Trajectory harness = engine->simulate(scene, ex, s);
    ASSERT_GT(harness.samples.size(), 100u);

    const int q = m->jnt_qposadr[id_of(m.get(), mjOBJ_JOINT, "lower_r")];
    std::optional<double> first_impact;
    double largest_difference = 0.0, previous = d->qpos[q];
    for (std::size_t i = 1; i < harness.samples.size(); ++i) {
        mj_step(m.get(), d.get());
        const double theta1 = d->qpos[q];
        ASSERT_NEAR(d->time, harness.samples[i].t, kRoundTrip);
        largest_difference = std::max(largest_difference, std::abs(theta1 - harness.samples[i].theta1));
        if (!first_impact && previous > 0.0 && theta1 <= 0.0)  // linear between the two steps
            first_impact = d->time - m->opt.timestep * theta1 / (theta1 - previous);
        previous = theta1;
    }
    EXPECT_LE(largest_difference, kSameRun);
    ASSERT_TRUE(first_impact);
    // The analytic model's quarter period, from its own run (compare/: the harness's reference).
    compare::FreeVibrationOptions free;
    free.r = r;
    const compare::FreeVibrationResult analytic = compare::run_free_vibration(
        *multibody::make_engine("analytic"), compare::analytic_reference_settings(), scene, free);
    ASSERT_TRUE(analytic.quarter_period);
    EXPECT_NEAR(*first_impact / *analytic.quarter_period - 1.0, 0.0, compare::kPeriodTarget);
}

}  // namespace
}  // namespace vssw

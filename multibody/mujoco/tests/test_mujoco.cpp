// MuJoCo's own tests (multibody/mujoco/mujoco_engine.cpp), registered by multibody/mujoco/engine.cmake and built into
// vssw_engine_tests (tests/CMakeLists.txt). Each skips without MuJoCo in the build.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "compare/experiments.hpp"
#include "compare/targets.hpp"
#include "multibody/engine.hpp"
#include "tests/engine_available.hpp"
#include "tests/engine_scenes.hpp"
#include "tests/refused_knobs.hpp"

namespace vssw {
namespace {

using multibody::EngineFailure;
using multibody::WallScene;
using compare::kRestitutionTarget;  // the project's target (compare/targets.hpp)
using testing::engine_available;
using testing::fig6_parapet;  // the wall of Fig. 6 (4 m x 0.4 m, hinge 0.7) and its parapet
using testing::fig6_vssw;


// MuJoCo (multibody/mujoco/mujoco_engine.cpp): its contacts are soft. At MuJoCo's own defaults (solref 0.02 s,
// solimp 0.9/0.95) the parapet's impact loses 5.5 % too much energy (restitution from the amplitudes either side);
// with the time constant at 2 dt and the impedance near 1 (the adapter's defaults) it is Housner's. Suite named in
// lower case for `ctest -R mujoco`.
double mujoco_amplitude_restitution(const multibody::Engine& engine, const multibody::EngineSettings& s) {
    const WallScene scene = fig6_parapet();
    const compare::FreeVibrationResult r = compare::run_free_vibration(engine, s, scene);
    if (r.amplitude.empty()) return NAN;
    return r.amplitude.front().energy / housner_restitution(scene.parapet->alpha) - 1.0;
}

TEST(mujoco, StiffContactGivesHousnersImpactWhereMujocosDefaultContactDoesNot) {
    if (!engine_available("mujoco")) GTEST_SKIP() << "MuJoCo is not compiled in";
    const auto engine = multibody::make_engine("mujoco");
    multibody::EngineSettings s = engine->default_settings();
    EXPECT_NEAR(mujoco_amplitude_restitution(*engine, s), 0.0, kRestitutionTarget);
    s.knobs["solref_steps"] = 0.02 / s.dt;  // MuJoCo's default time constant, 0.02 s
    s.knobs["solimp_dmin"] = 0.9;
    s.knobs["solimp_dmax"] = 0.95;
    constexpr double kDefaultContactLoss = -0.04;  // measured -5.5 % (docs/contributing/engines.md "MuJoCo"); beyond the target
    EXPECT_LT(mujoco_amplitude_restitution(*engine, s), kDefaultContactLoss);
}

TEST(mujoco, SettingsOutsideTheirRangesAreRefusedByName) {
    if (!engine_available("mujoco")) GTEST_SKIP() << "MuJoCo is not compiled in";
    const auto engine = multibody::make_engine("mujoco");
    vssw::testing::expect_knobs_refused_by_name(
        *engine,
        {{"solref_steps", 1.0}, {"solimp_dmax", 1.0}, {"integrator", 3.0}, {"tolerance", 0.0}, {"moving_supports", 1.0}});
}

// The sweep's MuJoCo settings: solimp_dmin at the low end of its documented range
// lets the upper block fall through the lower one (the top 33 m down). The run fails naming the hinge, in free
// vibration and under the pulse P, instead of giving a threshold 57 % low and "ok".
TEST(mujoco, AnUpperBlockFallingThroughTheHingeFailsTheRun) {
    if (!engine_available("mujoco")) GTEST_SKIP() << "MuJoCo is not compiled in";
    const auto engine = multibody::make_engine("mujoco");
    multibody::EngineSettings s = engine->default_settings();
    s.knobs["solimp_dmin"] = 1e-4;
    multibody::Excitation free;
    free.theta0 = 0.5 * fig6_vssw().alpha();
    free.t_end = 3.0;
    multibody::Excitation pulse;
    pulse.horizontal = sine_pulse(0.5 * 9.81, 0.5);
    pulse.t_end = 3.0;
    for (const multibody::Excitation& ex : {free, pulse}) {
        try {
            (void)engine->simulate(fig6_vssw(), ex, s);
            ADD_FAILURE() << "the run went on";
        } catch (const EngineFailure& e) {
            EXPECT_NE(std::string(e.what()).find("through the hinge"), std::string::npos) << e.what();
        }
    }
}

// MuJoCo answers a bad acceleration with a warning and resets the simulation to its start, then goes on: the
// adapter fails the run instead, naming MuJoCo's warning.
TEST(mujoco, AWarningOfMujocoFailsTheRunWithItsText) {
    if (!engine_available("mujoco")) GTEST_SKIP() << "MuJoCo is not compiled in";
    const auto engine = multibody::make_engine("mujoco");
    multibody::Excitation ex;
    ex.horizontal = constant_motion(1e30, 1.0);  // qacc far past MuJoCo's mjMAXVAL (1e10)
    ex.t_end = 0.1;
    try {
        engine->simulate(fig6_vssw(), ex, engine->default_settings());
        ADD_FAILURE() << "the run went on";
    } catch (const EngineFailure& e) {
        EXPECT_NE(std::string(e.what()).find("MuJoCo warned"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vssw

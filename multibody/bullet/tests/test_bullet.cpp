// Bullet's own tests (multibody/bullet/bullet_engine.cpp): its restitution on the walls and steps where it once
// missed, and the overburden as an impulse off the roller. Registered by multibody/bullet/engine.cmake and built into
// vssw_engine_tests (tests/CMakeLists.txt); each skips without Bullet in the build.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analytic/closed_forms.hpp"
#include "compare/experiments.hpp"
#include "compare/targets.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "tests/engine_available.hpp"
#include "tests/engine_scenes.hpp"
#include "tests/table1.hpp"

namespace vssw {
namespace {

using multibody::WallScene;
using testing::engine_available;
using testing::expect_whole_mechanism_restitution;
using testing::fig6_vssw;
using testing::table1;

// Bullet's restitution once missed the whole-mechanism impact by 5-6 % on the Table 1 walls at xi 0.5 and did not
// settle as the step fell on Fig. 6 (+0.2, -2.3, -2.3, -0.4 % at 1, 0.5, 0.2, 0.1 ms): contacts found a step late and
// pushed out through the velocity (docs/contributing/engines.md "Bullet"). Held here on those walls and steps.
TEST(BulletRestitution, Table1WallsUnderHeavyOverburdenTakeTheWholeMechanismImpact) {
    if (!engine_available("bullet")) GTEST_SKIP() << "Bullet is not compiled in";
    const auto engine = multibody::make_engine("bullet");
    for (int number : {1, 14, 15}) {
        SCOPED_TRACE("Table 1 #" + std::to_string(number) + ", xi 0.5");
        expect_whole_mechanism_restitution(*engine, engine->default_settings(),
                                           WallScene::of(make_vssw(table1(number), 0.5)));
    }
}

TEST(BulletRestitution, Fig6WallTakesTheWholeMechanismImpactAtEveryStep) {
    if (!engine_available("bullet")) GTEST_SKIP() << "Bullet is not compiled in";
    const auto engine = multibody::make_engine("bullet");
    for (double dt : {1e-3, 5e-4, 2e-4}) {
        SCOPED_TRACE("dt " + std::to_string(dt));
        multibody::EngineSettings settings = engine->default_settings();
        settings.dt = dt;
        expect_whole_mechanism_restitution(*engine, settings, fig6_vssw());
    }
}

// Bullet's friction rows leave an applied force's torque out of the velocity they hold, so N applied as a force made
// the hinge slide every step and lose energy, first order in the step: off the roller (Table 1 #14, xi 0.5, from
// 0.8 alpha1) the period was +3.16 % at 1 ms against the unilateral roller's model (docs/contributing/engines.md
// "Bullet"). With N as an impulse it is -0.063 %, ODE's figure; held at the 1 ms step explicitly, whatever the default.
TEST(BulletOffRoller, OverburdenTorqueDoesNotSlideTheHingeAtOneMillisecond) {
    if (!engine_available("bullet")) GTEST_SKIP() << "Bullet is not compiled in";
    const multibody::WallScene scene = multibody::WallScene::of(make_vssw(table1(14), 0.5));
    compare::FreeVibrationOptions options;
    options.r = 0.8;
    options.impacts = 1;
    const multibody::AnalyticEngine analytic;
    const auto reference = compare::run_free_vibration(
        analytic, multibody::analytic_settings({Kinematics::exact, {}, Roller::unilateral}), scene, options);
    const auto engine = multibody::make_engine("bullet");
    multibody::EngineSettings settings = engine->default_settings();
    settings.dt = 1e-3;
    const auto r = compare::run_free_vibration(*engine, settings, scene, options);
    ASSERT_TRUE(reference.period && r.period);
    EXPECT_LT(std::abs(*r.period / *reference.period - 1.0), compare::kPeriodTarget);
}

}  // namespace
}  // namespace vssw

// DART's own tests, registered by multibody/dart/engine.cmake and built into vssw_engine_tests (tests/CMakeLists.txt);
// each skips without DART in the build.
#include <gtest/gtest.h>

#include <string>

#include "analytic/closed_forms.hpp"
#include "compare/experiments.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "tests/engine_available.hpp"
#include "tests/engine_scenes.hpp"
#include "tests/refused_knobs.hpp"

namespace vssw {
namespace {

using multibody::WallScene;
using testing::analytic_reference;
using testing::engine_available;
using testing::first_impact;
using testing::fig6_parapet;
using testing::fig6_vssw;
using testing::fmt_scene;

// DART (multibody/dart/dart_engine.cpp): its knobs' ranges, its two collision detectors, the roller's spheres and
// guides placing the corner on its line, and the ContactConstraint statics set per run (they are process-wide).
TEST(Dart, BadSettingsAreRefusedByName) {
    if (!engine_available("dart")) GTEST_SKIP() << "DART is not compiled in";
    const auto engine = multibody::make_engine("dart");
    vssw::testing::expect_knobs_refused_by_name(
        *engine, {{"erp", 1.5}, {"cfm", 0.0}, {"cfm", 2.0}, {"erv", -1.0}, {"allowance", 1.0}, {"detector", 2.0}});
}

// The ODE detector (the default) and DART's own find the same corner contacts in free vibration: the same first impact
// and restitution (the Bullet detector is not offered: single precision, it aborts beside vssw's Bullet).
TEST(Dart, BothDetectorsGiveTheSameImpact) {
    if (!engine_available("dart")) GTEST_SKIP() << "DART is not compiled in";
    constexpr double kDetectorAgreement = 1e-3;  // both give a box corner as one point per edge end; measured equal
    const auto engine = multibody::make_engine("dart");
    multibody::EngineSettings own = engine->default_settings();
    own.knobs["detector"] = 0.0;
    for (const WallScene& scene : {fig6_vssw(), fig6_parapet()}) {
        SCOPED_TRACE(fmt_scene(scene, 0.5));
        const double own_impact = first_impact(*engine, own, scene, 0.5);
        EXPECT_NEAR(own_impact / first_impact(*engine, engine->default_settings(), scene, 0.5), 1.0, kDetectorAgreement);
        const auto a = compare::run_free_vibration(*engine, engine->default_settings(), scene);
        const auto b = compare::run_free_vibration(*engine, own, scene);
        ASSERT_TRUE(a.restitution && b.restitution);
        EXPECT_NEAR(*b.restitution / *a.restitution, 1.0, kDetectorAgreement);
    }
}

// The roller is a sphere centred at each top corner against a guide standing the sphere's radius outside x = +-b: the
// upper block must turn as the mechanism says (Eq. 2, exact kinematics) for the lower block's rotation, which a guide
// line off by the radius (0.1 b) would not give. Compared with the analytic model's theta2 at the same theta1.
TEST(Dart, RollerHoldsTheTopCornerOnItsLine) {
    if (!engine_available("dart")) GTEST_SKIP() << "DART is not compiled in";
    constexpr double kKinematics = 1e-3;  // relative to |theta2|: contact compliance (cfm) and the step's rounding
    const auto engine = multibody::make_engine("dart");
    const auto analytic = multibody::make_engine("analytic");
    const WallScene scene = fig6_vssw();
    multibody::Excitation ex;
    ex.theta0 = 0.8 * scene.alpha();
    ex.t_end = 0.9 * free_vibration(*analytic_reference(scene), ex.theta0).impacts.at(0).t;
    multibody::EngineSettings fine = analytic->default_settings();
    fine.sample_dt = 1e-4;
    const auto reference = analytic->simulate(scene, ex, fine).samples;  // theta1 falls from theta0 towards 0
    int compared = 0;
    for (const auto& p : engine->simulate(scene, ex, engine->default_settings()).samples) {
        if (p.theta1 < 0.2 * ex.theta0 || p.theta1 > 0.9 * ex.theta0) continue;
        for (std::size_t i = 1; i < reference.size(); ++i) {
            const auto &a = reference[i - 1], &b = reference[i];
            if ((a.theta1 - p.theta1) * (b.theta1 - p.theta1) > 0.0) continue;
            const double theta2 = a.theta2 + (b.theta2 - a.theta2) * (p.theta1 - a.theta1) / (b.theta1 - a.theta1);
            EXPECT_NEAR(p.theta2 / theta2, 1.0, kKinematics) << "theta1 " << p.theta1;
            ++compared;
            break;
        }
    }
    EXPECT_GT(compared, 100);
}

// DART's ContactConstraint erp, cfm, cap and allowance are static: a run must not inherit another's. In one process
// (the adapter itself), a default run after a run with other values is the default run to the last bit.
TEST(Dart, ContactStaticsAreSetForEachRun) {
    if (!engine_available("dart")) GTEST_SKIP() << "DART is not compiled in";
    const auto engine = multibody::make_engine_in_process("dart");
    const WallScene scene = fig6_vssw();
    multibody::Excitation ex;
    ex.theta0 = 0.5 * scene.alpha();
    ex.t_end = 1.5 * free_vibration(*analytic_reference(scene), ex.theta0).impacts.at(0).t;  // through an impact
    ex.motion_only = true;
    const multibody::EngineSettings defaults = engine->default_settings();
    multibody::EngineSettings other = defaults;
    other.knobs = {{"erp", 0.5}, {"cfm", 1e-3}, {"erv", 0.1}, {"allowance", 1e-3}};
    const auto before = engine->simulate(scene, ex, defaults).samples;
    const auto changed = engine->simulate(scene, ex, other).samples;
    const auto after = engine->simulate(scene, ex, defaults).samples;
    ASSERT_EQ(after.size(), before.size());
    EXPECT_NE(changed.back().theta1, before.back().theta1);  // the knobs do act
    for (std::size_t i = 0; i < before.size(); ++i) ASSERT_EQ(after[i].theta1, before[i].theta1) << "t " << before[i].t;
}

}  // namespace
}  // namespace vssw

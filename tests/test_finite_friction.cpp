// Finite friction (docs/model/analytic-core.md "Finite friction"): sliding measured, not failed, when the wall's
// friction is given. The slip meter against slips placed by hand; then every engine on walls not used for tuning
// (Table 1 #2 and the Fig. 6 parapet) under a sine pulse that rocks them: a friction of 1.2 times what the analytic
// model needs holds the wall, 0.8 times lets it slide; each contact takes its own coefficient; below the onset's
// friction (tan alpha for the parapet) the wall slides before it rocks; the default coefficient given by hand runs as
// the default does, to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/support_monitor.hpp"
#include "analytic/wall.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/slip_meter.hpp"
#include "tests/engine_scenes.hpp"
#include "tests/table1.hpp"

namespace vssw {
namespace {

using multibody::EngineFailure;
using multibody::Excitation;
using multibody::SlipMeasures;
using multibody::Trajectory;
using multibody::WallScene;
using multibody::WallState;

// A slip below this share of b is "held": the engines' largest at the default friction is 2e-4 b (MuJoCo's soft
// contacts), their largest at 1.2 times the model's need 6e-3 b (MuJoCo again; the others below 1.1e-3 b).
constexpr double kHeld = 1e-2;
// A slip above this share of b is "slid": at 0.8 times the need every engine slid 0.10 b or more; the default
// friction's failure limit is this (FailureLimits::slide).
constexpr double kSlid = 5e-2;
// Margins on the friction the model needs, as the criterion states them.
constexpr double kAbove = 1.2, kBelow = 0.8;

// Table 1 #2 (4.88 m x 0.356 m, h1/h 0.64), no overburden: not a wall any engine's settings were tuned on.
WallScene table1_wall() { return WallScene::of(make_vssw(testing::table1(2), 0.0)); }

// A sine pulse of 0.35 g (1.54 times Eq. (12) for that wall), 0.5 s: the wall rocks to about 0.42 alpha1 and lands.
Excitation rocking_pulse(double amplitude_g = 0.35) {
    Excitation ex;
    ex.horizontal = sine_pulse(amplitude_g * kStandardGravity, 0.5);
    ex.t_end = 2.0;
    return ex;
}

WallScene with_mu(WallScene scene, double base, double hinge) {
    scene.friction = base;
    scene.hinge_friction = hinge;
    scene.slip_measured = true;
    return scene;
}

// The friction the analytic model needs at the base and the hinge under the pulse (largest |T|/N while each pushes).
struct Needed {
    double base, hinge;
};
Needed model_needs(const WallScene& scene, const Excitation& ex) {
    const auto analytic = multibody::make_engine("analytic");
    const Trajectory t = analytic->simulate(scene, ex, analytic->default_settings());
    EXPECT_TRUE(t.located && t.located->supports_computed);
    return {t.located->base_friction_needed, t.located->hinge_friction_needed};
}

// ---- the slip meter on states placed by hand ----------------------------------------------------------------------

// The still wall at theta1, its lower block moved by dx along the ground and its upper block by dh along the lower
// block's top face: base slip dx, hinge slip dh, whatever the rotation. The rotated cases fail a meter that reads the
// corner nearer its place rather than the one in contact (measured: 2e-4 m off at the base, 6e-3 m at the hinge) or
// the hinge in the ground's frame rather than along the lower block's face. With rounded corners the still wall is
// rolled (rounded_pose_at) and rolling is no slip: a meter reading the nominal corners against +-b read 1.8e-3 b at
// r/b 0.1 and 9e-3 b at r/b 0.5 of pure rolling as hinge slip.
TEST(SlipMeter, ReadsSlipsPlacedByHandAtAnyRotation) {
    constexpr double kExact = 1e-12;  // [m] rounding of a few products of metres
    // [m] the rolled pose's Newton residual (1e-14 b) carried through its trigonometry, with margin
    constexpr double kRolled = 1e-11;
    for (const double radius : {0.0, 0.1, 0.5}) {
        const WallScene scene = WallScene::of(with_corner_radius(make_vssw(testing::table1(2), 0.0), radius));
        const multibody::BlockSizes z = multibody::block_sizes(scene);
        const double r = scene.corner_radius(), tol = radius == 0.0 ? kExact : kRolled;
        for (const double theta : {0.0, 0.3 * scene.alpha(), -0.6 * scene.alpha(), scene.alpha()}) {
            for (const double dx : {0.0, 0.01, -0.02}) {
                for (const double dh : {0.0, 0.005, -0.015}) {
                    WallState s = multibody::still_state_at(scene, theta);
                    const double turned = s.lower.angle;  // the lower block's rotation, along whose face dh goes
                    s.lower.x += dx;
                    s.upper.x += dx + dh * std::cos(turned);
                    s.upper.y -= dh * std::sin(turned);  // along the lower block's face (clockwise rotation)
                    EXPECT_NEAR(multibody::base_slip(s, z, r), dx, tol) << radius << " " << theta << " " << dx;
                    EXPECT_NEAR(multibody::hinge_slip(s, z, r), dh, tol) << radius << " " << theta << " " << dh;
                }
            }
        }
    }
}

TEST(SlipMeter, ParapetHasNoHinge) {
    const WallScene scene = testing::fig6_parapet();
    WallState s = multibody::still_state_at(scene, 0.2 * scene.alpha());
    s.lower.x += 0.01;
    EXPECT_NEAR(multibody::base_slip(s, multibody::block_sizes(scene)), 0.01, 1e-12);
    EXPECT_EQ(multibody::hinge_slip(s, multibody::block_sizes(scene)), 0.0);
}

// The monitor: a slide fails a default-friction run (a bug to report) and is measured with the friction given; a slide
// past kSlidOffLimit b ends the run with its reason. A parapet: a VSSW's top, held by the roller, cannot slide along.
TEST(SlipMeter, MonitorMeasuresWhatTheDefaultFails) {
    const WallScene plain = testing::fig6_parapet(), given = with_mu(plain, 0.5, 0.5);
    const double b = multibody::block_sizes(given).b;
    const Excitation ex = rocking_pulse();
    WallState s = multibody::still_state_at(given, 0.0);
    s.lower.x += 0.1 * b;
    multibody::RunMonitor fails("test", plain, ex, 1e-3, {});
    EXPECT_THROW(fails.check(1e-3, s), EngineFailure);
    multibody::RunMonitor measures("test", given, ex, 1e-3, {});
    EXPECT_EQ(measures.check(1e-3, s), multibody::RunMonitor::Verdict::go_on);
    s.lower.x += 1.0 * b;  // past one b
    EXPECT_EQ(measures.check(2e-3, s), multibody::RunMonitor::Verdict::slid_off);
    const SlipMeasures m = measures.slip().value();
    EXPECT_NEAR(m.base_largest / b, 1.1, 1e-9);
    EXPECT_NEAR(m.base_residual / b, 1.1, 1e-9);
    EXPECT_EQ(m.t_first_slip.value_or(-1.0), 1e-3);
    EXPECT_FALSE(m.t_first_lift.has_value());
    EXPECT_TRUE(m.slid_before_rocking());
    ASSERT_TRUE(m.slid_off.has_value());
    EXPECT_NE(m.slid_off->find("slid off its support"), std::string::npos) << *m.slid_off;
    EXPECT_FALSE(fails.slip().has_value());
}

// ---- every engine ---------------------------------------------------------------------------------------------------

class FiniteFriction : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        if (GetParam() == "analytic") GTEST_SKIP() << "the analytic model cannot slide (AnalyticSaysWhereItWouldSlide)";
        engine_ = multibody::make_engine(GetParam());
        settings_ = engine_->default_settings();
        // simbody-rigid refuses a friction given with its default PLUS solver (SimbodyRigidNeedsPgs): PGS slides.
        if (GetParam() == "simbody-rigid") settings_.knobs["solver"] = 1.0;
    }
    SlipMeasures slips(const WallScene& scene, const Excitation& ex) const {
        const Trajectory t = engine_->simulate(scene, ex, settings_);
        EXPECT_TRUE(t.slip.has_value());
        return t.slip.value_or(SlipMeasures{});
    }
    std::unique_ptr<multibody::Engine> engine_;
    multibody::EngineSettings settings_;
};

double largest(const SlipMeasures& m) { return std::max(m.base_largest, m.hinge_largest) / m.b; }

// The criterion with one coefficient at both contacts: F the larger of the model's two needs.
TEST_P(FiniteFriction, TheModelsNeedHoldsTheWallAndLessLetsItSlide) {
    const WallScene wall = table1_wall();
    const Excitation ex = rocking_pulse();
    const Needed need = model_needs(wall, ex);
    const double F = std::max(need.base, need.hinge);
    const SlipMeasures held = slips(with_mu(wall, kAbove * F, kAbove * F), ex);
    const SlipMeasures slid = slips(with_mu(wall, kBelow * F, kBelow * F), ex);
    EXPECT_LT(largest(held), kHeld) << "F " << F << ": base " << held.base_largest / held.b << " b, hinge "
                                    << held.hinge_largest / held.b << " b";
    EXPECT_GT(largest(slid), kSlid) << "F " << F;
    EXPECT_FALSE(held.slid_off.has_value());
}

// Each contact takes its own coefficient: 0.8 times the base's need with a high hinge slides the base (the upper block
// follows it, held by the hinge), 0.8 times the hinge's with a high base slides the hinge alone.
TEST_P(FiniteFriction, EachContactTakesItsOwnCoefficient) {
    const WallScene wall = table1_wall();
    const Excitation ex = rocking_pulse();
    const Needed need = model_needs(wall, ex);
    constexpr double kHigh = 2.0;  // the default: nothing slides
    const SlipMeasures base = slips(with_mu(wall, kBelow * need.base, kHigh), ex);
    const SlipMeasures hinge = slips(with_mu(wall, kHigh, kBelow * need.hinge), ex);
    EXPECT_GT(base.base_largest / base.b, kSlid);
    EXPECT_LT(base.hinge_largest / base.b, kHeld);
    EXPECT_GT(hinge.hinge_largest / hinge.b, kSlid);
    EXPECT_LT(hinge.base_largest / hinge.b, kHeld);
}

// A block on the ground slides before it rocks when the friction cannot carry the acceleration that would tip it:
// with N centred, m a_h <= mu (W + N) fails below a_h = Eq. (17)'s threshold g tan(alpha) (1 + xi) when
// mu < tan(alpha) (docs/model/analytic-core.md "Finite friction"); and sliding, it never rocks (its acceleration is
// capped at mu g (1 + xi), below the threshold). Above tan(alpha) it lifts first.
TEST_P(FiniteFriction, ParapetSlidesBeforeItRocksBelowTanAlpha) {
    const WallScene wall = testing::fig6_parapet();
    const double tan_alpha = std::tan(wall.parapet->alpha);
    // Three times Eq. (17): below tan(alpha) every engine slid 0.27 b before it could lift (at 1.5 times, 0.05 b).
    const Excitation ex = rocking_pulse(3.0 * eq17_parapet_threshold(*wall.parapet) / kStandardGravity);
    const SlipMeasures below = slips(with_mu(wall, kBelow * tan_alpha, kBelow * tan_alpha), ex);
    const SlipMeasures above = slips(with_mu(wall, kAbove * tan_alpha, kAbove * tan_alpha), ex);
    EXPECT_TRUE(below.slid_before_rocking());
    EXPECT_FALSE(below.t_first_lift.has_value()) << "lifted at " << below.t_first_lift.value_or(NAN);
    EXPECT_GT(below.base_largest / below.b, kSlid);
    EXPECT_TRUE(above.t_first_lift.has_value());
    EXPECT_FALSE(above.slid_before_rocking()) << "slid at " << above.t_first_slip.value_or(NAN) << ", lifted at "
                                              << above.t_first_lift.value_or(NAN);
}

// The VSSW's onset: at Eq. (12)'s threshold a_c the mechanism's reactions are determinate (base pivot, hinge and roller
// at their corners, theta1'' = 0). The upper block's moments about the hinge give the roller R = b (W2 + N) / (2 h2) +
// m2 a_c / 2, so the hinge carries T_h = R - m2 a_c and the base T_b = T_h - m1 a_c, under W1 + W2 + N
// (docs/model/analytic-core.md "Finite friction"):
//     mu_base = |(a_c/g)(m1 + m2/2) - (tan(alpha2)/2)(m2 + N/g)| / (m1 + m2 + N/g).
// Below it the wall slides before it rocks; above, it lifts first. The model's two-block reactions at the onset are
// the same number (a closed form against the model's Newton-Euler solve).
TEST_P(FiniteFriction, VsswSlidesBeforeItRocksBelowTheOnsetsFriction) {
    const WallScene wall = table1_wall();
    const VsswGeometry& w = *wall.vssw;
    const auto model = testing::analytic_reference(wall);
    const double a_c = model->rest_threshold(0.0), g = w.g;
    const double m1 = w.m1, m2 = w.m2, n = w.N / g;  // per unit depth [kg/m]
    const double F = std::abs(a_c / g * (m1 + 0.5 * m2) - 0.5 * std::tan(w.alpha2) * (m2 + n)) / (m1 + m2 + n);
    // theta1 > 0 is the side a negative a_h tips the wall to (multibody/engine.hpp).
    const TwoBlockReactions onset = SupportMonitor(*model).reactions(1, 0.0, 0.0, 0.0, -a_c, 0.0);
    constexpr double kSolve = 1e-9;  // the Newton-Euler solve's round-off on a ratio of order 0.1
    EXPECT_NEAR(onset.base_friction, F, kSolve);
    const Excitation ex = rocking_pulse();
    const SlipMeasures below = slips(with_mu(wall, kBelow * F, kBelow * F), ex);
    const SlipMeasures above = slips(with_mu(wall, kAbove * F, kAbove * F), ex);
    EXPECT_TRUE(below.slid_before_rocking()) << "onset F " << F;
    EXPECT_TRUE(above.t_first_lift.has_value());
    EXPECT_FALSE(above.slid_before_rocking()) << "onset F " << F << ": slid at " << above.t_first_slip.value_or(NAN)
                                              << ", lifted at " << above.t_first_lift.value_or(NAN);
}

// The default coefficient given by hand is the default run, sample for sample, and its slips are the contacts' drift.
TEST_P(FiniteFriction, TheDefaultCoefficientGivenRunsAsTheDefault) {
    const WallScene wall = table1_wall();
    const Excitation ex = rocking_pulse();
    const Trajectory plain = engine_->simulate(wall, ex, settings_);
    const WallScene given = with_mu(wall, wall.friction, wall.friction);
    const Trajectory measured = engine_->simulate(given, ex, settings_);
    ASSERT_EQ(plain.samples.size(), measured.samples.size());
    // Field by field, bit for bit (the struct's padding after `contacts` is not part of a sample).
    auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    for (std::size_t i = 0; i < plain.samples.size(); ++i) {
        const multibody::TrajectorySample &p = plain.samples[i], &m = measured.samples[i];
        ASSERT_TRUE(same(p.t, m.t) && same(p.theta1, m.theta1) && same(p.theta1_dot, m.theta1_dot) &&
                    same(p.theta2, m.theta2) && same(p.top_dy, m.top_dy) && same(p.kinetic, m.kinetic) &&
                    same(p.potential, m.potential) && p.contacts == m.contacts)
            << "sample " << i << " t " << p.t << ": theta1 " << p.theta1 << " / " << m.theta1;
    }
    EXPECT_FALSE(plain.slip.has_value());
    ASSERT_TRUE(measured.slip.has_value());
    EXPECT_LT(largest(*measured.slip), kHeld);
}

// simbody-rigid's PLUS solver holds the contacts past Coulomb's bound: a friction given is refused with the reason
// (its PGS solver, which the suite above runs, slides as the others do).
TEST(FiniteFrictionModel, SimbodyRigidNeedsPgs) {
    const std::vector<std::string> all = multibody::available_engines();
    if (std::find(all.begin(), all.end(), "simbody-rigid") == all.end()) GTEST_SKIP() << "no Simbody in this build";
    const auto engine = multibody::make_engine("simbody-rigid");
    const WallScene wall = testing::fig6_parapet();
    const Excitation ex = rocking_pulse(0.15);
    EXPECT_THROW(engine->simulate(with_mu(wall, 0.08, 0.08), ex, engine->default_settings()), InputError);
    EXPECT_NO_THROW(engine->simulate(wall, ex, engine->default_settings()));
}

std::string engine_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string n = info.param;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
}

INSTANTIATE_TEST_SUITE_P(Engines, FiniteFriction, ::testing::ValuesIn(multibody::available_engines()), engine_name);

// The analytic model runs as before with a friction given and says where it would slide: a warning naming the contact
// and its need when the need exceeds the coefficient, none when it does not.
TEST(FiniteFrictionModel, AnalyticSaysWhereItWouldSlide) {
    const WallScene wall = table1_wall();
    const Excitation ex = rocking_pulse();
    const Needed need = model_needs(wall, ex);
    const auto analytic = multibody::make_engine("analytic");
    auto friction_warnings = [&](const WallScene& scene) {
        std::string all;
        for (const std::string& w : analytic->simulate(scene, ex, analytic->default_settings()).warnings)
            if (w.find("would slide") != std::string::npos) all += w + "\n";
        return all;
    };
    const std::string base_only = friction_warnings(with_mu(wall, kBelow * need.base, kAbove * need.hinge));
    EXPECT_NE(base_only.find("the base needs"), std::string::npos) << base_only;
    EXPECT_EQ(base_only.find("the hinge needs"), std::string::npos) << base_only;
    EXPECT_EQ(friction_warnings(with_mu(wall, kAbove * need.base, kAbove * need.hinge)), "");
    // The run itself is the model's, friction or not.
    const Trajectory plain = analytic->simulate(wall, ex, analytic->default_settings());
    const Trajectory given = analytic->simulate(with_mu(wall, 0.01, 0.01), ex, analytic->default_settings());
    ASSERT_EQ(plain.samples.size(), given.samples.size());
    EXPECT_EQ(plain.samples.back().theta1, given.samples.back().theta1);
    EXPECT_FALSE(given.slip.has_value());
}

}  // namespace
}  // namespace vssw

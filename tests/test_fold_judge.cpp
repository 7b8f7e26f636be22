// A wall past the unstable equilibrium is judged overturned during the shaking once it cannot come back
// (multibody/kit/fold_judge.hpp): the capacity curve it rests on (RockingModel::holding_acceleration) against values
// computed independently, a wall that passes the equilibrium under a pulse and comes back never called overturned, and
// a folded wall called overturned before the record's end.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall.hpp"
#include "multibody/kit/fold_judge.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/wall_parts.hpp"
#include "tests/engine_scenes.hpp"

namespace vssw {
namespace {

using testing::fig6_parapet;
using testing::fig6_vssw;
using Verdict = multibody::RunMonitor::Verdict;

// Rotations at which the curves are compared, in units of the reference angle: rest, rocking, the unstable
// equilibrium's neighbourhood and past it toward the collapse.
const std::vector<double> kAngles = {0.0, 0.3, 0.8, 1.0, 1.3, 2.0, 3.0, 3.7};

// A rigid block on its corner (Housner's): still at q under a horizontal acceleration a when the weight's moment about
// the pivot, m g R sin(alpha - q), meets the inertial force's, m a R cos(alpha - q): a = g tan(alpha - q), by hand.
TEST(CapacityCurve, ABlockOnItsCornerIsHeldByGTanOfAlphaLessTheRotation) {
    const auto model = make_parapet_model(make_parapet(4.0, 0.4));
    const double alpha = model->reference_angle(), g = model->gravity();
    constexpr double kRounding = 1e-12;  // two evaluations of the same trigonometry, m/s^2 of order 1
    for (const double r : kAngles) {
        if (r * alpha >= model->collapse_angle()) continue;
        EXPECT_NEAR(model->holding_acceleration(1, r * alpha), g * std::tan(alpha - r * alpha), kRounding) << r;
        EXPECT_NEAR(model->holding_acceleration(-1, r * alpha), g * std::tan(alpha - r * alpha), kRounding) << r;
    }
}

// The two blocks of the Fig. 6 VSSW placed by the kit's mechanism (pose_at: Eq. 2, the blocks' centres by geometry),
// their weights' height and horizontal position differentiated over theta1: c = g d(sum m y)/dq / d(sum m x)/dq.
double capacity_by_differences(const multibody::WallScene& scene, double q) {
    const multibody::BlockSizes s = multibody::block_sizes(scene);
    const auto moments = [&](double theta, double& mx, double& my) {
        const multibody::WallPose p = multibody::pose_at(scene, theta);
        mx = s.m_lower * p.lower.x + s.m_upper * p.upper.x;
        my = s.m_lower * p.lower.y + s.m_upper * p.upper.y;
    };
    constexpr double kStep = 1e-6;  // [rad]: truncation ~1e-12, cancellation ~1e-10 of the lever sums
    double x_hi = 0, y_hi = 0, x_lo = 0, y_lo = 0;
    moments(q + kStep, x_hi, y_hi);
    moments(std::max(q - kStep, 0.0), x_lo, y_lo);  // one-sided at rest (the mechanism starts there)
    return scene.gravity() * (y_hi - y_lo) / (x_hi - x_lo);
}

TEST(CapacityCurve, TheVsswMatchesFiniteDifferencesOfItsBlocksPositions) {
    const multibody::WallScene scene = fig6_vssw();
    const auto model = make_vssw_model(*scene.vssw, Kinematics::exact);
    const auto paper = make_vssw_model(*scene.vssw, Kinematics::paper);
    const double alpha1 = scene.alpha();
    // Relative to the rest threshold's scale: the one-sided difference at rest errs by ~kStep / alpha1.
    constexpr double kDifferences = 1e-4;
    const double scale = model->rest_threshold(0.0);
    for (const double r : kAngles) {
        const double q = r * alpha1, by_hand = capacity_by_differences(scene, q);
        EXPECT_NEAR(model->holding_acceleration(1, q), by_hand, kDifferences * scale) << r;
        // The comparison tells kinematics apart: the paper's Eq. (3) misses these values past rest.
        if (r >= 2.0) {
            EXPECT_GT(std::abs(paper->holding_acceleration(1, q) - by_hand), 10 * kDifferences * scale) << r;
        }
    }
    // At rest Eq. (12); at the unstable equilibrium (the potential's maximum) zero; negative past it.
    constexpr double kClosedForm = 1e-9;  // Eq. (12)'s arithmetic against the model's terms
    EXPECT_NEAR(model->holding_acceleration(1, 0.0), eq12_threshold(*scene.vssw), kClosedForm * scale);
    constexpr double kAtTheMaximum = 1e-6;  // the argmax's error (~1e-8 rad) times c's slope (~scale / alpha1)
    EXPECT_NEAR(model->holding_acceleration(1, model->unstable_equilibrium(1)), 0.0, kAtTheMaximum * scale);
    EXPECT_LT(model->holding_acceleration(1, 1.5 * alpha1), 0.0);
}

// The analytic model of the Fig. 6 VSSW under a one-sine pulse of 6.375 g and 0.2 s, sampled every ms (a record, so
// that the acceleration left falls as the pulse goes; 6.25 and 6.5 g pass it and stand too): the wall passes its
// unstable equilibrium (to 1.28 alpha1) during the
// pulse's first half, the second half brings it back, and it stands. Fed to RunMonitor, the run is never called
// overturned. A judge that ignored the shaking left (past the equilibrium, moving outward: overturned) would have
// called it.
TEST(FoldJudge, AWallThatPassesTheEquilibriumAndComesBackIsNotOverturned) {
    const multibody::WallScene scene = fig6_vssw();
    const auto model = make_vssw_model(*scene.vssw, Kinematics::exact);
    const double g = scene.gravity(), period = 0.2, dt = 1e-3;
    const GroundMotion sine = sine_pulse(6.375 * g, period);
    std::vector<double> times, values;
    for (int i = 0; i <= 200; ++i) {
        times.push_back(i * dt);
        values.push_back(sine(i * dt));
    }
    const GroundMotion pulse = GroundMotion::sampled(times, values, "sine 6.375 g 0.2 s");
    SimulationOptions options;
    options.t_end = 3.0;
    options.output_dt = dt;
    const SimulationResult run = simulate(*model, pulse, GroundMotion::none(), {}, options);
    ASSERT_FALSE(run.overturned);
    const double unstable = model->unstable_equilibrium();
    ASSERT_GT(run.max_abs_theta, unstable);  // the premise: it went past the equilibrium

    multibody::Excitation ex;
    ex.horizontal = pulse;
    ex.t_end = options.t_end;
    const multibody::FailureLimits rotations_only{multibody::FailureLimits{}.slide, HUGE_VAL, HUGE_VAL};
    multibody::RunMonitor monitor("test", scene, ex, dt, rotations_only);
    multibody::FoldJudge judge(scene, pulse);
    bool outward_past = false;  // a sample past the equilibrium, moving outward
    for (const Sample& s : run.samples) {
        if (s.t <= 0.0) continue;
        const Verdict v = monitor.check(s.t, multibody::still_state_at(scene, s.theta, s.theta_dot));
        ASSERT_NE(v, Verdict::overturned) << "at t = " << s.t << ", theta1 = " << s.theta / scene.alpha() << " alpha1";
        const int side = s.theta < 0.0 ? -1 : 1;
        if (side * s.theta_dot >= 0.0 && judge.hold_back(side, std::abs(s.theta)) > 0.0) outward_past = true;
    }
    EXPECT_TRUE(outward_past);
}

// A folded wall (swinging at 3.7 to 4.0 alpha1, as MuJoCo's, Siconos's and Simbody's do) after a strong shaking, with
// a weak tail left to the record's end at 20 s: judged overturned at once, where the rule after the shaking waited
// for 20 + kFoldedFor s. While the strong part is still to come, the same wall is not judged.
TEST(FoldJudge, AFoldedWallIsOverturnedBeforeTheRecordsEnd) {
    const multibody::WallScene scene = fig6_vssw();
    const auto model = make_vssw_model(*scene.vssw, Kinematics::exact);
    const double alpha1 = scene.alpha(), dt = 1e-3;
    // The smallest hold-back over the swing, from the capacity curve (what an inward acceleration must exceed).
    double weakest = HUGE_VAL;
    for (double q = 3.7 * alpha1; q < model->collapse_angle(); q += 1e-3 * alpha1)
        weakest = std::min(weakest, -model->holding_acceleration(1, q));
    ASSERT_GT(weakest, 0.0);
    const double strong = 3.0 * weakest, weak = 0.5 * weakest;
    multibody::Excitation ex;
    ex.horizontal = GroundMotion::sampled({0.0, 2.0, 3.0, 4.0, 20.0}, {0.0, strong, weak, weak, weak}, "m");
    ex.t_end = 25.0;
    const auto swinging = [&](double t) { return (3.85 + 0.15 * std::sin(2.0 * M_PI * t)) * alpha1; };
    const multibody::FailureLimits rotations_only{multibody::FailureLimits{}.slide, HUGE_VAL, HUGE_VAL};
    // The first time from `start` at which the monitor ends the run as overturned, +infinity if not by `stop`.
    const auto overturned_at = [&](double start, double stop) {
        multibody::RunMonitor monitor("test", scene, ex, dt, rotations_only);
        for (double t = start; t < stop; t += dt) {
            const double rate = (swinging(t + dt) - swinging(t - dt)) / (2.0 * dt);
            if (monitor.check(t, multibody::still_state_at(scene, swinging(t), rate)) == Verdict::overturned)
                return t;
        }
        return HUGE_VAL;
    };
    constexpr double kSwing = 1.0;  // [s] the swing's period: the first outward-moving moment comes within it
    EXPECT_LT(overturned_at(3.0, 25.0), 3.0 + kSwing);  // the strong part over: now
    EXPECT_EQ(overturned_at(0.5, 1.9), HUGE_VAL);        // the strong part to come: not yet
}

}  // namespace
}  // namespace vssw

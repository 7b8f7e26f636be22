// The floor of bench/floor/ is a valid yardstick: the engines' scheme at its plainest reproduces the analytic model
// on the Fig. 6 wall within the targets an engine must meet (compare/targets.hpp), as the engines do, and its
// period error falls with the step. Its measures are read by the harness's own metrics (compare/metrics.hpp) and the
// expected values come from the analytic library, never from the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/simulate.hpp"
#include "bench/floor/floor_step.hpp"
#include "compare/experiments.hpp"  // kFirstImpactMargin: the window the suite runs to
#include "compare/metrics.hpp"
#include "compare/targets.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "tests/engine_scenes.hpp"

namespace vssw {
namespace {

using yardstick::FloorSettings;

constexpr double kRelease = 0.5;  // released at 0.5 alpha1, as the engines' benchmark and the figures quoted for it

struct FloorMeasures {
    std::optional<double> period_error;       // relative to the analytic model's (exact kinematics)
    std::optional<double> restitution_error;  // first impact's ratio relative to the whole mechanism's plastic impact
};

// The floor released on the Fig. 6 VSSW, run past its first impact, measured as an engine's run is.
FloorMeasures measure(const FloorSettings& settings) {
    const multibody::WallScene scene = testing::fig6_vssw();
    const double theta0 = kRelease * scene.alpha();
    const double quarter = free_vibration(*testing::analytic_reference(scene), theta0).impacts.at(0).t;
    const multibody::Trajectory traj =
        yardstick::run_floor(scene, theta0, compare::kFirstImpactMargin * quarter, settings);
    FloorMeasures m;
    if (const std::optional<double> q = compare::quarter_period(traj)) m.period_error = *q / quarter - 1.0;
    const std::vector<compare::ImpactMetric> impacts = compare::impacts(traj);
    if (!impacts.empty() && impacts.front().resolved)
        m.restitution_error = impacts.front().ratio / restitution_whole_mechanism(*scene.vssw) - 1.0;
    return m;
}

// What an engine must meet on this wall (tests/test_engines.cpp): both measures, each within its target.
bool meets_the_engines_targets(const FloorMeasures& m) {
    return m.period_error && std::abs(*m.period_error) <= compare::kPeriodTarget && m.restitution_error &&
           std::abs(*m.restitution_error) <= compare::kRestitutionTarget;
}

TEST(FloorStep, MeetsTheEnginesTargetsOnTheFig6Wall) {
    for (const int iterations : {8, 10, 20}) {
        FloorSettings s;
        s.iterations = iterations;
        const FloorMeasures m = measure(s);
        ASSERT_TRUE(m.period_error && m.restitution_error) << iterations << " iterations";
        EXPECT_TRUE(meets_the_engines_targets(m))
            << iterations << " iterations: period " << *m.period_error << ", restitution " << *m.restitution_error;
    }
}

// The period's error is the step's (symplectic Euler, first order): halving the step halves it. Measured: ratios
// 1.92, 1.97, 2.03 from 2 ms to 0.25 ms; the band allows the first impact's sampling error, a fraction of a step.
constexpr double kFirstOrderLow = 1.6, kFirstOrderHigh = 2.4;

TEST(FloorStep, PeriodErrorFallsWithTheStep) {
    double previous = NAN;
    for (const double dt : {2e-3, 1e-3, 5e-4, 2.5e-4}) {
        FloorSettings s;
        s.dt = dt;
        const FloorMeasures m = measure(s);
        ASSERT_TRUE(m.period_error) << "dt " << dt;
        const double error = std::abs(*m.period_error);
        if (!std::isnan(previous)) {
            EXPECT_GT(previous / error, kFirstOrderLow) << "dt " << dt;
            EXPECT_LT(previous / error, kFirstOrderHigh) << "dt " << dt;
        }
        previous = error;
    }
}

// The check above must be able to fail: without solver sweeps nothing holds the wall up (it sinks through the
// ground, never landing), and a single sweep leaves the mechanism's constraints loose.
TEST(FloorStep, TooFewIterationsFailTheTargets) {
    FloorSettings none;
    none.iterations = 0;
    const FloorMeasures fell = measure(none);
    EXPECT_FALSE(meets_the_engines_targets(fell));
    const multibody::WallScene scene = testing::fig6_vssw();
    yardstick::FloorWall wall(scene, kRelease * scene.alpha(), none);
    for (int k = 0; k < 1000; ++k) wall.step(0.0);  // 1 s: a free fall of 4.9 m, past the block's height
    EXPECT_LT(wall.lower_y(), 0.0) << "with no sweeps the lower block should have sunk through the ground";
}

// The ground's acceleration enters as the engines' tilted gravity: a steady push under the wall's rest threshold
// (Eq. 12, from the analytic library) leaves it at rest with every contact closed, one over it tips it.
constexpr double kThresholdMargin = 0.05;  // 5 % either side: the floor's step moves the threshold by far less
constexpr double kStillAngle = 1e-4;  // [rad] a wall at rest moves by the solver's residue (2.9e-6 measured at 0.95)
constexpr double kLifted = 1e-2;           // [rad] after 0.5 s over the threshold the wall is well off the ground

double largest_rotation_under(double share_of_threshold, int* contacts) {
    const multibody::WallScene scene = testing::fig6_vssw();
    yardstick::FloorWall wall(scene, 0.0, FloorSettings{});
    const double a_h = share_of_threshold * multibody::rest_threshold(scene);
    double largest = 0.0;
    for (int k = 0; k < 500; ++k) {
        wall.step(a_h);
        largest = std::max(largest, std::abs(wall.theta1()));
    }
    *contacts = wall.contacts();
    return largest;
}

TEST(FloorStep, LiftsOnlyPastTheRestThreshold) {
    int contacts = 0;
    EXPECT_LT(largest_rotation_under(1.0 - kThresholdMargin, &contacts), kStillAngle);
    EXPECT_EQ(contacts, 6);
    EXPECT_GT(largest_rotation_under(1.0 + kThresholdMargin, &contacts), kLifted);
}

TEST(FloorStep, RefusesWhatIsNotItsScene) {
    EXPECT_THROW(yardstick::FloorWall(testing::fig6_parapet(), 0.1, FloorSettings{}), std::invalid_argument);
    FloorSettings bad;
    bad.dt = 0.0;
    EXPECT_THROW(yardstick::FloorWall(testing::fig6_vssw(), 0.1, bad), std::invalid_argument);
}

}  // namespace
}  // namespace vssw

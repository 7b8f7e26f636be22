// The threshold search (compare/experiments.hpp, find_threshold): it brackets the analytic model's estimate
// (Eq. 12 / Eq. 17) and widens the bracket only when an end does not hold.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall.hpp"
#include "compare/experiments.hpp"
#include "multibody/host/analytic_engine.hpp"

namespace vssw::compare {
namespace {

using multibody::AnalyticEngine;
using multibody::Excitation;
using multibody::Trajectory;

// Trials of a search whose first bracket holds, bisected: its two ends, then the halvings of a bracket of relative
// width 1.01 - 1 / 1.01 = 0.0199 down to rel_tol 1e-4: ceil(log2(0.0199 / 1e-4)) = 8. The doubling from 0.05 g that
// this search replaced took 16-17 trials on these walls.
constexpr int kBracketedTrials = 10;
// Trials of a guided search on the analytic backend, whose wall leaves rest as the pointing assumes: the upper end,
// then one trial just below the point (does not lift) and one just above it (lifts).
constexpr int kGuidedTrials = 3;
// A trial's acceleration is the search's value in g times g (from the estimate in m/s^2 divided by g, times a bracket
// factor): a few ulps from the m/s^2 value the test expects. Where a trial lies: far above that, far below the
// bracket's 1 % and rel_tol 1e-4.
constexpr double kGRoundTrip = 1e-9;
// That no trial went beyond the cap: rounding only (a step past it would be of the order of rel_tol).
constexpr double kCapRoundoff = 1e-12;

// A backend whose wall lifts exactly when the held ground acceleration reaches a threshold of the test's choosing
// (a step, no dynamics): the search's bracket logic alone, with the threshold placed away from the estimate.
class StepThresholdEngine final : public multibody::Engine {
public:
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    explicit StepThresholdEngine(double threshold) : threshold_(threshold) {}  // [m/s^2]
    std::string name() const override { return "step-threshold"; }
    std::string version() const override { return "test"; }
    multibody::EngineSettings default_settings() const override { return {}; }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    void check_settings(const multibody::EngineSettings&) const override {}  // no knobs
    multibody::Trajectory simulate(const multibody::WallScene& scene, const Excitation& ex,
                        const multibody::EngineSettings&) const override {
        const double held = std::abs(ex.horizontal(ex.t_end));
        tried.push_back(held);
        multibody::Trajectory t;
        t.samples.push_back({0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 4});
        t.samples.push_back({ex.t_end, held >= threshold_ ? scene.alpha() : 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 4});
        return t;
    }
    mutable std::vector<double> tried;  // held accelerations of the trials [m/s^2]

private:
    double threshold_;
};

TEST(ThresholdSearch, TheAnalyticModelsThresholdIsBracketedAtOnce) {
    const AnalyticEngine engine;
    const ThresholdOptions o;
    // The mid-point of a final bracket of relative width rel_tol is within rel_tol / 2 of anything in it; the hold
    // lets any excess of detectable_excess * rel_tol lift the wall, so the truth is at most that below the bracket.
    const double tol = (0.5 + o.detectable_excess) * o.rel_tol;
    for (const VsswGeometry& w : {make_vssw(4.0, 0.4, 0.7, 0.1), make_vssw(3.05, 0.143, 0.6, 0.5)}) {
        const ThresholdResult r =
            find_threshold(engine, engine.default_settings(), multibody::WallScene::of(w), o);
        const double eq12 = eq12_threshold(w) / w.g;
        EXPECT_NEAR(r.value_g, eq12, tol * eq12);
        EXPECT_EQ(r.trials, kGuidedTrials);
    }
    const ParapetGeometry p = make_parapet(4.0, 0.4);
    const ThresholdResult r = find_threshold(engine, engine.default_settings(), multibody::WallScene::of(p), o);
    const double eq17 = eq17_parapet_threshold(p) / p.g;
    EXPECT_NEAR(r.value_g, eq17, tol * eq17);
    EXPECT_EQ(r.trials, kGuidedTrials);
}

// Bisection alone (guided = false) finds the same threshold in at most the bracketed trials: where the trials go does
// not change the answer beyond the tolerance both are held to.
TEST(ThresholdSearch, BisectionAloneFindsTheSameThreshold) {
    const AnalyticEngine engine;
    ThresholdOptions bisect;
    bisect.guided = false;
    const double tol = (0.5 + bisect.detectable_excess) * bisect.rel_tol;
    for (const VsswGeometry& w : {make_vssw(4.0, 0.4, 0.7, 0.1), make_vssw(3.05, 0.143, 0.6, 0.5)}) {
        const multibody::WallScene scene = multibody::WallScene::of(w);
        const ThresholdResult plain = find_threshold(engine, engine.default_settings(), scene, bisect);
        const ThresholdResult guided = find_threshold(engine, engine.default_settings(), scene, {});
        EXPECT_LE(plain.trials, kBracketedTrials);
        EXPECT_GT(plain.trials, guided.trials);
        EXPECT_NEAR(plain.value_g, guided.value_g, 2.0 * tol * plain.value_g);
    }
}

TEST(ThresholdSearch, ABracketThatDoesNotHoldIsWidened) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7, 0.1);
    const multibody::WallScene scene = multibody::WallScene::of(w);
    const ThresholdOptions o;
    const double estimate = eq12_threshold(w);  // [m/s^2]: the exact kinematics' rest threshold is Eq. (12)
    // Thresholds just outside the first bracket (1 %), far above and below it, and just under the search's cap.
    for (const double factor : {1.02, 0.97, 3.0, 1.0 / 3.0, 0.95 * o.max_over_estimate}) {
        const StepThresholdEngine engine(factor * estimate);
        const ThresholdResult r = find_threshold(engine, {}, scene, o);
        const double truth_g = factor * estimate / w.g;
        // The final bracket holds the step (lower did not lift, upper did) and is as narrow as asked.
        EXPECT_LT(r.lower_g, truth_g) << factor;
        EXPECT_GE(r.upper_g, truth_g) << factor;
        EXPECT_LE(r.upper_g - r.lower_g, o.rel_tol * r.upper_g) << factor;
        EXPECT_EQ(r.trials, static_cast<int>(engine.tried.size()));
        // The first trial was the bracket's upper end, inside [E, 1.01 E]: the search did start from the estimate.
        ASSERT_FALSE(engine.tried.empty());
        EXPECT_NEAR(engine.tried.front(), o.bracket * estimate, kGRoundTrip * estimate);
    }
}

TEST(ThresholdSearch, AnEngineThatNeverLiftsIsTriedUpToTheCap) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7, 0.1);
    const ThresholdOptions o;
    const StepThresholdEngine engine(10.0 * o.max_over_estimate * eq12_threshold(w));
    try {
        find_threshold(engine, {}, multibody::WallScene::of(w), o);
        ADD_FAILURE() << "no EngineFailure";
    } catch (const multibody::EngineFailure& e) {
        EXPECT_NE(std::string(e.what()).find("did not lift"), std::string::npos) << e.what();
    }
    ASSERT_FALSE(engine.tried.empty());
    // The last trial is at the cap exactly; none went beyond it.
    EXPECT_NEAR(engine.tried.back(), o.max_over_estimate * eq12_threshold(w), kGRoundTrip * eq12_threshold(w));
    for (const double a : engine.tried) EXPECT_LE(a, o.max_over_estimate * eq12_threshold(w) * (1.0 + kCapRoundoff));
}

TEST(ThresholdSearch, RejectsABracketThatIsNoBracket) {
    const AnalyticEngine engine;
    ThresholdOptions o;
    o.bracket = 1.0;
    EXPECT_THROW(find_threshold(engine, engine.default_settings(), multibody::WallScene::of(make_parapet(4.0, 0.4)), o),
                 InputError);
}

// The suite's free runs end at kFirstImpactMargin times the analytic model's first impact (first_impact_duration):
// the period and the first impact's restitution are what a run to the 8th impact gives, bit for bit (the run is the
// same up to its end). Ended before the impact, a run has neither: the end is what makes them measured.
TEST(FirstImpactDuration, ARunToItMeasuresWhatTheLongRunDoes) {
    const multibody::WallScene scene = multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7));
    const double theta0 = 0.5 * scene.alpha();
    const double t1 = free_vibration(*make_vssw_model(*scene.vssw, Kinematics::exact), theta0).impacts.at(0).t;
    EXPECT_EQ(first_impact_duration(scene, theta0), kFirstImpactMargin * t1);
    const AnalyticEngine engine;
    FreeVibrationOptions options;
    options.r = 0.5;
    const FreeVibrationResult whole = run_free_vibration(engine, engine.default_settings(), scene, options);
    ASSERT_GE(whole.impacts.size(), 8u);
    options.t_end = first_impact_duration(scene, theta0);
    const FreeVibrationResult first = run_free_vibration(engine, engine.default_settings(), scene, options);
    ASSERT_TRUE(first.period && first.restitution);
    EXPECT_EQ(*first.period, *whole.period);
    EXPECT_EQ(*first.restitution, *whole.restitution);
    options.t_end = 0.9 * t1;
    EXPECT_FALSE(run_free_vibration(engine, engine.default_settings(), scene, options).period);
}

}  // namespace
}  // namespace vssw::compare

// Metric extraction (compare/metrics.hpp) on synthetic trajectories with known answers, the analytic model behind the
// Engine interface (multibody/host/analytic_engine.hpp), and the experiments (compare/experiments.hpp) run on it against
// the closed forms and the integrator's own event list.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/simulate.hpp"
#include "compare/experiments.hpp"
#include "compare/metrics.hpp"
#include "multibody/host/analytic_engine.hpp"

namespace vssw::compare {
namespace {

using multibody::AnalyticEngine;
using multibody::Excitation;
using multibody::TrajectorySample;

constexpr double kPi = 3.14159265358979323846;

// Synthetic rocking -----------------------------------------------------------------------------------------------
// Flights theta = s (u tau - a tau^2 / 2) under a constant restoring acceleration a, alternating sides, each landing
// speed multiplied by e at the impact; the first flight is a release from rest at v0^2 / (2a). Everything is known in
// closed form: impact times, ratio e, turning points.
constexpr double kA = 1.3;    // restoring acceleration [rad/s^2]
constexpr double kV0 = 0.5;   // landing speed of the first flight [rad/s]
constexpr double kE = 0.81;   // restitution (sqrt(e) = 0.9 exactly, which keeps the bounds below constexpr)
constexpr double kSqrtE = 0.9;
constexpr double kDt = 1e-4;  // sampling [s], not commensurate with the impact times
constexpr int kFlights = 6;
// Slowest landing among the impacts measured (the 5th, after 4 losses).
constexpr double kVMin = kV0 * kE * kE * kE * kE;
// Linear interpolation across the kink of theta at an impact (slopes v and e v) misplaces the crossing by at most
// dt (1 - sqrt e)/(1 + sqrt e); the flight's curvature adds at most a dt^2 / (8 v) (metrics.hpp).
constexpr double kImpactTimeTol = kDt * (1.0 - kSqrtE) / (1.0 + kSqrtE) + kA * kDt * kDt / (8.0 * kVMin);
// Velocities are linear in a flight, so extrapolation is exact; read at the misplaced time, |v_before| gains and
// |v_after| loses a * dt_error: the ratio is off by at most (1 + e) a kImpactTimeTol / v (to first order).
constexpr double kRatioTol = (1.0 + kE) * kA * kImpactTimeTol / kVMin;
// A parabola through three samples of a parabolic flight is exact: only round-off in second differences remains.
constexpr double kParabolaExact = 1e-9;

struct Synthetic {
    multibody::Trajectory traj;
    std::vector<double> impact_times;
    std::vector<Peak> turning_points;
};

Synthetic synthetic_rocking() {
    Synthetic out;
    std::vector<double> start{0.0}, speed{kV0};
    std::vector<int> side{1};
    double t = kV0 / kA;  // the release lands after v0 / a
    for (int k = 1; k < kFlights; ++k) {
        out.impact_times.push_back(t);
        start.push_back(t);
        speed.push_back(speed.back() * kE);
        side.push_back(-side.back());
        t += 2.0 * speed.back() / kA;
    }
    const double t_end = t - 1e-3;  // the last flight is not allowed to land
    out.turning_points.push_back({0.0, kV0 * kV0 / (2.0 * kA)});
    for (int k = 1; k < kFlights; ++k)
        out.turning_points.push_back({start[k] + speed[k] / kA, side[k] * speed[k] * speed[k] / (2.0 * kA)});

    for (long i = 0;; ++i) {
        const double ti = static_cast<double>(i) * kDt;
        if (ti > t_end) break;
        int k = 0;
        while (k + 1 < kFlights && ti >= start[k + 1]) ++k;
        TrajectorySample s{};
        s.t = ti;
        if (k == 0) {
            s.theta1 = kV0 * kV0 / (2.0 * kA) - 0.5 * kA * ti * ti;
            s.theta1_dot = -kA * ti;
        } else {
            const double tau = ti - start[k];
            s.theta1 = side[k] * (speed[k] * tau - 0.5 * kA * tau * tau);
            s.theta1_dot = side[k] * (speed[k] - kA * tau);
        }
        out.traj.samples.push_back(s);
    }
    return out;
}

TEST(Metrics, ParabolicRockingGivesImpactTimesRatiosAndPeaks) {
    const Synthetic syn = synthetic_rocking();
    for (int skip : {0, 2, 5}) {
        SCOPED_TRACE(skip);
        const std::vector<ImpactMetric> list = impacts(syn.traj, skip);
        ASSERT_EQ(list.size(), syn.impact_times.size());
        for (std::size_t i = 0; i < list.size(); ++i) {
            EXPECT_NEAR(list[i].t, syn.impact_times[i], kImpactTimeTol);
            ASSERT_TRUE(list[i].resolved);
            EXPECT_NEAR(list[i].ratio, kE, kRatioTol);
        }
    }
    const std::vector<Peak> p = peaks(syn.traj);
    ASSERT_EQ(p.size(), syn.turning_points.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_NEAR(p[i].t, syn.turning_points[i].t, kParabolaExact);
        EXPECT_NEAR(p[i].theta, syn.turning_points[i].theta, kParabolaExact);
    }
    ASSERT_TRUE(quarter_period(syn.traj).has_value());
    EXPECT_NEAR(*quarter_period(syn.traj), kV0 / kA, kImpactTimeTol);
    const std::vector<double> half = half_cycles(syn.traj);
    ASSERT_EQ(half.size(), syn.impact_times.size() - 1);
    for (std::size_t i = 0; i < half.size(); ++i)
        EXPECT_NEAR(half[i], syn.impact_times[i + 1] - syn.impact_times[i], 2.0 * kImpactTimeTol);
}

TEST(Metrics, SmearedImpactNeedsTheWindow) {
    // An engine's impact: theta1_dot passes from v_before to v_after over four samples around the crossing.
    Synthetic syn = synthetic_rocking();
    auto& s = syn.traj.samples;
    for (const ImpactMetric& m : impacts(syn.traj, 0)) {
        const std::size_t j = m.index_before;
        const double v_before = s[j - 1].theta1_dot, v_after = s[j + 2].theta1_dot;
        for (std::size_t n = 0; n < 4; ++n) {
            const double w = static_cast<double>(n + 1) / 5.0;
            s[j - 1 + n].theta1_dot = (1.0 - w) * v_before + w * v_after;
        }
    }
    for (const ImpactMetric& m : impacts(syn.traj, 2)) EXPECT_NEAR(m.ratio, kE, kRatioTol);
    // Without the window the transition is read as the impact: far off (the blend is ~0.2 (1 - e) per sample).
    for (const ImpactMetric& m : impacts(syn.traj, 0)) EXPECT_GT(std::abs(m.ratio - kE), 100.0 * kRatioTol);
}

TEST(Metrics, ImpactTooCloseToTheEndIsKeptButNotResolved) {
    Synthetic syn = synthetic_rocking();
    const std::size_t after = impacts(syn.traj).back().index_after;
    syn.traj.samples.resize(after + 2);  // two samples on the new side: fewer than skip + 2 = 4
    const std::vector<ImpactMetric> list = impacts(syn.traj, 2);
    ASSERT_EQ(list.size(), syn.impact_times.size());
    EXPECT_FALSE(list.back().resolved);
    EXPECT_TRUE(std::isnan(list.back().ratio));
    EXPECT_TRUE(impacts(syn.traj, 0).back().resolved);
}

// A trajectory of a bump on each side of theta1 = 0 separated by exact rest, then jitter at rest.
multibody::Trajectory bumps_with_rest(double jitter) {
    multibody::Trajectory traj;
    constexpr double kStep = 1e-3;
    for (int i = 0; i <= 4000; ++i) {
        const double t = i * kStep;
        TrajectorySample s{};
        s.t = t;
        if (t > 0.0 && t < 1.0) {
            s.theta1 = 0.05 * std::sin(kPi * t);
            s.theta1_dot = 0.05 * kPi * std::cos(kPi * t);
        } else if (t > 2.0 && t < 3.0) {
            s.theta1 = -0.05 * std::sin(kPi * (t - 2.0));
            s.theta1_dot = -0.05 * kPi * std::cos(kPi * (t - 2.0));
        } else if (t > 3.0) {
            s.theta1 = (i % 2 == 0 ? 1.0 : -1.0) * jitter;
        }
        traj.samples.push_back(s);
    }
    return traj;
}

TEST(Metrics, RestBetweenExcursionsIsNoImpact) {
    const multibody::Trajectory traj = bumps_with_rest(0.0);
    EXPECT_TRUE(impacts(traj).empty());
    const std::vector<Peak> p = peaks(traj);
    ASSERT_EQ(p.size(), 2u);  // one turning point per bump, none at rest
    EXPECT_NEAR(p[0].theta, 0.05, 1e-6);
    EXPECT_NEAR(p[1].theta, -0.05, 1e-6);
    EXPECT_FALSE(quarter_period(traj).has_value());  // the run does not start from a release
    EXPECT_TRUE(lifted(traj, 0.05 - 1e-6));
    EXPECT_FALSE(lifted(traj, 0.06));
}

TEST(Metrics, NoiseAngleIgnoresJitterAtRest) {
    constexpr double kJitter = 1e-9;  // an engine's wall settled on its contacts
    const multibody::Trajectory traj = bumps_with_rest(kJitter);
    EXPECT_GT(impacts(traj).size(), 100u);  // every sign change counts by default
    EXPECT_TRUE(impacts(traj, kDefaultImpactSkip, 10.0 * kJitter).empty());
    EXPECT_EQ(peaks(traj, 10.0 * kJitter).size(), 2u);
    // A real rocking trajectory is unchanged by a noise angle far below its amplitude.
    const Synthetic syn = synthetic_rocking();
    EXPECT_EQ(impacts(syn.traj, 2, 1e-6).size(), syn.impact_times.size());
}

TEST(Metrics, PeaksOfASampledCosine) {
    constexpr double kAmp = 0.1, kOmega = 2.0 * kPi * 0.37, kStep = 1e-2, kEnd = 10.0;
    // Parabola through three samples around a turning point of A cos(w t) (derived from the quartic Taylor term):
    // vertex time within (w^2/24) max|2 tau h^2 - 8 tau^3| <= 0.016 w^2 h^3, value within (9/16) A w^4 h^4 / 24.
    constexpr double kTimeTol = 0.02 * kOmega * kOmega * kStep * kStep * kStep;
    constexpr double kValueTol = 0.025 * kAmp * kOmega * kOmega * kOmega * kOmega * kStep * kStep * kStep * kStep;
    multibody::Trajectory traj;
    for (int i = 0; i * kStep <= kEnd; ++i) {
        const double t = i * kStep;
        traj.samples.push_back({t, kAmp * std::cos(kOmega * t), -kAmp * kOmega * std::sin(kOmega * t), 0, 0, 0, 0, 0});
    }
    const std::vector<Peak> p = peaks(traj);
    const int expected = static_cast<int>(std::floor(kEnd * kOmega / kPi)) + 1;  // the release at t = 0 included
    ASSERT_EQ(static_cast<int>(p.size()), expected);
    for (int k = 0; k < expected; ++k) {
        EXPECT_NEAR(p[k].t, k * kPi / kOmega, kTimeTol);
        EXPECT_NEAR(p[k].theta, (k % 2 == 0 ? 1.0 : -1.0) * kAmp, kValueTol);
    }
}

// The analytic engine ----------------------------------------------------------------------------------------------

VsswGeometry test_vssw() { return make_vssw(4.0, 0.4, 0.7, 0.1); }  // hinge above mid-height, xi = 0.1
ParapetGeometry test_parapet() { return make_parapet(4.0, 0.4); }

TEST(AnalyticEngine, PositiveGroundAccelerationTipsTheWallTowardsNegativeTheta) {
    const AnalyticEngine engine;
    const multibody::WallScene scene = multibody::WallScene::of(test_vssw());
    Excitation ex;
    ex.horizontal = constant_motion(2.0 * eq12_threshold(test_vssw()), 0.5);
    ex.t_end = 0.5;
    const multibody::Trajectory traj = engine.simulate(scene, ex, engine.default_settings());
    ASSERT_FALSE(traj.samples.empty());
    EXPECT_LT(traj.samples.back().theta1, 0.0);
    EXPECT_GT(traj.samples.back().theta2, 0.0);  // the upper body turns the other way (Eq. 2)
    // The roller lets the top rise while the wall tips (it comes down again past ~0.8 alpha1 for this wall).
    int rising = 0;
    for (const TrajectorySample& x : traj.samples) {
        if (x.theta1 == 0.0 || std::abs(x.theta1) > 0.5 * scene.alpha()) continue;
        EXPECT_GT(x.top_dy, 0.0);
        ++rising;
    }
    EXPECT_GT(rising, 0);
}

TEST(AnalyticEngine, SamplesCarryTheKinematicsAndEnergiesOfTheModel) {
    constexpr double kRoundoff = 1e-12;  // same functions evaluated on the same numbers
    const AnalyticEngine engine;
    const VsswGeometry w = test_vssw();
    Excitation ex;
    ex.theta0 = 0.5 * w.alpha1;
    ex.t_end = 1.0;
    for (double paper : {0.0, 1.0}) {
        multibody::EngineSettings s = engine.default_settings();
        s.knobs["paper_kinematics"] = paper;
        s.knobs["unilateral_roller"] = 1.0 - paper;  // the paper's kinematics need the bilateral roller
        s.sample_dt = 1e-2;
        const multibody::Trajectory traj = engine.simulate(multibody::WallScene::of(w), ex, s);
        const auto model = make_vssw_model(w, paper == 1.0 ? Kinematics::paper : Kinematics::exact);
        ASSERT_EQ(traj.samples.size(), 101u);  // every sample_dt from 0 to t_end
        for (const TrajectorySample& x : traj.samples) {
            const double theta2 = paper == 1.0 ? eq3_theta2_linear(w, x.theta1) : *eq2_theta2_exact(w, x.theta1);
            EXPECT_NEAR(x.theta2, theta2, kRoundoff);
            EXPECT_NEAR(x.kinetic, model->kinetic(x.theta1, x.theta1_dot), kRoundoff);
            EXPECT_NEAR(x.potential, model->potential(x.theta1), kRoundoff);
            EXPECT_EQ(x.contacts, 0);
        }
    }
    const ParapetGeometry p = test_parapet();
    ex.theta0 = 0.5 * p.alpha;
    const multibody::Trajectory pw = engine.simulate(multibody::WallScene::of(p), ex, engine.default_settings());
    for (const TrajectorySample& x : pw.samples) EXPECT_EQ(x.theta2, 0.0);
}

TEST(AnalyticEngine, RejectsUnknownKnobsAndIllFormedScenes) {
    const AnalyticEngine engine;
    EXPECT_EQ(engine.name(), "analytic");
    Excitation ex;
    ex.theta0 = 0.01;
    multibody::EngineSettings s = engine.default_settings();
    s.knobs["rtoll"] = 1e-8;
    EXPECT_THROW(engine.simulate(multibody::WallScene::of(test_vssw()), ex, s), InputError);
    s = engine.default_settings();
    s.knobs["paper_kinematics"] = 0.5;
    EXPECT_THROW(engine.simulate(multibody::WallScene::of(test_vssw()), ex, s), InputError);
    EXPECT_THROW(engine.simulate(multibody::WallScene{}, ex, engine.default_settings()), InputError);
}

// Experiments on the analytic backend ------------------------------------------------------------------------------

TEST(Experiments, ThresholdByBisectionIsEq12AndEq17) {
    const AnalyticEngine engine;
    const ThresholdOptions o;
    // The mid-point of a final bracket of relative width rel_tol is within rel_tol / 2 of anything in it; the hold
    // lets any excess of detectable_excess * rel_tol lift the wall, so the truth is at most that below the bracket.
    const double tol = (0.5 + o.detectable_excess) * o.rel_tol;
    const VsswGeometry w = test_vssw();
    const ThresholdResult v = find_threshold(engine, engine.default_settings(), multibody::WallScene::of(w), o);
    EXPECT_NEAR(v.value_g, eq12_threshold(w) / w.g, tol * eq12_threshold(w) / w.g);
    EXPECT_LE(v.upper_g - v.lower_g, o.rel_tol * v.upper_g);
    EXPECT_LT(v.trials, 25);  // test_experiments.cpp bounds the trials of a bracketed search more tightly
    const ParapetGeometry p = test_parapet();
    const ThresholdResult pw = find_threshold(engine, engine.default_settings(), multibody::WallScene::of(p), o);
    EXPECT_NEAR(pw.value_g, eq17_parapet_threshold(p) / p.g, tol * eq17_parapet_threshold(p) / p.g);
}

TEST(Experiments, TheHoldLetsTheSmallestDetectableExcessLiftTheWall) {
    const AnalyticEngine engine;
    const ThresholdOptions o;
    for (const multibody::WallScene& scene : {multibody::WallScene::of(test_vssw()), multibody::WallScene::of(test_parapet())}) {
        const double hold = threshold_hold_time(scene, o);
        const auto model = vssw::analytic_model(scene, Kinematics::exact);
        auto lifts = [&](double excess) {
            Excitation ex;
            ex.horizontal = ramp_and_hold(model->rest_threshold(0.0) * (1.0 + excess), o.ramp_time, hold);
            ex.t_end = o.ramp_time + hold;
            multibody::EngineSettings s = engine.default_settings();
            s.sample_dt = o.sample_dt;
            return lifted(engine.simulate(scene, ex, s), o.lift_angle * scene.alpha());
        };
        EXPECT_TRUE(lifts(o.detectable_excess * o.rel_tol));
        EXPECT_FALSE(lifts(-o.detectable_excess * o.rel_tol));
    }
}

// A backend that never lifts the wall, or fails on every run.
class StubEngine final : public multibody::Engine {
public:
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    explicit StubEngine(bool fails) : fails_(fails) {}
    std::string name() const override { return "stub"; }
    std::string version() const override { return "0"; }
    multibody::EngineSettings default_settings() const override { return {}; }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    void check_settings(const multibody::EngineSettings&) const override {}  // no knobs
    multibody::Trajectory simulate(const multibody::WallScene&, const Excitation& ex, const multibody::EngineSettings&) const override {
        ++runs;
        if (fails_) throw multibody::EngineFailure("stub: blew up");
        multibody::Trajectory t;
        t.samples.push_back({ex.t_end, 0, 0, 0, 0, 0, 0, 4});
        return t;
    }
    mutable int runs = 0;

private:
    bool fails_;
};

TEST(Experiments, ThresholdReportsAnEngineThatFailsOrNeverLifts) {
    const multibody::WallScene scene = multibody::WallScene::of(test_vssw());
    const StubEngine failing(true), stuck(false);
    EXPECT_THROW(find_threshold(failing, {}, scene), multibody::EngineFailure);
    EXPECT_EQ(failing.runs, 1);  // the first failure ends the search
    EXPECT_THROW(find_threshold(stuck, {}, scene), multibody::EngineFailure);
    // The upper end at E * 1.01^(2^k), k = 0..7 (1.01 to 3.57 E: below the cap of 4 E), then one trial at the cap.
    constexpr int kTrialsToTheCap = 9;
    EXPECT_EQ(stuck.runs, kTrialsToTheCap);
    EXPECT_THROW(find_threshold(stuck, {}, multibody::WallScene{}), InputError);
    EXPECT_THROW(run_free_vibration(stuck, {}, multibody::WallScene{}), InputError);
}

// An engine whose first impact gains energy (or reverses the motion) gives no restitution but a note saying why, and
// a comparison with it lists the failure (vssw compare exits 3): Simbody once returned -0.26 with exit 0.
class EnergyGainingEngine final : public multibody::Engine {
public:
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    std::string name() const override { return "gainer"; }
    std::string version() const override { return "stub"; }
    multibody::EngineSettings default_settings() const override {
        multibody::EngineSettings s;
        s.dt = kDt;
        return s;
    }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    void check_settings(const multibody::EngineSettings&) const override {}  // no knobs
    multibody::Trajectory simulate(const multibody::WallScene& scene, const Excitation& ex, const multibody::EngineSettings&) const override {
        // theta1 falls linearly from theta0 at kSpeed, crosses 0 at t_c and leaves at twice the speed: ratio 2.
        const double t_c = ex.theta0 / kSpeed;
        multibody::Trajectory out;
        for (double t = 0.0; t <= 2.0 * t_c; t += kDt) {
            const bool after = t > t_c;
            const double theta = after ? -2.0 * kSpeed * (t - t_c) : ex.theta0 - kSpeed * t;
            if (theta < -0.9 * scene.alpha()) break;
            out.samples.push_back({t, theta, after ? -2.0 * kSpeed : -kSpeed, 0, 0, 0, 0, 1});
        }
        return out;
    }

private:
    static constexpr double kDt = 1e-3;    // [s]
    static constexpr double kSpeed = 0.1;  // [rad/s]
};

TEST(Experiments, AnImpactRatioOutsideZeroToOneIsAFailureNotARestitution) {
    const multibody::WallScene scene = multibody::WallScene::of(test_vssw());
    const EnergyGainingEngine engine;
    FreeVibrationOptions o;
    o.t_end = 10.0;
    const FreeVibrationResult r = run_free_vibration(engine, engine.default_settings(), scene, o);
    ASSERT_FALSE(r.impacts.empty());
    EXPECT_FALSE(r.restitution.has_value());
    EXPECT_NE(r.restitution_note.find("outside (0, 1]"), std::string::npos) << r.restitution_note;
    EXPECT_NE(r.restitution_note.find("gained energy"), std::string::npos) << r.restitution_note;
    EXPECT_NE(r.restitution_note.find("gainer"), std::string::npos) << r.restitution_note;
}

// Bound on the error of the first impact's velocity ratio from sampling every dt (metrics.hpp): the crossing time is
// off by at most dt (1 - sqrt e)/(1 + sqrt e), which moves the extrapolated velocities by theta1'' times it; the
// linear extrapolation over (skip + 1) dt adds p^2 (skip + 1)(skip + 2) dt^2 / 2 on each side.
double ratio_sampling_bound(const RockingModel& m, const Impact& first, double dt, int skip) {
    constexpr double kLeadingOrderMargin = 1.5;  // the bound keeps leading-order terms only
    const double e = m.restitution();
    const double dt_cross = dt * (1.0 - std::sqrt(e)) / (1.0 + std::sqrt(e));
    const double v = std::abs(first.theta_dot_before);
    const double acc_before = std::abs(m.acceleration(1, 0.0, first.theta_dot_before, 0.0, 0.0));
    const double acc_after = std::abs(m.acceleration(-1, 0.0, first.theta_dot_after, 0.0, 0.0));
    const double q = 1e-6 * m.reference_angle();
    const double p2 = std::abs(m.acceleration(1, q, 0.0, 0.0, 0.0) - m.acceleration(1, 0.0, 0.0, 0.0, 0.0)) / q;
    const double s = skip;
    return kLeadingOrderMargin * (dt_cross * (acc_after + e * acc_before) / v + p2 * (s + 1) * (s + 2) * dt * dt);
}

TEST(Experiments, FreeVibrationMeasuresWhatTheIntegratorReports) {
    const AnalyticEngine engine;
    // The model free_vibration() integrates by default: exact kinematics (as asked below), Eq. (19), bilateral roller.
    const multibody::EngineSettings settings = multibody::analytic_settings({Kinematics::exact, ImpactLaw{}, Roller::bilateral});
    for (const multibody::WallScene& scene : {multibody::WallScene::of(test_vssw()), multibody::WallScene::of(test_parapet())}) {
        SCOPED_TRACE(scene.is_vssw() ? "vssw" : "parapet");
        const auto model = vssw::analytic_model(scene, Kinematics::exact);
        const FreeVibrationResult f = run_free_vibration(engine, settings, scene);
        const SimulationResult reference = vssw::free_vibration(*model, f.theta0);
        ASSERT_GE(f.impacts.size(), 8u);
        // Quarter period: the first crossing, misplaced by at most the kink bound (curvature adds ~1e-3 of it).
        const double e = model->restitution();
        const double crossing = 1.1 * settings.dt * (1.0 - std::sqrt(e)) / (1.0 + std::sqrt(e));
        ASSERT_TRUE(f.quarter_period.has_value());
        EXPECT_NEAR(*f.quarter_period, reference.impacts[0].t, crossing);
        EXPECT_DOUBLE_EQ(*f.period, 4.0 * *f.quarter_period);
        for (std::size_t i = 0; i < f.half_cycles.size() && i + 1 < reference.impacts.size(); ++i)
            EXPECT_NEAR(f.half_cycles[i], reference.impacts[i + 1].t - reference.impacts[i].t, 2.0 * crossing);
        // Restitution of the first impact: Eq. (19) for the VSSW, Housner's e for the parapet.
        const double closed_form =
            scene.is_vssw() ? eq19_restitution(*scene.vssw) : housner_restitution(scene.parapet->alpha);
        ASSERT_TRUE(f.restitution.has_value());
        EXPECT_NEAR(*f.restitution, closed_form,
                    ratio_sampling_bound(*model, reference.impacts[0], settings.dt, kDefaultImpactSkip));
        // Peaks: the parabola through samples errs by O(dt^4) in theta; the energy form then gives e back.
        constexpr double kPeakRestitution = 1e-7;  // observed ~1e-10 at dt = 1e-4: three orders of headroom
        ASSERT_FALSE(f.amplitude.empty());
        EXPECT_EQ(f.amplitude.front().impact, 0u);
        EXPECT_NEAR(f.amplitude.front().energy, closed_form, kPeakRestitution);
        EXPECT_EQ(std::isnan(f.amplitude.front().eq23), !scene.is_vssw());
    }
}

TEST(Experiments, AnalyticAgainstItselfHasNoError) {
    // The comparison machinery with the analytic engine on both sides: identical runs, identical metrics.
    const AnalyticEngine engine;
    const VsswGeometry w = test_vssw();
    ComparisonOptions o;
    o.free.impacts = 3;
    const EngineComparison c = compare_with_analytic(engine, engine.default_settings(), multibody::WallScene::of(w), 0.5, o);
    EXPECT_EQ(c.threshold_g.rel_error, 0.0);
    EXPECT_EQ(c.period.rel_error, 0.0);
    EXPECT_EQ(c.restitution.rel_error, 0.0);
    EXPECT_EQ(c.restitution_amplitude.rel_error, 0.0);
    EXPECT_EQ(c.threshold_closed_form_g, eq12_threshold(w) / w.g);
    EXPECT_EQ(c.restitution_closed_form, eq19_restitution(w));
    EXPECT_TRUE(std::isnan(c.period_linearised));  // Eq. (22) assumes N = 0; this wall has xi = 0.1
    EXPECT_GE(c.engine_impacts, 3);
}

}  // namespace
}  // namespace vssw::compare

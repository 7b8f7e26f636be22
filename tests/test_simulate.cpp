// Event-driven simulation: balance laws (energy, angular momentum at impact), symmetry, the threshold found by
// bisection on simulations, size invariance, the paper's Fig. 6 and Sect. 5 statements, rest and overturning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/simulate.hpp"
#include "analytic/validity.hpp"
#include "tests/table1.hpp"

namespace vssw {
namespace {

using testing::table1;

// rtol 1e-10 per step accumulates over 1e3-1e4 steps; observed drifts are ~1e-9 to ~1e-8 of V_r: 10x headroom.
constexpr double kEnergyBalance = 1e-7;
constexpr double kEventTimeMatch = 1e-9;   // two runs that must be mirror images: same steps up to round-off
constexpr double kThresholdBisection = 1e-7;  // relative bracket width the bisection below stops at
constexpr double kGravityInG = 9.81;
constexpr double kLiftOffTime = 1e-12;     // [s] the rest phase's bisection (event_time_tol 1e-13) and asin's rounding
constexpr double kWeightlessTime = 1e-11;  // [s] its bisection (1e-12) and the sine's rounding near the crossing
// [s] near the threshold the computed margin is 0 (or of either sign) over ~1e-9 s around the root: sin's slope there
// is small (cos(asin(1/1.0001)) = 0.014) and the margin is a difference of nearly equal terms.
constexpr double kNearThresholdLiftOff = 1e-8;

const std::string kRinaldi = std::string(VSSW_DATA_DIR) + "/NGA_no_1063_RRS228.AT2";

VsswGeometry fig6_vssw() { return make_vssw(4.0, 0.4, 0.7); }
ParapetGeometry fig6_parapet() { return make_parapet(4.0, 0.4); }

TEST(Simulate, FreeVibrationConservesEnergyBetweenImpactsAndDissipatesAllOfItAtImpacts) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.65, 0.3);
    const std::unique_ptr<RockingModel> models[] = {make_vssw_model(w, Kinematics::paper),
                                                    make_vssw_model(w, Kinematics::exact),
                                                    make_parapet_model(make_parapet(4.0, 0.4, 0.3))};
    for (const auto& m : models) {
        SCOPED_TRACE(m->name());
        const double theta0 = 0.8 * m->reference_angle();
        const SimulationResult r = free_vibration(*m, theta0);
        EXPECT_LT(r.energy_balance_error, kEnergyBalance);
        EXPECT_TRUE(r.at_rest_at_end);
        ASSERT_FALSE(r.samples.empty());
        // At rest, everything the wall had (its potential energy at release) has been dissipated.
        EXPECT_NEAR(r.samples.back().dissipated, m->potential(theta0), kEnergyBalance * m->reference_energy());
    }
}

// largest_rotation: the one rule for a run's peak (history's t_max_theta, the analytic backend's located peak).
TEST(Simulate, LargestRotationIsTheLargestTurningPointTheOverturningOrTheEndOfACutSwing) {
    const auto m = make_vssw_model(fig6_vssw(), Kinematics::paper);
    const double alpha = m->reference_angle();
    // Released from rest: the release is the largest turning point (impacts only take energy away).
    const SimulationResult released = free_vibration(*m, 0.5 * alpha);
    EXPECT_EQ(largest_rotation(released).t, 0.0);
    EXPECT_EQ(largest_rotation(released).abs_theta, 0.5 * alpha);
    // Launched from theta1 = 0 and cut off while still rising: no turning point, the largest rotation is at the end.
    SimulationOptions cut;
    cut.t_end = 0.05;
    const SimulationResult rising = simulate(*m, GroundMotion::none(), GroundMotion::none(), {0.0, 0.2}, cut);
    ASSERT_TRUE(rising.peaks.empty());
    ASSERT_GT(rising.max_abs_theta, 0.0);
    EXPECT_EQ(largest_rotation(rising).t, rising.t_final);
    EXPECT_EQ(largest_rotation(rising).abs_theta, rising.max_abs_theta);
    // The same launch run past its turning point: that point, not the end.
    cut.t_end = 2.0;
    const SimulationResult turned = simulate(*m, GroundMotion::none(), GroundMotion::none(), {0.0, 0.2}, cut);
    ASSERT_FALSE(turned.peaks.empty());
    EXPECT_EQ(largest_rotation(turned).t, turned.peaks.front().t);
    // Started moving inwards from 0.5 alpha1: the start is no turning point, but it is the largest rotation (the
    // little kinetic energy added is less than the first impact takes).
    cut.t_end = 2.0;
    const SimulationResult inwards = simulate(*m, GroundMotion::none(), GroundMotion::none(), {0.5 * alpha, -0.05}, cut);
    EXPECT_EQ(largest_rotation(inwards).t, 0.0);
    EXPECT_EQ(largest_rotation(inwards).abs_theta, 0.5 * alpha);
    // Past the collapse angle: the overturning.
    const SimulationResult fell = free_vibration(*m, 0.99 * m->collapse_angle());
    ASSERT_TRUE(fell.overturned);
    EXPECT_EQ(largest_rotation(fell).t, fell.t_overturn);
}

TEST(Simulate, PeaksEitherSideOfAnImpactGiveTheRestitutionBack) {
    // Between impacts energy is conserved, so the peaks either side of an impact give e back by energy.
    constexpr double kPeakBased = 1e-7;  // peaks located on the dense output at rtol 1e-10
    const VsswGeometry w = make_vssw(table1(18), 0.1);
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(w, k);
        const SimulationResult r = free_vibration(*m, 0.8 * w.alpha1);
        for (std::size_t i = 0; i + 1 < 6; ++i)
            EXPECT_NEAR(restitution_from_peaks(*m, r.peaks[i].theta, r.peaks[i + 1].theta), m->restitution(), kPeakBased);
    }
}

TEST(Simulate, Eq23AsPrintedIsOffByTheChangeOfCAAcrossTheImpact) {
    // Eq. (23) evaluates C_A at the peaks, not at rest where the velocities are compared: its error is of the order
    // of the relative change of C_A between the two peaks, and vanishes as they approach each other.
    const VsswGeometry w = make_vssw(table1(18));
    const auto m = make_vssw_model(w, Kinematics::paper);
    const SimulationResult r = free_vibration(*m, 0.8 * w.alpha1);
    for (std::size_t i = 0; i + 1 < 6; ++i) {
        const double ca_before = eq11_coefficients(w, std::abs(r.peaks[i].theta)).C_A;
        const double ca_after = eq11_coefficients(w, std::abs(r.peaks[i + 1].theta)).C_A;
        const double printed = eq23_restitution_from_amplitudes(w, r.peaks[i].theta, r.peaks[i + 1].theta);
        EXPECT_NEAR(printed, eq19_restitution(w), std::abs(ca_before / ca_after - 1.0));
    }
}

TEST(Simulate, Eq25CountsTheEnergyLostAtTheImpacts) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::paper);
    const SimulationResult r = free_vibration(*m, 0.5 * w.alpha1);
    double sum_sq = 0.0;
    for (const Impact& i : r.impacts) sum_sq += i.theta_dot_before * i.theta_dot_before;
    // The simulation also dissipates the closed-form tail below rest_amplitude: its share is ~1e-6 of V_r.
    const double tail_share = 1e-5 * m->reference_energy();
    EXPECT_NEAR(eq25_dissipated_energy(w, sum_sq), r.samples.back().dissipated, tail_share);
}

TEST(Simulate, MirrorImageReleaseGivesMirrorImageMotion) {
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(make_vssw(4.0, 0.4, 0.6, 0.1), k);
        const double theta0 = 0.6 * m->reference_angle();
        const SimulationResult plus = free_vibration(*m, theta0), minus = free_vibration(*m, -theta0);
        ASSERT_EQ(plus.impacts.size(), minus.impacts.size());
        for (std::size_t i = 0; i < plus.impacts.size(); ++i) {
            EXPECT_NEAR(plus.impacts[i].t, minus.impacts[i].t, kEventTimeMatch);
            EXPECT_NEAR(plus.impacts[i].theta_dot_before, -minus.impacts[i].theta_dot_before, kEventTimeMatch);
        }
    }
}

TEST(Simulate, ReversedRecordGivesMirrorImageResponse) {
    const auto m = make_vssw_model(make_vssw(table1(18), 0.1), Kinematics::exact);
    const GroundMotion record = read_record(kRinaldi).scaled(0.25);  // rocks through the whole record, no fall
    SimulationOptions o;
    o.t_end = 25.0;
    const SimulationResult a = simulate(*m, record, GroundMotion::none(), {}, o);
    const SimulationResult b = simulate(*m, record.scaled(-1.0), GroundMotion::none(), {}, o);
    ASSERT_GT(a.impacts.size(), 0u);
    ASSERT_FALSE(a.overturned);
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) EXPECT_NEAR(a.samples[i].theta, -b.samples[i].theta, 1e-12);
    EXPECT_LT(a.energy_balance_error, kEnergyBalance);
}

// Does a constant horizontal ground acceleration (in g) move the wall off rest within half a second?
bool lifts(const RockingModel& m, double a_g, const GroundMotion& vertical = GroundMotion::none()) {
    SimulationOptions o;
    o.t_end = 0.5;
    o.keep_samples = false;
    const SimulationResult r = simulate(m, constant_motion(a_g * kGravityInG, 1.0), vertical, {}, o);
    return r.max_abs_theta > 0.0;
}

double threshold_by_bisection(const RockingModel& m, const GroundMotion& vertical = GroundMotion::none()) {
    double lo = 0.0, hi = 2.0;  // in g; every wall here tips under 2 g
    while (hi - lo > kThresholdBisection * hi) {
        const double mid = 0.5 * (lo + hi);
        (lifts(m, mid, vertical) ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

TEST(Simulate, ThresholdFoundBySimulationIsEq12) {
    for (double xi : {0.0, 0.1, 0.5}) {
        const Specimen& t1 = table1(2);
        const VsswGeometry w = make_vssw(t1.height, t1.thickness, t1.hinge_ratio, xi, kDefaultDensity, kGravityInG);
        const auto m = make_vssw_model(w, Kinematics::exact);
        EXPECT_NEAR(threshold_by_bisection(*m), eq12_threshold(w) / kGravityInG,
                    2.0 * kThresholdBisection * eq12_threshold(w) / kGravityInG);
    }
    const ParapetGeometry p = make_parapet(0.9, 0.11, 0.2, kDefaultDensity, kGravityInG);
    EXPECT_NEAR(threshold_by_bisection(*make_parapet_model(p)), eq17_parapet_threshold(p) / kGravityInG,
                2.0 * kThresholdBisection);
}

TEST(Simulate, UpwardGroundAccelerationRaisesTheThresholdAsEq12Says) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.6, 0.1, kDefaultDensity, kGravityInG);
    const auto m = make_vssw_model(w, Kinematics::paper);
    const double a_v = 0.3 * kGravityInG;
    EXPECT_NEAR(threshold_by_bisection(*m, constant_motion(a_v, 1.0)), eq12_threshold(w, a_v) / kGravityInG,
                2.0 * kThresholdBisection);
}

TEST(Simulate, ThresholdDoesNotDependOnSize) {
    const double reference = threshold_by_bisection(*make_vssw_model(make_vssw(4.0, 0.4, 0.7, 0.1), Kinematics::exact));
    for (double scale : {0.3, 5.0}) {
        const auto m = make_vssw_model(make_vssw(4.0 * scale, 0.4 * scale, 0.7, 0.1), Kinematics::exact);
        EXPECT_NEAR(threshold_by_bisection(*m), reference, 2.0 * kThresholdBisection * reference);
    }
}

TEST(Simulate, JustBelowTheThresholdNothingMovesAndJustAboveTheWallRocks) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::paper);
    const double threshold_g = eq12_threshold(w) / w.g;
    EXPECT_FALSE(lifts(*m, threshold_g * (1.0 - 1e-6)));
    EXPECT_TRUE(lifts(*m, threshold_g * (1.0 + 1e-6)));
}

TEST(Simulate, Fig6VsswStopsInLessThanAQuarterOfTheParapetsTime) {
    const VsswGeometry w = fig6_vssw();
    const ParapetGeometry p = fig6_parapet();
    const SimulationResult vssw = free_vibration(*make_vssw_model(w, Kinematics::paper), 0.9 * w.alpha1);
    const SimulationResult pw = free_vibration(*make_parapet_model(p), 0.9 * p.alpha);
    ASSERT_FALSE(vssw.rest_times.empty());
    ASSERT_FALSE(pw.rest_times.empty());
    EXPECT_LT(vssw.rest_times.back(), 0.25 * pw.rest_times.back());
}

TEST(Simulate, ImpactsAccumulateAndTheWallStopsAtAFiniteTime) {
    const auto m = make_vssw_model(fig6_vssw(), Kinematics::exact);
    const SimulationResult r = free_vibration(*m, 0.3 * fig6_vssw().alpha1);
    ASSERT_EQ(r.rest_times.size(), 1u);
    ASSERT_FALSE(r.impacts.empty());
    // Flight times shrink geometrically (by e per impact); the closed-form tail after the last one is short.
    const std::size_t n = r.impacts.size();
    const double last_gap = r.impacts[n - 1].t - r.impacts[n - 2].t;
    EXPECT_LT(r.rest_times[0] - r.impacts[n - 1].t, last_gap / (1.0 - m->restitution()));
    EXPECT_GT(r.rest_times[0], r.impacts[n - 1].t);
    EXPECT_LT(n, 1000u);
    for (std::size_t i = 2; i < n; ++i) EXPECT_LT(r.impacts[i].t - r.impacts[i - 1].t, r.impacts[i - 1].t - r.impacts[i - 2].t);
}

TEST(Simulate, PaperAndExactKinematicsGiveTheSameMotionAtMidHeightHinge) {
    const VsswGeometry w = make_vssw(3.05, 0.194, 0.5, 0.1);
    const SimulationResult p = free_vibration(*make_vssw_model(w, Kinematics::paper), 0.7 * w.alpha1);
    const SimulationResult e = free_vibration(*make_vssw_model(w, Kinematics::exact), 0.7 * w.alpha1);
    ASSERT_EQ(p.impacts.size(), e.impacts.size());
    for (std::size_t i = 0; i < p.impacts.size(); ++i) EXPECT_NEAR(p.impacts[i].t, e.impacts[i].t, kEventTimeMatch);
}

TEST(Simulate, ReleasedPastTheUnstableEquilibriumTheWallFalls) {
    const VsswGeometry w = fig6_vssw();
    const ParapetGeometry p = fig6_parapet();
    const std::unique_ptr<RockingModel> models[] = {make_vssw_model(w, Kinematics::paper),
                                                    make_vssw_model(w, Kinematics::exact), make_parapet_model(p)};
    for (const auto& m : models) {
        SCOPED_TRACE(m->name());
        const SimulationResult falls = free_vibration(*m, 1.02 * m->reference_angle());
        EXPECT_TRUE(falls.overturned);
        EXPECT_GT(falls.t_overturn, 0.0);
        EXPECT_LT(falls.energy_balance_error, kEnergyBalance);
        EXPECT_FALSE(free_vibration(*m, 0.98 * m->reference_angle()).overturned);
    }
}

TEST(Simulate, ReleaseBeyondTheCollapseAngleIsBadInput) {
    const auto m = make_vssw_model(fig6_vssw(), Kinematics::exact);
    EXPECT_THROW(free_vibration(*m, 1.01 * m->collapse_angle()), InputError);
    EXPECT_THROW(free_vibration(*m, std::nan("")), InputError);
}

TEST(Simulate, PulseAboveTheThresholdRocksTheWallWhichThenComesBackToRest) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::exact);
    const GroundMotion pulse = sine_pulse(1.5 * eq12_threshold(w), 0.5);
    SimulationOptions o;
    o.t_end = 60.0;
    const SimulationResult r = simulate(*m, pulse, GroundMotion::none(), {}, o);
    EXPECT_EQ(r.lift_offs.size(), 1u);
    EXPECT_GT(r.lift_offs[0], 0.0);
    EXPECT_FALSE(r.overturned);
    EXPECT_TRUE(r.at_rest_at_end);
    EXPECT_LT(r.energy_balance_error, kEnergyBalance);
}

// At rest the wall lifts at the first instant the ground acceleration passes Eq. (12)'s threshold, however briefly:
// under a_p sin(w t) with a_p above it, at asin(threshold / a_p) / w. A 2 ms harmonic was once looked at every 1 ms,
// on its zeros, and never lifted the wall (exit 0, at rest, 0.5 g against a 0.29 g threshold).
TEST(Simulate, TheWallLiftsWhereEq12SaysUnderAFastHarmonicAndJustAboveTheThreshold) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::paper);
    for (double period : {2e-3, 1e-3, 0.5}) {
        const double ap = 0.5 * kGravityInG, omega = 2.0 * 3.141592653589793 / period;
        SimulationOptions o;
        o.t_end = 2.0 * period;  // a second of shaking (the rest phase's fallback scan step 1 ms), two periods run
        const SimulationResult r = simulate(*m, harmonic(ap, period, 1.0), GroundMotion::none(), {}, o);
        ASSERT_FALSE(r.lift_offs.empty()) << "period " << period;
        EXPECT_NEAR(r.lift_offs[0], std::asin(eq12_threshold(w) / ap) / omega, kLiftOffTime) << "period " << period;
    }
    // Just above the threshold the margin is exactly 0 over many ulps around its root: the search once stopped on
    // such a zero and the wall lifted at the next look, 0.6 ms late at 1.01 times the threshold.
    for (double ratio : {1.01, 1.001, 1.0001}) {
        const double period = 0.05, omega = 2.0 * 3.141592653589793 / period, ap = ratio * eq12_threshold(w);
        SimulationOptions o;
        o.t_end = period;
        const SimulationResult r = simulate(*m, sine_pulse(ap, period), GroundMotion::none(), {}, o);
        ASSERT_FALSE(r.lift_offs.empty()) << ratio;
        EXPECT_NEAR(r.lift_offs[0], std::asin(1.0 / ratio) / omega, kNearThresholdLiftOff) << ratio;
    }
}

// g + a_v <= 0: the weight points up and the wall would leave the ground, at rest or rocking. Said, with the first
// instant (linear between a record's samples): here half way down a ramp from 0 to -2 g.
TEST(Simulate, AVerticalAccelerationThatCancelsGravityIsSaid) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::paper);
    SimulationOptions o;
    o.t_end = 3.0;
    const GroundMotion up = GroundMotion::sampled({0.0, 1.0, 2.0}, {0.0, -2.0 * w.g, 0.0}, "up");
    const SimulationResult r = simulate(*m, GroundMotion::none(), up, {}, o);
    ASSERT_TRUE(r.weightless_at.has_value());
    EXPECT_NEAR(*r.weightless_at, 0.5, kWeightlessTime);
    const std::vector<std::string> said = validity_warnings(*m, Kinematics::paper, r);
    EXPECT_TRUE(std::any_of(said.begin(), said.end(),
                            [](const std::string& s) { return s.find("cancels gravity at t = 0.5 s") != s.npos; }));
    // Cut off before the sample below -g: the run's end is a look too (0.9 s, past the crossing at 0.5 s).
    o.t_end = 0.9;
    const SimulationResult cut = simulate(*m, GroundMotion::none(), up, {}, o);
    ASSERT_TRUE(cut.weightless_at.has_value());
    EXPECT_NEAR(*cut.weightless_at, 0.5, kWeightlessTime);
    o.t_end = 3.0;
    // Down to -0.9 g only: never weightless, nothing said.
    const GroundMotion light = GroundMotion::sampled({0.0, 1.0, 2.0}, {0.0, -0.9 * w.g, 0.0}, "light");
    EXPECT_FALSE(simulate(*m, GroundMotion::none(), light, {}, o).weightless_at.has_value());
    // An analytic signal (looked at its extrema, then bisected): 1.5 g sin(2 pi t) first reaches -g at
    // t = 1/2 + asin(2/3) / (2 pi).
    const GroundMotion shaking = harmonic(1.5 * w.g, 1.0, 2.0);
    const SimulationResult h = simulate(*m, GroundMotion::none(), shaking, {}, o);
    ASSERT_TRUE(h.weightless_at.has_value());
    EXPECT_NEAR(*h.weightless_at, 0.5 + std::asin(2.0 / 3.0) / (2.0 * 3.141592653589793), kWeightlessTime);
}

TEST(Simulate, StrongPulseOverturnsTheWall) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::paper);
    const SimulationResult r =
        simulate(*m, sine_pulse(8.0 * eq12_threshold(w), 1.5), GroundMotion::none(), {}, SimulationOptions{});
    EXPECT_TRUE(r.overturned);
    constexpr double kCollapseLocated = 1e-9;  // [rad] the overturning is an event located like an impact
    EXPECT_NEAR(std::abs(r.samples.back().theta), m->collapse_angle(), kCollapseLocated);
}

TEST(Simulate, EnergyBalanceClosesUnderTheRinaldiRecordWithOverburdenAndVerticalShaking) {
    const GroundMotion record = read_record(kRinaldi).scaled(0.25);  // rocks through the whole record, no fall
    const GroundMotion vertical = harmonic(0.05 * kGravityInG, 0.3, 15.0);  // with the 0.25 record: ~100 impacts, no fall
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(make_vssw(table1(18), 0.1), k);
        SimulationOptions o;
        o.t_end = 25.0;
        o.output_dt = 0.01;
        const SimulationResult r = simulate(*m, record, vertical, {}, o);
        EXPECT_GT(r.impacts.size(), 3u);
        ASSERT_FALSE(r.overturned);
        EXPECT_LT(r.energy_balance_error, kEnergyBalance);
        // The same balance on the output grid, relative to V_r alone (the reported error divides by the largest
        // energy in play, which under a record can be many V_r).
        const Sample& s0 = r.samples.front();
        const double e0 = s0.kinetic + s0.weight_potential - s0.work_overburden - s0.work_ground + s0.dissipated;
        double worst = 0.0;
        for (const Sample& s : r.samples)
            worst = std::max(worst, std::abs(s.kinetic + s.weight_potential - s.work_overburden - s.work_ground +
                                             s.dissipated - e0));
        EXPECT_LT(worst / m->reference_energy(), kEnergyBalance);
        // the output grid is honoured
        ASSERT_GT(r.samples.size(), 100u);
        EXPECT_NEAR(r.samples[100].t, 1.0, 1e-12);
    }
}

TEST(Simulate, OutputGridHasNoGapsAcrossRestAndTheSummedTailOfImpacts) {
    const VsswGeometry w = fig6_vssw();
    const auto m = make_vssw_model(w, Kinematics::paper);
    SimulationOptions o;
    o.output_dt = 0.01;
    o.t_end = 20.0;
    o.stop_at_rest = false;
    const SimulationResult r =
        simulate(*m, read_record(kRinaldi).scaled_to_pga(0.3 * kStandardGravity), GroundMotion::none(), {}, o);
    ASSERT_FALSE(r.rest_times.empty());  // it comes to rest at least once, through a summed tail
    ASSERT_EQ(r.samples.size(), 2001u);
    for (std::size_t i = 0; i < r.samples.size(); ++i)
        EXPECT_NEAR(r.samples[i].t, 0.01 * static_cast<double>(i), kEventTimeMatch);  // i dt: round-off only
}

TEST(Simulate, VsswDampsMoreThanTheParapetLikeSection5Says) {
    // Sect. 5: equivalent viscous damping from the logarithmic decrement over four cycles (eight half-cycles) after
    // release at theta0/alpha = 0.7, for Lam's parapet and Doherty's VSSW. See docs/model/paper.md ("§5 damping") for
    // the values.
    auto zeta = [](const RockingModel& m) {
        const SimulationResult r = free_vibration(m, 0.7 * m.reference_angle());
        const double delta = std::log(std::abs(r.peaks.at(0).theta) / std::abs(r.peaks.at(8).theta)) / 4.0;
        return delta / std::sqrt(4.0 * M_PI * M_PI + delta * delta);
    };
    const double pw = zeta(*make_parapet_model(make_parapet(0.9, 0.11)));
    const double vssw = zeta(*make_vssw_model(make_vssw(1.5, 0.11, 0.5), Kinematics::paper));
    EXPECT_GT(vssw, 1.5 * pw);
}

// The accuracy goal (docs/contributing/analytic-speed.md) for the default tolerance: impact times within 1e-8 s of a
// run at rtol 1e-14 (measured: 1.2e-9 s paper, 1.6e-9 s exact kinematics over Fig. 6's 130 impacts; rtol 1e-9 gives
// 1.0e-8 and 1.3e-8, so a looser default would fail here).
constexpr double kImpactTimeGoal = 1e-8;  // [s] the speed work's bound on impact times at the default tolerance
constexpr double kReferenceRtol = 1e-14;  // four orders tighter than the default: its own error is negligible here

void expect_impact_times_within_goal(const SimulationResult& run, const SimulationResult& reference) {
    ASSERT_EQ(run.impacts.size(), reference.impacts.size());
    ASSERT_GT(run.impacts.size(), 50u);
    double worst = 0.0;
    for (std::size_t i = 0; i < run.impacts.size(); ++i)
        worst = std::max(worst, std::abs(run.impacts[i].t - reference.impacts[i].t));
    EXPECT_LT(worst, kImpactTimeGoal);
}

TEST(Simulate, DefaultToleranceLocatesFig6ImpactsWithin1e8SecondsOfATightRun) {
    const VsswGeometry w = fig6_vssw();
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(w, k);
        SimulationOptions tight;
        tight.step.rtol = kReferenceRtol;
        expect_impact_times_within_goal(free_vibration(*m, 0.9 * w.alpha1), free_vibration(*m, 0.9 * w.alpha1, tight));
    }
}

// Under a record the steps are set by its 10 ms samples, not by the tolerance, and the predicted landings
// (kShortLandingSpan in analytic/simulate.cpp) place most impacts: measured within 1.9e-10 s (paper, 376 impacts) and
// 1.4e-10 s (exact, 99) of a tight run that searches every landing, at every rtol from 1e-9 to 1e-12 alike.
SimulationResult rinaldi_run(Kinematics k, double rtol, bool predict) {
    static const GroundMotion record = read_record(kRinaldi).scaled(0.25);  // rocks through the whole record
    const auto m = make_vssw_model(make_vssw(table1(18), 0.1), k);
    SimulationOptions o;
    o.t_end = record.duration();
    o.keep_samples = false;
    o.step.rtol = rtol;
    o.predict_landings = predict;
    return simulate(*m, record, GroundMotion::none(), {}, o);
}

TEST(Simulate, DefaultToleranceLocatesImpactsUnderARecordWithin1e8SecondsOfATightRun) {
    for (Kinematics k : {Kinematics::paper, Kinematics::exact})
        expect_impact_times_within_goal(rinaldi_run(k, SimulationOptions{}.step.rtol, true),
                                        rinaldi_run(k, kReferenceRtol, false));
}

// What the free-flight prediction rests on: the equation of motion is even in theta1' and has no time in it when the
// ground is still, so each flight from theta1 = 0 takes as long to fall from its turning point as it took to rise
// to it. Measured on a run that predicts nothing (every landing searched).
constexpr double kFlightSymmetry = 1e-9;  // [s] a run at rtol 1e-13 places its events to ~1e-11 s: 100x headroom

TEST(Simulate, FreeFlightsAreSymmetricAboutTheirTurningPoints) {
    const VsswGeometry w = fig6_vssw();
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(w, k);
        SimulationOptions tight;
        tight.step.rtol = 1e-13;
        tight.keep_samples = false;
        tight.predict_landings = false;
        const SimulationResult r = free_vibration(*m, 0.9 * w.alpha1, tight);
        ASSERT_GT(r.impacts.size(), 50u);
        int checked = 0;
        for (std::size_t i = 1; i < r.impacts.size(); ++i) {
            const double launch = r.impacts[i - 1].t, landing = r.impacts[i].t;
            for (const TurningPoint& p : r.peaks) {
                if (p.t <= launch || p.t >= landing) continue;
                EXPECT_NEAR(landing - p.t, p.t - launch, kFlightSymmetry) << "flight " << i;
                ++checked;
            }
        }
        EXPECT_EQ(checked, static_cast<int>(r.impacts.size()) - 1);  // one turning point per flight
    }
}

// Peaks of two runs whose impact times agree within kImpactTimeGoal: a flight launched a time dt later at the same
// speed v peaks v dt higher or lower at most (1e-9 rad for 0.1 rad/s over 1e-8 s); measured 1.1e-12 rad.
constexpr double kPeakMatch = 1e-9;  // [rad]
// Of the landings, the share the predictions must place, or they are not working: on Fig. 6 the symmetry needs two
// flights' history and a turning point first (85 of 130 placed); under the record the parabola places 374 of 376.
constexpr double kLeastPredictedFig6 = 0.5;
constexpr double kLeastPredictedUnderARecord = 0.9;

double searched_share(const SimulationResult& r) {
    return static_cast<double>(r.searched_events) / static_cast<double>(r.impacts.size());
}

// Landings placed by the predictions agree with landings found by search to the accuracy goal, both at the default
// tolerance: the free flights' symmetry over the 130 impacts of Fig. 6 (85 of them predicted), the parabola and the
// short Runge-Kutta steps under the Rinaldi record (paper: 374 of 376 impacts so placed, exact: all 99). Most landings
// must be predicted, or the predictions are not working.
TEST(Simulate, PredictedLandingsAreTheSearchedOnesWithinTheAccuracyGoal) {
    const VsswGeometry w = fig6_vssw();
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(w, k);
        SimulationOptions predicted, searched;
        predicted.keep_samples = searched.keep_samples = false;
        searched.predict_landings = false;
        const SimulationResult fast = free_vibration(*m, 0.9 * w.alpha1, predicted);
        const SimulationResult slow = free_vibration(*m, 0.9 * w.alpha1, searched);
        expect_impact_times_within_goal(fast, slow);
        EXPECT_EQ(slow.searched_events, static_cast<long>(slow.impacts.size()));
        EXPECT_LE(searched_share(fast), 1.0 - kLeastPredictedFig6);
    }
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const double rtol = SimulationOptions{}.step.rtol;
        const SimulationResult fast = rinaldi_run(k, rtol, true), slow = rinaldi_run(k, rtol, false);
        expect_impact_times_within_goal(fast, slow);
        EXPECT_LE(searched_share(fast), 1.0 - kLeastPredictedUnderARecord);
        EXPECT_EQ(fast.peaks.size(), slow.peaks.size());
        for (std::size_t i = 0; i < std::min(fast.peaks.size(), slow.peaks.size()); ++i)
            EXPECT_NEAR(fast.peaks[i].theta, slow.peaks[i].theta, kPeakMatch) << "peak " << i;
    }
}

// What a run reports besides the impacts is the same whether its landings were predicted or searched: the samples on
// the output grid (none missing, none past an impact that is not shown) and the supports' forces, whose extremes and
// first tension fall at impacts as often as not. Under the record at a 1 ms grid, and a sampled free vibration.
TEST(Simulate, PredictedLandingsReportTheSameSamplesAndSupportForces) {
    // Samples: two runs whose impact times agree within kImpactTimeGoal differ at a sample by theta1' dt at most (0.1
    // rad/s over 1e-8 s); measured 2.0e-12 rad.
    constexpr double kSampleMatch = 1e-9;  // [rad]
    // Support forces [N/m] and friction demands, relative: read at states that differ as much, 1e-7 of their size at
    // most; measured 4.7e-13. (A landing's forces read with theta1'' from the step's start were 1 % off.)
    constexpr double kForceMatch = 1e-6;
    const GroundMotion record = read_record(kRinaldi).scaled(0.25);
    const auto m = make_vssw_model(make_vssw(table1(18), 0.1), Kinematics::paper);
    SimulationOptions o;
    o.t_end = record.duration();
    o.output_dt = 1e-3;
    o.sample_energies = false;
    SimulationOptions searched = o;
    searched.predict_landings = false;
    const SimulationResult fast = simulate(*m, record, GroundMotion::none(), {}, o);
    const SimulationResult slow = simulate(*m, record, GroundMotion::none(), {}, searched);
    ASSERT_GT(fast.impacts.size(), 300u);
    EXPECT_LE(searched_share(fast), 1.0 - kLeastPredictedUnderARecord);
    ASSERT_EQ(fast.samples.size(), slow.samples.size());
    EXPECT_EQ(fast.samples.size(), static_cast<std::size_t>(std::llround(record.duration() / o.output_dt)) + 1);
    double worst = 0.0;
    for (std::size_t i = 0; i < fast.samples.size(); ++i) {
        EXPECT_EQ(fast.samples[i].t, slow.samples[i].t);
        worst = std::max(worst, std::abs(fast.samples[i].theta - slow.samples[i].theta));
    }
    EXPECT_LT(worst, kSampleMatch);
    const SupportDemand& a = fast.supports;
    const SupportDemand& b = slow.supports;
    EXPECT_NEAR(a.min_roller_reaction, b.min_roller_reaction, kForceMatch * std::abs(b.min_roller_reaction));
    EXPECT_NEAR(a.base_friction, b.base_friction, kForceMatch * b.base_friction);
    EXPECT_NEAR(a.hinge_friction, b.hinge_friction, kForceMatch * b.hinge_friction);
    EXPECT_EQ(a.roller_tension_at.has_value(), b.roller_tension_at.has_value());

    const VsswGeometry w = fig6_vssw();
    SimulationOptions free;
    free.output_dt = 1e-3;
    SimulationOptions free_searched = free;
    free_searched.predict_landings = false;
    const auto fig6 = make_vssw_model(w, Kinematics::paper);
    const SimulationResult f1 = free_vibration(*fig6, 0.9 * w.alpha1, free);
    const SimulationResult f2 = free_vibration(*fig6, 0.9 * w.alpha1, free_searched);
    ASSERT_EQ(f1.samples.size(), f2.samples.size());
    double worst_free = 0.0;
    for (std::size_t i = 0; i < f1.samples.size(); ++i)
        worst_free = std::max(worst_free, std::abs(f1.samples[i].theta - f2.samples[i].theta));
    EXPECT_LT(worst_free, kSampleMatch);
}

}  // namespace
}  // namespace vssw

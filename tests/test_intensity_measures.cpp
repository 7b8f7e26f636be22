// Intensity measures of a record (analytic/intensity_measures.hpp) against closed forms: the linear oscillator's
// response to a constant and a ramped load (Chopra, section 4.3 and 4.4) and its steady state under a harmonic at and
// off resonance, Sa -> PGA as the period -> 0, a hand-checked record, PGV of a sine pulse, Arias intensity of a sine,
// and how each measure scales with the record.
#include "analytic/intensity_measures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analytic/error.hpp"

namespace vssw {
namespace {

constexpr double kPi = 3.141592653589793;
// Rounding of a few thousand steps of a recurrence whose coefficients are exact to rounding.
constexpr double kRecurrenceRoundoff = 1e-10;
// A sine sampled 1000 times a period: the linear interpolation between samples lowers its amplitude by about
// (omega dt)^2 / 8 = 5e-6, and a peak read at the samples misses the true one by at most (omega dt)^2 / 2 = 2e-5.
constexpr double kFineSamplingTol = 1e-4;
// The trapezoidal velocity of a sine pulse sampled 1000 times: error (omega dt)^2 / 12 ~ 3e-6 of the peak.
constexpr double kTrapezoidTol = 1e-5;
// At T = 1e-5 s and 200 samples a second, each kink of the linear input excites the stiff oscillator by about
// 1 / (omega dt) = 3e-4 of the static response: Sa equals the PGA to that.
constexpr double kStiffOscillatorTol = 1e-3;

struct Samples {
    std::vector<double> t, a;
};

Samples sampled(double duration, double dt, double (*f)(double, double, double), double p1, double p2) {
    Samples s;
    const auto n = static_cast<std::size_t>(std::llround(duration / dt));
    for (std::size_t i = 0; i <= n; ++i) {
        s.t.push_back(static_cast<double>(i) * dt);
        s.a.push_back(f(s.t.back(), p1, p2));
    }
    return s;
}

double sine(double t, double amplitude, double period) { return amplitude * std::sin(2.0 * kPi * t / period); }
double constant(double, double amplitude, double) { return amplitude; }
double ramp(double t, double slope, double) { return slope * t; }

TEST(IntensityMeasures, OscillatorFollowsTheClosedFormsOfAConstantAndARampedLoad) {
    const double T = 0.8, zeta = 0.05, omega = 2.0 * kPi / T, k = omega * omega;
    const double wd = omega * std::sqrt(1.0 - zeta * zeta), r = zeta / std::sqrt(1.0 - zeta * zeta);
    const double a0 = 1.7, slope = 0.9;  // [m/s^2], [m/s^3]
    // u'' + 2 zeta omega u' + k u = p with p = -a: a step load p0 (Chopra Eq. 4.3.3) and a ramp p = s t (Eq. 4.4.3).
    const auto step = [&](double t) {
        return -a0 / k * (1.0 - std::exp(-zeta * omega * t) * (std::cos(wd * t) + r * std::sin(wd * t)));
    };
    const auto ramped = [&](double t) {
        return -slope / k *
               (t - 2.0 * zeta / omega +
                std::exp(-zeta * omega * t) * (2.0 * zeta / omega * std::cos(wd * t) -
                                               (1.0 - 2.0 * zeta * zeta) / wd * std::sin(wd * t)));
    };
    const Samples c = sampled(3.0, 0.01, constant, a0, 0.0);
    const Samples p = sampled(3.0, 0.01, ramp, slope, 0.0);
    const std::vector<double> uc = oscillator_displacement(c.t, c.a, T, zeta);
    const std::vector<double> up = oscillator_displacement(p.t, p.a, T, zeta);
    for (std::size_t i = 0; i < c.t.size(); i += 7) {
        EXPECT_NEAR(uc[i], step(c.t[i]), kRecurrenceRoundoff * a0 / k) << c.t[i];
        EXPECT_NEAR(up[i], ramped(p.t[i]), kRecurrenceRoundoff * slope * 3.0 / k) << p.t[i];
    }
}

// The steady-state amplitude of u under a = A sin(Omega t): A / omega^2 / sqrt((1 - b^2)^2 + (2 zeta b)^2), b =
// Omega / omega; read over the last periods of a record long enough for the start's transient to die out
// (e^(-zeta omega t) ~ 1e-8 after 60 s at T = 1 s).
TEST(IntensityMeasures, HarmonicSteadyStateAtAndOffResonance) {
    const double T = 1.0, zeta = 0.05, omega = 2.0 * kPi / T, A = 2.0;
    for (const double b : {1.0, 0.5, 2.0}) {
        const double period = T / b;
        const Samples s = sampled(60.0, period / 1000.0, sine, A, period);
        const std::vector<double> u = oscillator_displacement(s.t, s.a, T, zeta);
        double late = 0.0;
        for (std::size_t i = 0; i < u.size(); ++i)
            if (s.t[i] > 60.0 - 3.0 * std::max(T, period)) late = std::max(late, std::abs(u[i]));
        const double expected = A / (omega * omega) / std::hypot(1.0 - b * b, 2.0 * zeta * b);
        EXPECT_NEAR(late / expected, 1.0, kFineSamplingTol) << "Omega / omega = " << b;
        if (b == 1.0) {  // from rest at resonance the amplitude grows towards A / (2 zeta) and never passes it
            EXPECT_NEAR(spectral_acceleration(s.t, s.a, T, zeta) / (A / (2.0 * zeta)), 1.0, kFineSamplingTol);
        }
    }
}

TEST(IntensityMeasures, SaTendsToThePgaAsThePeriodVanishes) {
    const Samples s = sampled(4.0, 0.005, sine, 3.0, 0.7);
    double pga = 0.0;
    for (double a : s.a) pga = std::max(pga, std::abs(a));
    EXPECT_NEAR(spectral_acceleration(s.t, s.a, 1e-5, 0.05) / pga, 1.0, kStiffOscillatorTol);
    // And far from it at a period near the input's.
    EXPECT_GT(spectral_acceleration(s.t, s.a, 0.7, 0.05) / pga, 1.5);
}

// By hand: a constant a0 for a quarter period, undamped. u = -(a0 / omega^2)(1 - cos omega t) reaches -a0 / omega^2
// with velocity -a0 / omega as the record ends; the free vibration then swings to sqrt(u^2 + (v / omega)^2) =
// sqrt(2) a0 / omega^2, so Sa = sqrt(2) a0: the peak after the record counts.
TEST(IntensityMeasures, HandCheckedRecordPeaksInTheFreeVibrationAfterIt) {
    const double T = 2.0, a0 = 1.5;
    const std::vector<double> t = {0.0, T / 4.0}, a = {a0, a0};
    EXPECT_NEAR(spectral_acceleration(t, a, T, 0.0), std::sqrt(2.0) * a0, kRecurrenceRoundoff * a0);
    // Half a period: u swings to -2 a0 / omega^2 at the end, at rest there; Sa = 2 a0.
    const std::vector<double> t2 = {0.0, T / 2.0};
    EXPECT_NEAR(spectral_acceleration(t2, a, T, 0.0), 2.0 * a0, kRecurrenceRoundoff * a0);
}

TEST(IntensityMeasures, PgvOfASinePulseIsItsAnalyticVelocity) {
    // a = A sin(2 pi t / Tp) on [0, Tp]: v = A Tp / (2 pi) (1 - cos(2 pi t / Tp)), largest A Tp / pi at Tp / 2.
    // Either sign: the PGV is the largest |v|.
    const double Tp = 0.5;
    for (const double A : {4.0, -4.0}) {
        const Samples s = sampled(Tp, Tp / 1000.0, sine, A, Tp);
        EXPECT_NEAR(peak_ground_velocity(s.t, s.a) / (std::abs(A) * Tp / kPi), 1.0, kTrapezoidTol) << A;
    }
}

TEST(IntensityMeasures, AriasIntensityOfASine) {
    // Over whole periods the mean of sin^2 is 1/2 (the trapezoidal sum of a periodic function is exact there):
    // I_a = pi / (2 g0) A^2 D / 2.
    const double A = 3.0, Tp = 0.4, D = 8.0;
    const Samples s = sampled(D, Tp / 40.0, sine, A, Tp);
    EXPECT_NEAR(arias_intensity(s.t, s.a) / (kPi / (2.0 * kStandardGravity) * A * A * D / 2.0), 1.0,
                kRecurrenceRoundoff);
}

TEST(IntensityMeasures, EachMeasureScalesWithTheRecordTheAriasIntensityAsItsSquare) {
    const Samples s = sampled(5.0, 0.01, sine, 2.0, 0.6);
    const GroundMotion record = GroundMotion::sampled(s.t, s.a, "sine");
    const double factor = 2.5;
    for (const IntensityMeasure m :
         {IntensityMeasure::pga, IntensityMeasure::pgv, IntensityMeasure::sa, IntensityMeasure::arias}) {
        const Intensity im{m, 0.5, 0.05};
        const double one = record_intensity(record, im);
        const double scaled = record_intensity(record.scaled(factor), im);
        EXPECT_NEAR(scaled / intensity_at_scale(m, one, factor), 1.0, kRecurrenceRoundoff) << to_string(m);
        EXPECT_NEAR(scale_to_intensity(m, one, scaled) / factor, 1.0, kRecurrenceRoundoff) << to_string(m);
    }
    EXPECT_NEAR(record_intensity(record.scaled(factor), {IntensityMeasure::arias, 0.0, 0.05}) /
                    record_intensity(record, {IntensityMeasure::arias, 0.0, 0.05}),
                factor * factor, kRecurrenceRoundoff);
}

TEST(IntensityMeasures, RefusesWhatItCannotMeasure) {
    const std::vector<double> t = {0.0, 0.01, 0.02}, a = {0.0, 1.0, 0.0};
    EXPECT_THROW(spectral_acceleration(t, a, 0.0, 0.05), InputError);
    EXPECT_THROW(spectral_acceleration(t, a, 1.0, 1.0), InputError);
    EXPECT_THROW(spectral_acceleration(t, a, 1.0, -0.1), InputError);
    EXPECT_THROW(peak_ground_velocity({0.0, 0.0}, {1.0, 1.0}), InputError);
    EXPECT_THROW(record_intensity(sine_pulse(1.0, 0.5), {IntensityMeasure::pgv, 0.0, 0.05}), InputError);
    EXPECT_THROW(parse_intensity_measure("pgd"), InputError);
    EXPECT_EQ(parse_intensity_measure("sa"), IntensityMeasure::sa);
    EXPECT_EQ(intensity_label({IntensityMeasure::sa, 1.0, 0.05}), "Sa(1 s, 5 %) [g]");
}

}  // namespace
}  // namespace vssw

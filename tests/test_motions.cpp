// The ground motions of motions/: the measures against closed forms, the generator's statistics against the model's
// targets, the parameter draws against their distributions' moments, reproducibility and the AT2 round trip.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "motions/at2_writer.hpp"
#include "motions/measures.hpp"
#include "motions/motion_set.hpp"
#include "motions/parameter_draws.hpp"
#include "motions/stochastic.hpp"
#include "tests/temp_files.hpp"

namespace {

using namespace vssw::motions;
using vssw::kStandardGravity;

// The trapezoidal rule is exact, to rounding, for a trigonometric polynomial over whole periods sampled more than
// twice a period: sin^2 over 10 cycles at 1000 samples a cycle.
constexpr double kExactToRounding = 1e-12;
// The trapezoidal velocity of a sine has the relative error (w dt)^2 / 12 = 3.3e-6 at w dt = 2 pi / 1000; a bound.
constexpr double kTrapezoidVelocity = 1e-5;
// Crossing times interpolated linearly: a crossing of the Husid curve is off by at most one sample step.
constexpr double kOneStep = 1.0;
// A sine's zero crossings interpolated linearly: the curve is straight there to third order in w dt (1e-7 here).
constexpr double kCrossingRate = 1e-6;
// Means over many draws: within this many standard errors of the expected value (a 4-sigma miss happens once in
// 16,000 runs of a test with a fixed seed: never, since the seeds are fixed, unless the code changes).
constexpr double kSigmas = 4.0;

struct Sine {
    double amplitude = 2.0, frequency = 1.0, dt = 0.001;
    int cycles = 10;  // a multiple of 5: sin(4 pi f t) vanishes at 5 %, 45 % and 95 % of the record
    double length() const { return cycles / frequency; }
    std::vector<double> samples() const {
        const auto n = static_cast<std::size_t>(std::llround(length() / dt)) + 1;
        std::vector<double> a(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = amplitude * std::sin(2 * M_PI * frequency * static_cast<double>(i) * dt);
        return a;
    }
};

TEST(Measures, SineMatchesClosedForms) {
    const Sine s;
    const Measures m = measure_uniform(s.samples(), s.dt);
    const double T = s.length();
    // I_a = pi/(2g) * A^2 T / 2: the mean of sin^2 over whole cycles is 1/2.
    EXPECT_NEAR(m.arias_m_s / (M_PI / (2 * kStandardGravity) * s.amplitude * s.amplitude * T / 2), 1.0, kExactToRounding);
    // v(t) = A/(2 pi f) (1 - cos 2 pi f t) from rest: from 0 to 2A/(2 pi f) = A/(pi f) at every half cycle.
    EXPECT_NEAR(m.pgv_m_s / (s.amplitude / (M_PI * s.frequency)), 1.0, kTrapezoidVelocity);
    EXPECT_NEAR(m.pga_g, s.amplitude / kStandardGravity, 1e-12);
    // Husid H(t) = t/T - sin(4 pi f t)/(4 pi f T): with 10 cycles the sine term vanishes at 0.05 T, 0.45 T, 0.95 T.
    EXPECT_NEAR(m.d5_95_s, 0.9 * T, kOneStep * s.dt);
    EXPECT_NEAR(m.t_mid_s, 0.45 * T, kOneStep * s.dt);
    // Up-crossings at whole periods: the rate is f.
    EXPECT_NEAR(m.mid_frequency_hz / s.frequency, 1.0, kCrossingRate);
    EXPECT_NEAR(m.duration_s, T, 1e-9);
    EXPECT_NEAR(m.dt_s, s.dt, 1e-12);
}

TEST(Measures, ConstantAccelerationMatchesClosedForms) {
    const double c = 0.5, dt = 0.01, T = 20.0;
    const std::vector<double> a(static_cast<std::size_t>(std::llround(T / dt)) + 1, c);
    const Measures m = measure_uniform(a, dt);
    EXPECT_NEAR(m.arias_m_s / (M_PI / (2 * kStandardGravity) * c * c * T), 1.0, kExactToRounding);
    EXPECT_NEAR(m.pgv_m_s / (c * T), 1.0, kExactToRounding);  // v = c t, exact for the trapezoid
    EXPECT_NEAR(m.d5_95_s, 0.9 * T, 1e-9);                     // H(t) = t / T: linear, so interpolation is exact
    EXPECT_NEAR(m.t_mid_s, 0.45 * T, 1e-9);
    EXPECT_TRUE(std::isnan(m.mid_frequency_hz));  // no zero crossing
}

TEST(Measures, SilentRecordHasNoDuration) {
    const Measures m = measure_uniform(std::vector<double>(100, 0.0), 0.01);
    EXPECT_EQ(m.arias_m_s, 0.0);
    EXPECT_TRUE(std::isnan(m.d5_95_s));
    EXPECT_THROW(measure_uniform({1.0}, 0.01), vssw::InputError);
}

// The gamma modulation solved from (I_a, D5-95, t_mid): its q(t)^2, sampled finely and measured as a record, has
// them. q^2 measured as a^2 = q^2 (a = q).
TEST(Stochastic, ModulationHasItsTargets) {
    const double arias = 0.8, d = 12.0, tmid = 7.0, dt = 0.001;
    const auto q = modulation_for(arias, d, tmid);
    ASSERT_TRUE(q.has_value());
    std::vector<double> a;
    for (double t = 0; t < q->energy_time(1.0 - 1e-12); t += dt) a.push_back((*q)(t));
    const Measures m = measure_uniform(a, dt);
    // The tail cut at 1 - 1e-12 of the energy and the trapezoid of a smooth curve at 1 ms: far below 1e-5.
    constexpr double kQuadrature = 1e-5;
    EXPECT_NEAR(m.arias_m_s / arias, 1.0, kQuadrature);
    EXPECT_NEAR(m.d5_95_s, d, kOneStep * dt);
    EXPECT_NEAR(m.t_mid_s, tmid, kOneStep * dt);
    // D5-95 above 4.92 t_mid needs alpha2 <= 1 (an exponential q^2 has (3.00 - 0.05) / 0.60 = 4.92): refused.
    EXPECT_FALSE(modulation_for(arias, 30.0, 5.0).has_value());
    EXPECT_TRUE(modulation_for(arias, 24.0, 5.0).has_value());
}

struct Spread {
    double mean = 0, sd = 0;
    explicit Spread(const std::vector<double>& x) {
        mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
        double ss = 0;
        for (double v : x) ss += (v - mean) * (v - mean);
        sd = std::sqrt(ss / static_cast<double>(x.size() - 1));
    }
    double standard_error(std::size_t n) const { return sd / std::sqrt(static_cast<double>(n)); }
};

// 200 motions of one parameter set: the measured I_a, D5-95 and mid frequency, averaged, against the model's
// targets. The filtered noise has unit variance, so E[I_a] is the target; the allowances below are the model's own
// departures, each far below what an error in the model (a wrong normalisation, a misplaced modulation, a filter at
// the wrong frequency) makes, which is tens of percent.
TEST(Stochastic, MeasuredMotionsMatchTheTargetsOnAverage) {
    const ModelParameters p{0.5, 15.0, 10.0, 5.0, 0.0, 0.2};
    SimulationSettings settings;
    settings.dt = 0.01;  // 20 samples a period at 5 Hz
    constexpr int kMotions = 200;
    // The high-pass filter removes the noise's power near and below f_c = 0.2 Hz ((f_c / f)^2 ~ 0.2 % of a 5 Hz
    // process, more of its low-frequency tail), and the record keeps 99.9 % of the modulation's energy: 2 % bounds
    // both.
    constexpr double kAriasBias = 0.02;
    // D5-95 and the up-crossing rate of one realization are ratios of random sums: their means differ from the
    // targets by O(1 / number of correlated cycles in the strong phase) ~ 1 / (15 s * 5 Hz * 2 pi zeta): ~1 %. And
    // the high-pass filter shifts crossings up by about (f_c / f)^2. 3 % bounds both.
    constexpr double kDurationBias = 0.03, kFrequencyBias = 0.03;
    std::vector<double> arias, duration, frequency;
    for (int k = 1; k <= kMotions; ++k) {
        RandomStream random(2024, static_cast<std::uint64_t>(k));
        const Measures m = measure_uniform(simulate(p, settings, random), settings.dt);
        arias.push_back(m.arias_m_s / p.arias_m_s);
        duration.push_back(m.d5_95_s / p.d5_95_s);
        frequency.push_back(m.mid_frequency_hz / p.mid_frequency_hz);
    }
    const Spread a(arias), d(duration), f(frequency);
    EXPECT_NEAR(a.mean, 1.0, kAriasBias + kSigmas * a.standard_error(kMotions)) << "sd " << a.sd;
    EXPECT_NEAR(d.mean, 1.0, kDurationBias + kSigmas * d.standard_error(kMotions)) << "sd " << d.sd;
    EXPECT_NEAR(f.mean, 1.0, kFrequencyBias + kSigmas * f.standard_error(kMotions)) << "sd " << f.sd;
}

// The draws without a site follow the published marginals: means and spreads of the parameters the rejection of
// D5-95 > 4.92 t_mid does not touch (it depends on D5-95 and t_mid only; the six are independent here).
TEST(ParameterDraws, MarginalsHaveTheirMoments) {
    constexpr int kDraws = 4000;
    const DrawSettings settings;
    std::vector<double> ln_arias, freq, damping;
    for (int k = 1; k <= kDraws; ++k) {
        RandomStream random(99, static_cast<std::uint64_t>(k));
        const ModelParameters p = draw_parameters(settings, random);
        ln_arias.push_back(std::log(p.arias_m_s / kStandardGravity));
        freq.push_back(p.mid_frequency_hz);
        damping.push_back(p.damping);
    }
    // ln(I_a [s g]) normal (-4.8255, 1.4318); w_mid/2pi Gamma(4.0982, 1.4330): mean k theta, sd sqrt(k) theta;
    // zeta_f = 0.02 + 0.98 Beta(1.4250, 5.7208): mean a / (a + b), sd sqrt(ab / ((a+b)^2 (a+b+1))).
    const double a = 1.4250, b = 5.7208;
    const double beta_sd = std::sqrt(a * b / ((a + b) * (a + b) * (a + b + 1)));
    const Spread l(ln_arias), f(freq), z(damping);
    EXPECT_NEAR(l.mean, -4.8255, kSigmas * 1.4318 / std::sqrt(kDraws));
    EXPECT_NEAR(f.mean, 4.0982 * 1.4330, kSigmas * std::sqrt(4.0982) * 1.4330 / std::sqrt(kDraws));
    EXPECT_NEAR(z.mean, 0.02 + 0.98 * a / (a + b), kSigmas * 0.98 * beta_sd / std::sqrt(kDraws));
}

TEST(ParameterDraws, NoScatterGivesTheMedians) {
    DrawSettings s;
    s.medians = {0.3, 12.0, 6.0, 4.0, -0.1, 0.25};
    s.scatter = 0.0;
    RandomStream random(1, 1);
    const ModelParameters p = draw_parameters(s, random);
    // Each median goes through F^-1(Phi(Phi^-1(F(m)))): two bisections to the last bits, then rounding.
    constexpr double kInverse = 1e-9;
    EXPECT_NEAR(p.arias_m_s, 0.3, kInverse);
    EXPECT_NEAR(p.d5_95_s, 12.0, kInverse * 12);
    EXPECT_NEAR(p.t_mid_s, 6.0, kInverse * 6);
    EXPECT_NEAR(p.mid_frequency_hz, 4.0, kInverse * 4);
    EXPECT_NEAR(p.slope_hz_per_s, -0.1, kInverse);
    EXPECT_NEAR(p.damping, 0.25, kInverse);
    s.medians[kD595] = 50.0;
    EXPECT_THROW(check_draw_settings(s), vssw::InputError);
}

// Every median option has a range (median_range): a median just inside it is the parameter at --scatter 0, one just
// outside is refused naming the option and the range. The ends are rounded inward to 6 significant digits, so the
// parameter at an end is that end to 1e-6 (and to the inverse's 1e-9 inside).
TEST(ParameterDraws, EveryMedianInsideItsRangeIsHonouredAndOutsideRefused) {
    constexpr double kAtAnEnd = 2e-6;   // the end rounded inward at 6 digits, plus the two inverses
    constexpr double kOutside = 1e-5;   // a step past an end, relative, well beyond its rounding
    const char* const options[kParameterCount] = {"--arias", "--d5-95", "--t-mid", "--mid-frequency",
                                                  "--frequency-slope", "--damping"};
    const double medians[kParameterCount] = {0.3, 12.0, 6.0, 4.0, -0.1, 0.25};
    for (int j = 0; j < kParameterCount; ++j) {
        const Parameter pj = static_cast<Parameter>(j);
        const MedianRange r = median_range(pj);
        ASSERT_LT(r.lo, r.hi) << options[j];
        for (const double end : {r.lo, r.hi}) {
            DrawSettings s;
            s.scatter = 0.0;
            for (int k = 0; k < kParameterCount; ++k) s.medians[k] = medians[k];
            s.medians[j] = end;
            EXPECT_NO_THROW(check_draw_settings(s)) << options[j] << " " << end;
            const ModelParameters m = median_parameters(s);
            const double got[kParameterCount] = {m.arias_m_s, m.d5_95_s, m.t_mid_s, m.mid_frequency_hz,
                                                 m.slope_hz_per_s, m.damping};
            EXPECT_NEAR(got[j], end, kAtAnEnd * std::abs(end)) << options[j];
            const double step = kOutside * std::max(std::abs(end), 1e-3);
            s.medians[j] = end == r.lo ? end - step : end + step;
            try {
                check_draw_settings(s);
                ADD_FAILURE() << options[j] << " " << *s.medians[j] << " was accepted";
            } catch (const vssw::InputError& e) {
                const std::string what = e.what();
                EXPECT_NE(what.find(options[j]), std::string::npos) << what;
                EXPECT_NE(what.find(median_range_text(pj)), std::string::npos) << what;
            }
        }
    }
    // The clamps the sweep found: Arias 1e6 and f_mid 100 Hz were held at the 8-sigma quantile silently.
    EXPECT_LT(median_range(kArias).hi, 1e4);
    EXPECT_LT(median_range(kMidFrequency).hi, 100.0);
}

// A motion whose filter would take more than kMaxFilterSteps (a long record at low damping and frequency: samples x
// impulse span) is refused before anything is made, naming the options; the same at a short duration is made.
TEST(Stochastic, FilterCostIsBoundedUpFront) {
    ModelParameters p{0.3, 12.0, 6.0, 0.31, 0.0, 0.021};
    SimulationSettings s;
    s.duration = 50000.0;
    try {
        (void)record_samples(p, s, "the median motion");
        ADD_FAILURE() << "a 50000 s record at damping 0.021 was accepted";
    } catch (const vssw::InputError& e) {
        const std::string what = e.what();
        for (const char* option : {"--duration", "--dt", "--damping", "--mid-frequency"})
            EXPECT_NE(what.find(option), std::string::npos) << what;
    }
    s.duration = 60.0;
    EXPECT_EQ(record_samples(p, s, "the median motion"), 12001u);
    // The record's length: a --dt so small that the default length is past 1e7 samples names --dt and --corner.
    s.duration.reset();
    s.dt = 1e-9;
    try {
        (void)record_samples(p, s, "the median motion");
        ADD_FAILURE() << "--dt 1e-9 was accepted";
    } catch (const vssw::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("--dt 1e-09"), std::string::npos) << what;
        EXPECT_NE(what.find("--corner"), std::string::npos) << what;
    }
}

TEST(Reproducibility, SameSeedSameMotionWhateverTheCount) {
    const DrawSettings draws;
    const SimulationSettings sim;
    const GeneratedMotion a = generate_motion(7, 3, draws, sim), b = generate_motion(7, 3, draws, sim);
    EXPECT_EQ(a.accel_m_s2, b.accel_m_s2);
    EXPECT_NE(a.accel_m_s2, generate_motion(8, 3, draws, sim).accel_m_s2);

    vssw::testing::TempDir dir;
    MotionSetRequest r;
    r.seed = 7;
    r.count = 3;
    r.out = dir / "three";
    write_motion_set(r);
    r.count = 5;
    r.out = dir / "five";
    write_motion_set(r);
    r.out = dir / "five-again";
    write_motion_set(r);
    const auto bytes = [](const std::filesystem::path& p) { return vssw::testing::read_file(p.string()); };
    EXPECT_EQ(bytes(dir / "three" / "motion-003.at2"), bytes(dir / "five" / "motion-003.at2"));
    for (const char* f : {"motion-001.at2", "motion-005.at2", "motions.csv"})
        EXPECT_EQ(bytes(dir / "five" / f), bytes(dir / "five-again" / f)) << f;
    // A smaller set in the same folder leaves none of the larger one's files behind.
    r.count = 2;
    write_motion_set(r);
    EXPECT_TRUE(std::filesystem::exists(dir / "five-again" / "motion-002.at2"));
    EXPECT_FALSE(std::filesystem::exists(dir / "five-again" / "motion-003.at2"));
}

TEST(At2Writer, ReadsBack) {
    std::vector<double> a;
    for (int i = 0; i < 23; ++i) a.push_back(3.7 * std::sin(0.37 * i) * std::pow(10.0, i % 7 - 3));
    a.push_back(1e-120);  // written as 0
    vssw::testing::TempDir dir;
    const std::string path = (dir / "r.at2").string();
    write_at2_file(path, a, 0.005, "a test record");
    const vssw::GroundMotion g = vssw::read_peer_at2(path);
    ASSERT_EQ(g.sample_values().size(), a.size());
    // "%15.7E": 8 significant digits, half a unit in the last: 5e-8 relative.
    constexpr double kEightDigits = 5.1e-8;
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        EXPECT_NEAR(g.sample_values()[i], a[i], kEightDigits * std::fabs(a[i])) << i;
        EXPECT_NEAR(g.sample_times()[i], 0.005 * static_cast<double>(i), 1e-12) << i;
    }
    EXPECT_EQ(g.sample_values().back(), 0.0);
    // A step that four decimals would round is written in full.
    write_at2_file(path, a, 0.00123456789, "odd step");
    EXPECT_NEAR(vssw::read_peer_at2(path).sample_times()[10], 0.0123456789, 1e-15);
}

}  // namespace

// The statistics of an ensemble comparison (compare/ensemble_statistics.hpp) against mathematics computed here,
// independently of the code under test: the Wilson interval's quadratic, its coverage by simulation and by the
// binomial sum, the lognormal fit's logs, the censored MLE on a large simulated sample, the bootstrap's 1/sqrt(n),
// type-7 quantiles by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "analytic/error.hpp"
#include "compare/ensemble_statistics.hpp"

namespace vssw::compare {
namespace {

constexpr double kZ95 = 1.959963984540054;  // Phi^-1(0.975), the brief's value
constexpr double kPi = 3.14159265358979323846;

// Draws of our own from the standard-specified mt19937_64, so the samples are the same on any standard library.
double uniform_open(std::mt19937_64& rng) {  // in (0, 1)
    return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
}
double standard_normal(std::mt19937_64& rng) {  // Box-Muller, cosine branch
    const double u1 = uniform_open(rng), u2 = uniform_open(rng);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}
std::vector<double> lognormal_sample(std::mt19937_64& rng, std::size_t n, double median, double beta) {
    std::vector<double> x(n);
    for (double& v : x) v = median * std::exp(beta * standard_normal(rng));
    return x;
}
std::vector<IdaRecord> all_collapsed(const std::vector<double>& im) {
    std::vector<IdaRecord> r;
    for (double v : im) r.push_back({v, true});
    return r;
}

// Normal distribution ------------------------------------------------------------------------------------------
// A few ulps of 1.96 (ulp 2.2e-16): Halley's last step and erfc's own rounding.
constexpr double kQuantileTolerance = 1e-15;
// Relative: Phi(Phi^-1(p)) = p, down to p = 1e-300, with erfc's relative accuracy of a few ulps in the tail.
constexpr double kRoundTripRelative = 1e-13;

TEST(EnsembleStatistics, NormalQuantileIsTheInverseOfTheCdf) {
    EXPECT_NEAR(normal_quantile(0.975), kZ95, kQuantileTolerance);
    EXPECT_NEAR(normal_quantile(0.025), -kZ95, kQuantileTolerance);
    EXPECT_EQ(normal_quantile(0.5), 0.0);
    EXPECT_EQ(normal_quantile(0.0), -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(normal_quantile(1.5)));
    for (double p : {1e-300, 1e-50, 1e-10, 1e-3, 0.1, 0.3, 0.49, 0.51, 0.7, 0.9, 0.999}) {
        const double back = normal_cdf(normal_quantile(p));
        EXPECT_NEAR(back, p, kRoundTripRelative * p) << p;
    }
    // Symmetry for p near 1, where 1 - p is exact (p = 1 - 2^-30): Phi^-1(p) = -Phi^-1(1 - p).
    EXPECT_EQ(normal_quantile(1.0 - 0x1.0p-30), -normal_quantile(0x1.0p-30));
}

// Wilson interval ----------------------------------------------------------------------------------------------
// The test's quadratic formula loses a few digits to cancellation in b^2 - 4ac: 1e-12 is far above that and far
// below any error of form.
constexpr double kWilsonTolerance = 1e-12;

// The Wilson interval as the roots in q of (p - q)^2 = z^2 q (1 - q)/n: (1 + z^2/n) q^2 - (2p + z^2/n) q + p^2 = 0.
std::pair<double, double> wilson_roots(long k, long n, double z) {
    const double p = static_cast<double>(k) / static_cast<double>(n);
    const double a = 1.0 + z * z / static_cast<double>(n);
    const double b = -(2.0 * p + z * z / static_cast<double>(n));
    const double c = p * p;
    const double root = std::sqrt(b * b - 4.0 * a * c);
    return {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)};
}

TEST(EnsembleStatistics, WilsonIntervalIsTheQuadraticsRoots) {
    const std::vector<std::pair<long, long>> cases{{0, 1}, {1, 1}, {0, 10}, {10, 10}, {3, 10},
                                                   {37, 100}, {1, 200}, {500, 1000}};
    for (auto [k, n] : cases) {
        const Interval w = wilson_interval(k, n);
        const auto [lo, hi] = wilson_roots(k, n, kZ95);
        EXPECT_EQ(w.n, n);
        EXPECT_DOUBLE_EQ(w.value, static_cast<double>(k) / static_cast<double>(n));
        EXPECT_NEAR(w.lo, lo, kWilsonTolerance) << k << "/" << n;
        EXPECT_NEAR(w.hi, hi, kWilsonTolerance) << k << "/" << n;
    }
    // k = 0 and k = n: one end exact, the other z^2/(n + z^2) from it.
    const double z2 = kZ95 * kZ95;
    EXPECT_EQ(wilson_interval(0, 10).lo, 0.0);
    EXPECT_NEAR(wilson_interval(0, 10).hi, z2 / (10.0 + z2), kWilsonTolerance);
    EXPECT_EQ(wilson_interval(10, 10).hi, 1.0);
    EXPECT_NEAR(wilson_interval(10, 10).lo, 10.0 / (10.0 + z2), kWilsonTolerance);
    // Another confidence: z = Phi^-1(0.995) = 2.5758293035489 (tables), roots from it.
    const auto [lo99, hi99] = wilson_roots(7, 40, 2.5758293035489004);
    EXPECT_NEAR(wilson_interval(7, 40, 0.99).lo, lo99, kWilsonTolerance);
    EXPECT_NEAR(wilson_interval(7, 40, 0.99).hi, hi99, kWilsonTolerance);
}

TEST(EnsembleStatistics, WilsonIntervalHoldsTheProportionInsideZeroOne) {
    for (long n = 1; n <= 60; ++n)
        for (long k = 0; k <= n; ++k) {
            const Interval w = wilson_interval(k, n);
            EXPECT_LE(0.0, w.lo);
            EXPECT_LE(w.lo, w.value);
            EXPECT_LE(w.value, w.hi);
            EXPECT_LE(w.hi, 1.0);
        }
    const Interval none = wilson_interval(0, 0);
    EXPECT_TRUE(std::isnan(none.value) && std::isnan(none.lo) && std::isnan(none.hi));
    EXPECT_EQ(none.n, 0);
    EXPECT_THROW(wilson_interval(3, 2), InputError);
    EXPECT_THROW(wilson_interval(-1, 2), InputError);
    EXPECT_THROW(wilson_interval(1, 2, 1.0), InputError);
}

// Coverage at n = 100: the exact coverage sum_k P(k) [p in interval(k)] oscillates with p (Brown, Cai & DasGupta
// 2001, Stat. Sci. 16:101, Fig. 4); at n = 100 and p = 0.1, 0.3, 0.5 it is 0.936-0.943, inside 0.95 +- 0.02.
constexpr double kCoverageBand = 0.02;
// Simulated against exact coverage: 4 Monte Carlo standard deviations sqrt(c (1 - c)/M), a false alarm 6e-5.
constexpr double kCoverageSigmas = 4.0;

double binomial_pmf(long k, long n, double p) {
    const double nn = static_cast<double>(n), kk = static_cast<double>(k);
    const double lg = std::lgamma(nn + 1.0) - std::lgamma(kk + 1.0) - std::lgamma(nn - kk + 1.0);
    return std::exp(lg + kk * std::log(p) + (nn - kk) * std::log1p(-p));
}

TEST(EnsembleStatistics, WilsonIntervalCoversNinetyFivePercent) {
    constexpr long kTrials = 100;
    constexpr int kSamples = 20000;
    std::mt19937_64 rng(7);
    for (double p : {0.1, 0.3, 0.5}) {
        double exact = 0.0;
        for (long k = 0; k <= kTrials; ++k) {
            const Interval w = wilson_interval(k, kTrials);
            if (w.lo <= p && p <= w.hi) exact += binomial_pmf(k, kTrials, p);
        }
        int covered = 0;
        for (int s = 0; s < kSamples; ++s) {
            long k = 0;
            for (long t = 0; t < kTrials; ++t) k += uniform_open(rng) < p ? 1 : 0;
            const Interval w = wilson_interval(k, kTrials);
            covered += (w.lo <= p && p <= w.hi) ? 1 : 0;
        }
        const double simulated = covered / static_cast<double>(kSamples);
        EXPECT_NEAR(exact, 0.95, kCoverageBand) << p;
        EXPECT_NEAR(simulated, exact, kCoverageSigmas * std::sqrt(exact * (1.0 - exact) / kSamples)) << p;
    }
}

// Lognormal fit ------------------------------------------------------------------------------------------------
// Relative: a sum of a handful of logs and an exp, each rounded to an ulp.
constexpr double kFitRelative = 1e-13;

TEST(EnsembleStatistics, LognormalFitIsTheMeanAndSampleDeviationOfTheLogs) {
    const std::vector<double> pga{0.31, 0.52, 0.44, 0.28, 0.61, 0.39, 0.47};  // [g]
    double mean = 0.0;
    for (double x : pga) mean += std::log(x) / 7.0;
    double squares = 0.0;
    for (double x : pga) squares += (std::log(x) - mean) * (std::log(x) - mean);
    const double beta = std::sqrt(squares / 6.0);  // n - 1
    const LognormalFit fit = fit_lognormal_ida(all_collapsed(pga));
    ASSERT_TRUE(fit.ok()) << fit.reason;
    EXPECT_NEAR(fit.median, std::exp(mean), kFitRelative * std::exp(mean));
    EXPECT_NEAR(fit.beta, beta, kFitRelative * beta);
    EXPECT_EQ(fit.records, 7);
    EXPECT_EQ(fit.collapsed, 7);
    EXPECT_FALSE(fit.censored_mle);
    // The same through ida_records with a cap above all of them: nothing censored.
    std::vector<std::optional<double>> im(pga.begin(), pga.end());
    const LognormalFit same = fit_lognormal_ida(ida_records(im, 1.0));
    EXPECT_EQ(same.median, fit.median);
    EXPECT_EQ(same.beta, fit.beta);
    // The fragility at the median is 1/2 and at median exp(z beta) is 0.975.
    EXPECT_NEAR(fragility(fit.median, fit), 0.5, 1e-15);
    EXPECT_NEAR(fragility(fit.median * std::exp(kZ95 * fit.beta), fit), 0.975, kRoundTripRelative);
    EXPECT_EQ(fragility(0.0, fit), 0.0);
}

TEST(EnsembleStatistics, LognormalFitNeedsTwoDistinctCollapses) {
    const LognormalFit one = fit_lognormal_ida({{0.4, true}, {0.9, false}, {0.9, false}});
    EXPECT_FALSE(one.ok());
    EXPECT_TRUE(std::isnan(one.median) && std::isnan(one.beta));
    EXPECT_EQ(one.collapsed, 1);
    EXPECT_EQ(one.records, 3);
    EXPECT_TRUE(std::isnan(fragility(0.5, one)));
    const LognormalFit equal = fit_lognormal_ida({{0.4, true}, {0.4, true}});
    EXPECT_FALSE(equal.ok());
    EXPECT_THROW(fit_lognormal_ida({{0.0, true}, {0.4, true}}), InputError);
    EXPECT_THROW(ida_records({0.3, std::nullopt, 1.2}, 1.0), InputError);  // collapse above the cap
}

// A censored record far below the median contributes 1 - Phi(-33) = 1 to the likelihood: the censored MLE is then
// the MLE of the collapsed records alone, mean of the logs and beta with divisor n (Newton stops at a relative step
// of 1e-13; 1e-10 leaves room for the conditioning).
constexpr double kMleRelative = 1e-10;

TEST(EnsembleStatistics, CensoredMleWithoutInformativeCensoringIsTheCompleteMle) {
    const std::vector<double> pga{0.31, 0.52, 0.44, 0.28, 0.61, 0.39, 0.47};
    std::vector<IdaRecord> records = all_collapsed(pga);
    records.push_back({1e-6, false});
    double mean = 0.0;
    for (double x : pga) mean += std::log(x) / 7.0;
    double squares = 0.0;
    for (double x : pga) squares += (std::log(x) - mean) * (std::log(x) - mean);
    const LognormalFit fit = fit_lognormal_ida(records);
    ASSERT_TRUE(fit.ok()) << fit.reason;
    EXPECT_TRUE(fit.censored_mle);
    EXPECT_EQ(fit.collapsed, 7);
    EXPECT_NEAR(fit.median, std::exp(mean), kMleRelative * std::exp(mean));
    EXPECT_NEAR(fit.beta, std::sqrt(squares / 7.0), kMleRelative);
}

// theta = 0.5 g, beta = 0.4, cap 0.6 g (32 % censored), n = 20000. The asymptotic standard deviations, from the
// right-censored normal's Fisher information (Cohen 1959, Technometrics 1:217) evaluated for these parameters by
// quadrature, are 1.08 beta/sqrt(n) = 0.0031 for ln theta and 1.31 beta/sqrt(2n) = 0.0026 for beta; 5 of them.
constexpr double kCensoredLnThetaTolerance = 5 * 0.0031;
constexpr double kCensoredBetaTolerance = 5 * 0.0026;
// Against the complete-data MLE of the same sample (both efficient, so the variance of their difference is the
// difference of their variances, Hausman 1978): sqrt(0.0031^2 - 0.0028^2) = 0.0013 and
// sqrt(0.0026^2 - 0.0020^2) = 0.0017 (60 seeds measured 0.0011 and 0.0016); 5 of them.
constexpr double kVersusCompleteLnThetaTolerance = 5 * 0.0013;
constexpr double kVersusCompleteBetaTolerance = 5 * 0.0017;

TEST(EnsembleStatistics, CensoredMleRecoversThetaAndBeta) {
    constexpr double kTheta = 0.5, kBeta = 0.4, kCap = 0.6;
    std::mt19937_64 rng(2015);
    const std::vector<double> sample = lognormal_sample(rng, 20000, kTheta, kBeta);
    std::vector<std::optional<double>> im;
    for (double x : sample) im.push_back(x <= kCap ? std::optional(x) : std::nullopt);
    const std::vector<IdaRecord> records = ida_records(im, kCap);
    const LognormalFit fit = fit_lognormal_ida(records);
    ASSERT_TRUE(fit.ok()) << fit.reason;
    EXPECT_TRUE(fit.censored_mle);
    EXPECT_LT(fit.collapsed, 14000);  // about 68 % collapsed below the cap
    EXPECT_NEAR(std::log(fit.median), std::log(kTheta), kCensoredLnThetaTolerance);
    EXPECT_NEAR(fit.beta, kBeta, kCensoredBetaTolerance);
    // The complete sample's MLE, from its logs here.
    double mean = 0.0;
    for (double x : sample) mean += std::log(x);
    mean /= static_cast<double>(sample.size());
    double squares = 0.0;
    for (double x : sample) squares += (std::log(x) - mean) * (std::log(x) - mean);
    EXPECT_NEAR(std::log(fit.median), mean, kVersusCompleteLnThetaTolerance);
    EXPECT_NEAR(fit.beta, std::sqrt(squares / static_cast<double>(sample.size())), kVersusCompleteBetaTolerance);
    // Dropping the censored records instead fits a truncated sample: its median is far low (by about
    // beta phi(0.46)/Phi(0.46) = 0.21 in ln theta), which is why they are kept.
    std::vector<IdaRecord> dropped;
    for (const IdaRecord& r : records)
        if (r.collapsed) dropped.push_back(r);
    EXPECT_LT(std::log(fit_lognormal_ida(dropped).median), std::log(kTheta) - 10 * kCensoredLnThetaTolerance);
}

// Bootstrap ----------------------------------------------------------------------------------------------------
// The 95 % percentile interval of ln theta is about 2 z beta/sqrt(n) wide (the sampling distribution of the mean
// log). Relative error of a measured width: the sample's own beta (1/sqrt(2n), 10 % at n = 50) and the 2.5 %
// quantiles of B = 2000 replicates (about 3 %); 35 % is 3 of those at the smallest n.
constexpr double kWidthRelative = 0.35;

TEST(EnsembleStatistics, BootstrapIntervalsHoldTheTruthAndShrinkAsOneOverRootN) {
    constexpr double kTheta = 0.5, kBeta = 0.4;
    std::mt19937_64 rng(99);
    double previous_width = 0.0;
    for (std::size_t n : {50u, 200u, 800u}) {
        const std::vector<IdaRecord> records = all_collapsed(lognormal_sample(rng, n, kTheta, kBeta));
        const FitBootstrap b = bootstrap_fit(records);
        ASSERT_TRUE(b.fit.ok());
        EXPECT_EQ(b.beta.n + b.failed, 2000);
        EXPECT_EQ(b.median.n, static_cast<long>(n));  // uncensored: the median's t interval rests on the records
        EXPECT_LE(b.median.lo, kTheta);
        EXPECT_GE(b.median.hi, kTheta);
        EXPECT_LE(b.beta.lo, kBeta);
        EXPECT_GE(b.beta.hi, kBeta);
        EXPECT_EQ(b.median.value, b.fit.median);
        const double width = std::log(b.median.hi / b.median.lo);
        const double expected = 2.0 * kZ95 * kBeta / std::sqrt(static_cast<double>(n));
        EXPECT_NEAR(width, expected, kWidthRelative * expected) << n;
        if (previous_width > 0.0) {
            EXPECT_NEAR(previous_width / width, 2.0, 2.0 * kWidthRelative) << n;
        }
        previous_width = width;
    }
}

TEST(EnsembleStatistics, BootstrapIsReproducibleAndItsIndexDrawIsTheStandardsEngine) {
    std::mt19937_64 rng(5);
    std::vector<IdaRecord> records = all_collapsed(lognormal_sample(rng, 30, 0.5, 0.4));
    records.push_back({0.9, false});
    const FitBootstrap a = bootstrap_fit(records, {500, 0.9, 11});
    const FitBootstrap b = bootstrap_fit(records, {500, 0.9, 11});
    EXPECT_EQ(a.median.lo, b.median.lo);
    EXPECT_EQ(a.beta.hi, b.beta.hi);
    EXPECT_TRUE(a.fit.censored_mle);
    // The standard fixes mt19937_64's 10000th output from the default seed; a draw outside the rejected top
    // 2^64 mod 1000 values is that output mod 1000.
    std::mt19937_64 standard;
    standard.discard(9999);
    EXPECT_EQ(uniform_index(standard, 1000), 9981545732273789042ull % 1000);
    std::mt19937_64 one(1);
    EXPECT_EQ(uniform_index(one, 1), 0u);
    // Two collapses among ten records: a resample often draws fewer than 2 of them; those replicates are counted.
    std::vector<IdaRecord> sparse(8, IdaRecord{1.0, false});
    sparse.push_back({0.4, true});
    sparse.push_back({0.7, true});
    const FitBootstrap s = bootstrap_fit(sparse);
    ASSERT_TRUE(s.fit.ok()) << s.fit.reason;
    EXPECT_GT(s.failed, 0);
    EXPECT_EQ(s.median.n + s.failed, 2000);
    EXPECT_EQ(s.beta.n, s.median.n);
}

// Rounding only: ln(c x) = ln c + ln x to an ulp of each log.
constexpr double kPairedRelative = 1e-13;

TEST(EnsembleStatistics, PairedRatioOfAFitWithItselfIsExactlyOne) {
    std::mt19937_64 rng(3);
    std::vector<IdaRecord> records = all_collapsed(lognormal_sample(rng, 40, 0.5, 0.4));
    records.push_back({0.8, false});
    const RatioBootstrap same = bootstrap_median_ratio(records, records);
    EXPECT_EQ(same.ratio.value, 1.0);
    EXPECT_EQ(same.ratio.lo, 1.0);
    EXPECT_EQ(same.ratio.hi, 1.0);
    EXPECT_EQ(same.ratio.n + same.failed, 2000);
    // An engine collapsing at 1.2 times the reference's intensity on every record: the paired ratio is 1.2 with no
    // width, where the two fits' own intervals are wide.
    std::vector<IdaRecord> scaled = records;
    for (IdaRecord& r : scaled) r.im *= 1.2;
    const RatioBootstrap ratio = bootstrap_median_ratio(scaled, records);
    EXPECT_NEAR(ratio.ratio.value, 1.2, kPairedRelative);
    EXPECT_NEAR(ratio.ratio.lo, 1.2, kPairedRelative);
    EXPECT_NEAR(ratio.ratio.hi, 1.2, kPairedRelative);
    const FitBootstrap alone = bootstrap_fit(records);
    EXPECT_GT(alone.median.hi / alone.median.lo, 1.1);
    scaled.pop_back();
    EXPECT_THROW(bootstrap_median_ratio(scaled, records), InputError);  // not the same records
}

// Quantiles and bands ------------------------------------------------------------------------------------------
TEST(EnsembleStatistics, QuartilesAreTypeSevenByHand) {
    // Sorted: 1 1 2 3 4 5 6 9 (n = 8). h = 7 p: q1 at 1.75 -> 1 + 0.75 (2 - 1) = 1.75; median at 3.5 -> 3.5;
    // q3 at 5.25 -> 5 + 0.25 (6 - 5) = 5.25.
    const std::vector<double> v{3, 1, 4, 1, 5, 9, 2, 6, std::numeric_limits<double>::quiet_NaN()};
    const Quartiles q = quartiles(v);
    EXPECT_DOUBLE_EQ(q.q1, 1.75);
    EXPECT_DOUBLE_EQ(q.median, 3.5);
    EXPECT_DOUBLE_EQ(q.q3, 5.25);
    EXPECT_EQ(q.n, 8);
    EXPECT_EQ(q.nan, 1);
    EXPECT_EQ(quantile(v, 0.0), 1.0);
    EXPECT_EQ(quantile(v, 1.0), 9.0);
    EXPECT_DOUBLE_EQ(quantile(v, 0.9), 6.0 + 0.3 * 3.0);  // h = 6.3
    EXPECT_EQ(quantile({2.5}, 0.3), 2.5);
    EXPECT_TRUE(std::isnan(quartiles({}).median));
    EXPECT_THROW(quantile(v, 1.1), InputError);
}

TEST(EnsembleStatistics, CountsRunsInsideTheBand) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<BandRun> runs{
        {1.0, 0.9, 1.1, 1.0},   // inside
        {1.0, 0.9, 1.1, 0.9},   // on the lower end: inside
        {1.0, 0.9, 1.1, 1.1},   // on the upper end: inside
        {1.0, 0.9, 1.1, 1.2},   // above
        {2.0, 0.9, 1.1, 1.0},   // inside, but the reference is outside its own band
        {1.0, 0.9, 1.1, nan},   // no engine value: outside
    };
    const BandCount c = count_inside_band(runs);
    EXPECT_EQ(c.runs, 6);
    EXPECT_EQ(c.inside, 4);
    EXPECT_EQ(c.outside, (std::vector<std::size_t>{3, 5}));
    EXPECT_EQ(c.reference_outside, (std::vector<std::size_t>{4}));
    EXPECT_THROW(count_inside_band({{1.0, 1.2, 1.1, 1.0}}), InputError);
}

}  // namespace
}  // namespace vssw::compare

// The lognormal fragility of a multiple stripe analysis (compare/stripe_fragility.hpp): the maximum likelihood fit of
// Baker (2015) against its closed form on two levels and against a known truth on a large simulated ensemble, the
// cases with no finite fit, and the record bootstrap.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analytic/error.hpp"
#include "compare/ensemble_statistics.hpp"
#include "compare/stripe_fragility.hpp"

namespace vssw::compare {
namespace {

// Records with collapse capacities c_i, run at each level x_j: overturned where x_j >= c_i (what a monotone IDA
// curve gives; the stripe fit uses the levels' counts only).
std::vector<StripeOutcomes> from_capacities(const std::vector<double>& levels, const std::vector<double>& capacities) {
    std::vector<StripeOutcomes> out;
    for (double c : capacities) {
        StripeOutcomes o;
        for (double x : levels) o.push_back(x >= c ? 1 : 0);
        out.push_back(o);
    }
    return out;
}

// Records whose outcomes give z collapses of n at each level: record i collapses at level j when i < z_j.
std::vector<StripeOutcomes> from_counts(const std::vector<int>& collapsed, int n) {
    std::vector<StripeOutcomes> out(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        for (int z : collapsed) out[static_cast<std::size_t>(i)].push_back(i < z ? 1 : 0);
    return out;
}

TEST(StripeFragility, TwoLevelsFitTheirSharesExactly) {
    // With two levels the model has as many parameters as data: the maximum passes through both observed shares,
    // ln(x_j / theta) / beta = Phi^-1(z_j / n), solved here by hand.
    constexpr double kNewtonRoundOff = 1e-9;  // Newton stops at a log-likelihood gain of 1e-12: parameters to ~1e-9
    const std::vector<double> levels = {0.3, 0.6};
    const auto records = from_counts({3, 8}, 10);
    const double u1 = normal_quantile(0.3), u2 = normal_quantile(0.8);
    const double beta = (std::log(0.6) - std::log(0.3)) / (u2 - u1);
    const double median = std::exp(std::log(0.3) - beta * u1);
    const LognormalFit fit = fit_lognormal_stripes(levels, records);
    ASSERT_TRUE(fit.ok()) << fit.reason;
    EXPECT_NEAR(fit.beta, beta, kNewtonRoundOff);
    EXPECT_NEAR(fit.median, median, kNewtonRoundOff * median);
    EXPECT_EQ(fit.records, 10);
    EXPECT_EQ(fit.collapsed, 11);  // runs that overturned, over both levels
}

TEST(StripeFragility, RecoversAKnownLognormalFromALargeEnsemble) {
    // 4000 records with lognormal capacities (theta 0.5 g, beta 0.4) at 7 levels: the fit's standard errors are about
    // beta / sqrt(n_eff) with a few thousand informative runs, ~0.01 in ln theta and ~0.01 in beta.
    constexpr double kLogMedianTolerance = 0.04;  // ~4 standard errors of ln theta
    constexpr double kBetaTolerance = 0.04;       // ~4 standard errors of beta
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> capacities;
    for (int i = 0; i < 4000; ++i) capacities.push_back(0.5 * std::exp(0.4 * normal(rng)));
    const std::vector<double> levels = {0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0};
    const LognormalFit fit = fit_lognormal_stripes(levels, from_capacities(levels, capacities));
    ASSERT_TRUE(fit.ok()) << fit.reason;
    EXPECT_NEAR(std::log(fit.median), std::log(0.5), kLogMedianTolerance);
    EXPECT_NEAR(fit.beta, 0.4, kBetaTolerance);
}

TEST(StripeFragility, NoFiniteFitIsSaidWithItsReason) {
    const std::vector<double> levels = {0.3, 0.6};
    EXPECT_NE(fit_lognormal_stripes(levels, from_counts({0, 0}, 5)).reason.find("no run collapsed"),
              std::string::npos);
    EXPECT_NE(fit_lognormal_stripes(levels, from_counts({5, 5}, 5)).reason.find("every run collapsed"),
              std::string::npos);
    // Everything stands at 0.3 g and collapses at 0.6 g: beta -> 0, no maximum.
    const LognormalFit separated = fit_lognormal_stripes(levels, from_counts({0, 5}, 5));
    EXPECT_FALSE(separated.ok());
    EXPECT_NE(separated.reason.find("do not overlap"), std::string::npos);
    EXPECT_TRUE(std::isnan(separated.median));
    // Quasi-separated: nothing collapses below the top level, where half do: still no finite maximum (beta -> 0
    // with the median at that level).
    EXPECT_FALSE(fit_lognormal_stripes(levels, from_counts({0, 2}, 4)).ok());
    // The mirror image, collapses only below the standing runs: a falling share, no fragility.
    EXPECT_NE(fit_lognormal_stripes(levels, from_counts({3, 0}, 5)).reason.find("falls"), std::string::npos);
    EXPECT_THROW(fit_lognormal_stripes({0.3, -1.0}, from_counts({1, 2}, 3)), InputError);
    EXPECT_THROW(fit_lognormal_stripes({0.3}, from_counts({1, 2}, 3)), InputError);
}

TEST(StripeFragility, FailedRunsAreLeftOutNotCountedAsStanding) {
    // The same shares with a failed run (-1) added at each level: the fit must not move.
    constexpr double kSameFit = 1e-9;  // the same counts: equal up to Newton's stopping point
    const std::vector<double> levels = {0.3, 0.6};
    auto records = from_counts({3, 8}, 10);
    const LognormalFit plain = fit_lognormal_stripes(levels, records);
    records.push_back({-1, -1});
    const LognormalFit with_failed = fit_lognormal_stripes(levels, records);
    EXPECT_NEAR(with_failed.median, plain.median, kSameFit);
    EXPECT_NEAR(with_failed.beta, plain.beta, kSameFit);
    EXPECT_EQ(with_failed.records, 10);  // a record with no result is not a record of the fit
}

TEST(StripeFragility, BootstrapHoldsTheFitAndAFitAgainstItselfIsOne) {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> capacities;
    for (int i = 0; i < 60; ++i) capacities.push_back(0.5 * std::exp(0.4 * normal(rng)));
    const std::vector<double> levels = {0.3, 0.4, 0.5, 0.6, 0.8};
    const auto records = from_capacities(levels, capacities);
    BootstrapOptions o;
    o.replicates = 400;
    const FitBootstrap b = bootstrap_stripes(levels, records, o);
    ASSERT_TRUE(b.fit.ok()) << b.fit.reason;
    EXPECT_LE(b.median.lo, b.fit.median);
    EXPECT_GE(b.median.hi, b.fit.median);
    EXPECT_LT(b.median.lo, b.median.hi);
    EXPECT_EQ(b.median.n + b.failed, o.replicates);
    const RatioBootstrap self = bootstrap_stripe_median_ratio(levels, records, records, o);
    EXPECT_EQ(self.ratio.value, 1.0);
    EXPECT_EQ(self.ratio.lo, 1.0);
    EXPECT_EQ(self.ratio.hi, 1.0);
    // The same seed gives the same interval.
    const FitBootstrap again = bootstrap_stripes(levels, records, o);
    EXPECT_EQ(again.median.lo, b.median.lo);
    EXPECT_EQ(again.beta.hi, b.beta.hi);
}

}  // namespace
}  // namespace vssw::compare

namespace vssw::compare {
namespace {

// Fits the data do not support are "not resolved" with the reason, never a number: flat stripes (the
// share the same at every level: beta runs away), too few records; a resolved fit on the same levels for contrast.
TEST(StripeFragility, FitsTheStripesDoNotSupportAreNotResolved) {
    const std::vector<double> levels = {0.4, 0.8};
    const auto not_resolved = [](const LognormalFit& f) { return f.reason.rfind("not resolved: ", 0) == 0; };
    const LognormalFit flat = fit_lognormal_stripes(levels, {{0, 0}, {1, 1}, {0, 0}, {1, 1}});
    EXPECT_TRUE(not_resolved(flat)) << flat.reason;
    EXPECT_TRUE(std::isnan(flat.median));
    const LognormalFit two = fit_lognormal_stripes(levels, {{0, 1}, {1, 1}});
    EXPECT_TRUE(not_resolved(two)) << two.reason;
    EXPECT_NE(two.reason.find("2 records"), std::string::npos) << two.reason;
    const LognormalFit resolved = fit_lognormal_stripes(levels, {{0, 1}, {1, 1}, {0, 0}, {0, 1}});
    EXPECT_TRUE(resolved.ok()) << resolved.reason;
}

}  // namespace
}  // namespace vssw::compare

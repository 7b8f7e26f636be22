// Coverage of the fragility median's 95 % intervals, by simulation: records' collapse intensities drawn
// from a known lognormal, fitted (IDA and stripes), the interval computed; over many repetitions the share holding
// the true median. The IDA interval without censoring (Student's t on ln IM) must cover 95 %; the percentile
// bootstrap's (stripes, censored IDA) falls short at few records, which is why it is "not resolved" below
// kMinStripeIntervalRecords / kMinCensoredIntervalRecords (compare/ensemble_statistics.hpp; docs/earthquakes.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "analytic/error.hpp"
#include "compare/ensemble_statistics.hpp"
#include "compare/stripe_fragility.hpp"
#include "tests/interval_coverage.hpp"

namespace vssw::compare {
namespace {

// The report's wall and ensemble: its reference's median collapse PGA, the dispersion measured in PGA over 46
// motions and its four levels.
constexpr double kTheta = 0.77, kBeta = 0.6;
const std::vector<double> kLevels = {0.4, 0.55, 0.7, 0.85};
constexpr int kRepetitions = 600;  // coverage's standard error sqrt(0.95 * 0.05 / 600) = 0.009
constexpr int kReplicates = 300;   // a percentile interval's ends move ~0.01 in coverage from 300 to 2000 (measured)
// Four standard errors of a coverage at 600 repetitions: a true 95 % is never outside, a 90 % seldom inside.
constexpr double kCoverageTolerance = 0.036;

using vssw::testing::Coverage;

// One simulated ensemble: n lognormal capacities.
std::vector<double> capacities(std::mt19937_64& rng, int n) {
    std::normal_distribution<double> z(0.0, 1.0);
    std::vector<double> c;
    for (int i = 0; i < n; ++i) c.push_back(kTheta * std::exp(kBeta * z(rng)));
    return c;
}

void count(Coverage& c, const Interval& i) { vssw::testing::count_coverage(c, i, kTheta); }

enum class Fit { ida, censored_ida, stripes };

// The coverage of one fit's median interval at n records; `shown` counts the intervals given.
Coverage coverage(Fit kind, int n) {
    std::mt19937_64 rng(20261128 + static_cast<unsigned>(n));
    Coverage c;
    for (int r = 0; r < kRepetitions; ++r) {
        BootstrapOptions o;
        o.replicates = kReplicates;
        o.seed = static_cast<std::uint64_t>(r) + 1;
        const std::vector<double> caps = capacities(rng, n);
        if (kind == Fit::stripes) {
            std::vector<StripeOutcomes> s;
            for (double cap : caps) {
                StripeOutcomes o_r;
                for (double x : kLevels) o_r.push_back(x >= cap ? 1 : 0);
                s.push_back(o_r);
            }
            count(c, bootstrap_stripes(kLevels, s, o).median);
            continue;
        }
        // Censored: the search's ceiling at the 84th percentile, so some records still stand there.
        const double cap = kind == Fit::censored_ida ? kTheta * std::exp(kBeta) : INFINITY;
        std::vector<IdaRecord> records;
        for (double x : caps) records.push_back(x <= cap ? IdaRecord{x, true} : IdaRecord{cap, false});
        if (kind == Fit::censored_ida && caps.end() == std::find_if(caps.begin(), caps.end(),
                                                                    [cap](double x) { return x > cap; }))
            continue;  // none censored: the t interval's case, above
        count(c, bootstrap_fit(records, o).median);
    }
    return c;
}

TEST(FragilityCoverage, StudentsTQuantileMatchesTheTables) {
    constexpr double kTableRounding = 5e-4;  // the tables' three decimals
    EXPECT_NEAR(student_t_quantile(0.975, 1), 12.706, kTableRounding);
    EXPECT_NEAR(student_t_quantile(0.975, 2), 4.303, kTableRounding);
    EXPECT_NEAR(student_t_quantile(0.975, 3), 3.182, kTableRounding);
    EXPECT_NEAR(student_t_quantile(0.975, 7), 2.365, kTableRounding);
    EXPECT_NEAR(student_t_quantile(0.975, 19), 2.093, kTableRounding);
    EXPECT_NEAR(student_t_quantile(0.95, 10), 1.812, kTableRounding);
    EXPECT_NEAR(student_t_quantile(0.025, 4), -2.776, kTableRounding);
    constexpr double kLargeDof = 1e-3;  // t at 5000 dof lies 2.4e-4 above the normal's 1.95996
    EXPECT_NEAR(student_t_quantile(0.975, 5000), normal_quantile(0.975), kLargeDof);
    EXPECT_THROW(student_t_quantile(0.975, 0), InputError);
    EXPECT_THROW(student_t_quantile(1.0, 3), InputError);
}

TEST(FragilityCoverage, IdaMedianIntervalCoversNinetyFivePercentAtAnyRecordCount) {
    for (int n : {4, 8, 20}) {
        const Coverage c = coverage(Fit::ida, n);
        EXPECT_EQ(c.shown, kRepetitions) << n;
        EXPECT_NEAR(c.share(), 0.95, kCoverageTolerance) << n << " records";
    }
}

TEST(FragilityCoverage, PercentileIntervalsAreShownOnlyWhereTheyCoverNearlyNinetyFivePercent) {
    // Shown: at the smallest record count allowed and beyond, the coverage lies within a few points of 95 %
    // (at least 90 %: it misses at most twice as often as it claims).
    constexpr double kLeastCoverage = 0.90;
    for (int n : {static_cast<int>(kMinStripeIntervalRecords), 8, 20}) {
        const Coverage c = coverage(Fit::stripes, n);
        EXPECT_GT(c.shown, 0);
        EXPECT_GE(c.share(), kLeastCoverage - kCoverageTolerance) << n << " records, stripes";
    }
    for (int n : {static_cast<int>(kMinCensoredIntervalRecords), 20}) {
        const Coverage c = coverage(Fit::censored_ida, n);
        EXPECT_GE(c.share(), kLeastCoverage - kCoverageTolerance) << n << " records, censored IDA";
    }
    // Not shown below: there the percentile interval fell short, and the rule must leave it out.
    EXPECT_EQ(coverage(Fit::stripes, 4).shown, 0);
    EXPECT_EQ(coverage(Fit::censored_ida, 8).shown, 0);
}

}  // namespace
}  // namespace vssw::compare

// Paired statistics of an engine against the reference (compare/paired_runs.hpp) against sums computed here by hand:
// the exact McNemar p-value from binomial coefficients, the records' medians' order-statistic interval against the sign
// test's k worked out by hand, the record bootstrap's median and its resamples without a value counted.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "compare/paired_runs.hpp"

namespace vssw::compare {
namespace {

constexpr double kExact = 1e-12;  // sums of a few exact binomial terms: rounding only

TEST(McNemarExact, IsTwiceTheBinomialTailOfTheSmallerCount) {
    EXPECT_EQ(mcnemar_exact_p(0, 0), 1.0);
    EXPECT_NEAR(mcnemar_exact_p(5, 0), 2.0 / 32.0, kExact);   // 2 (1/2)^5
    EXPECT_NEAR(mcnemar_exact_p(0, 6), 2.0 / 64.0, kExact);   // 2 (1/2)^6: below 0.05, a one-sided disagreement
    EXPECT_NEAR(mcnemar_exact_p(3, 7), 2.0 * (1 + 10 + 45 + 120) / 1024.0, kExact);
    EXPECT_EQ(mcnemar_exact_p(7, 3), mcnemar_exact_p(3, 7));
    EXPECT_EQ(mcnemar_exact_p(4, 4), 1.0);  // 2 P(X <= 4) > 1 for n = 8: capped
    const double large = mcnemar_exact_p(1000, 900);  // no overflow of the coefficients
    EXPECT_TRUE(std::isfinite(large));
    EXPECT_GT(large, 0.0);
    EXPECT_LT(large, 0.05);
    EXPECT_THROW(mcnemar_exact_p(-1, 2), InputError);
}

TEST(RecordMedianInterval, IsTheOrderStatisticsOfTheRecordsMedians) {
    // k the largest with 2 P(X <= k - 1) <= 0.05, X ~ Binomial(n, 1/2): 2/64 at n = 6 (k 1), 2 * 79/4096 at 12 (k 3,
    // while 2 * 299/4096 = 0.146 > 0.05), 2 * 971712/2^26 = 0.029 at 26 (k 8, while 2 * 2533987/2^26 = 0.076).
    EXPECT_EQ(median_order_statistic(5, 0.95), 0);  // 2/32 = 0.0625: even [min, max] is short of 95 %
    EXPECT_EQ(median_order_statistic(6, 0.95), 1);
    EXPECT_EQ(median_order_statistic(12, 0.95), 3);
    EXPECT_EQ(median_order_statistic(26, 0.95), 8);
    EXPECT_EQ(median_order_statistic(4, 0.80), 1);  // 2/16 = 0.125 <= 0.2
    EXPECT_NEAR(binomial_half_cdf(12, 2), 79.0 / 4096.0, kExact);
    EXPECT_THROW(median_order_statistic(6, 1.0), InputError);

    // Six records (one without a run where both stand, left out: five is too few), then a seventh: [min, max] of
    // the records' medians; the value is the pooled runs' median (the verdict's), not the medians' median.
    std::vector<std::vector<double>> by_record = {{0.0, 0.3, 0.31}, {-0.1}, {0.05, 0.07}, {}, {0.2}, {-0.02, 0.0}};
    RecordMedian five = record_median_interval(by_record);
    EXPECT_EQ(five.records, 5);
    EXPECT_EQ(five.values, 9);
    EXPECT_NEAR(five.median.value, 0.05, kExact);  // of {-0.1, -0.02, 0, 0, 0.05, 0.07, 0.2, 0.3, 0.31}
    EXPECT_TRUE(std::isnan(five.median.lo) && std::isnan(five.median.hi));
    EXPECT_EQ(five.reason, "not resolved: 5 records (a distribution-free 95 % interval of the median needs 6)");
    by_record.push_back({0.5, 0.6});
    const RecordMedian six = record_median_interval(by_record);
    EXPECT_EQ(six.reason, "");
    EXPECT_EQ(six.median.n, 6);
    EXPECT_NEAR(six.median.lo, -0.1, kExact);   // the lowest record median
    EXPECT_NEAR(six.median.hi, 0.55, kExact);   // the highest: (0.5 + 0.6) / 2
    EXPECT_NEAR(six.median.value, 0.07, kExact);  // of the 11 pooled runs
    EXPECT_TRUE(std::isnan(record_median_interval({{}, {}}).median.value));
}

TEST(RecordMedianBootstrap, PoolsTheRecordsAndCountsResamplesWithoutAValue) {
    const MedianBootstrap none = bootstrap_record_median({{}, {}});
    EXPECT_TRUE(std::isnan(none.median.value));
    EXPECT_EQ(none.median.n, 0);

    const MedianBootstrap same = bootstrap_record_median({{0.1, 0.1}, {0.1}});
    EXPECT_EQ(same.median.value, 0.1);
    EXPECT_EQ(same.median.lo, 0.1);
    EXPECT_EQ(same.median.hi, 0.1);
    EXPECT_EQ(same.values, 3);
    EXPECT_EQ(same.records, 2);

    // Two records without a run where both stand: a resample draws none of the third with probability (2/3)^3.
    BootstrapOptions o;
    o.replicates = 4000;
    const MedianBootstrap sparse = bootstrap_record_median({{}, {}, {0.3, -0.1}}, o);
    EXPECT_EQ(sparse.failed + sparse.median.n, o.replicates);
    const double share = static_cast<double>(sparse.failed) / o.replicates, expected = 8.0 / 27.0;
    EXPECT_NEAR(share, expected, 4.0 * std::sqrt(expected * (1.0 - expected) / o.replicates));  // 4 binomial s.e.
    EXPECT_NEAR(sparse.median.value, 0.1, kExact);  // the median of {0.3, -0.1}

    // Records resampled together: one record far off moves the interval's end, not the point estimate alone.
    const MedianBootstrap spread = bootstrap_record_median({{0.0, 0.01}, {0.02, -0.01}, {0.5, 0.6}, {0.0}});
    EXPECT_NEAR(spread.median.value, 0.01, kExact);
    EXPECT_LE(spread.median.lo, spread.median.value);
    EXPECT_GT(spread.median.hi, 0.2);  // resamples with two or more of the far record (p 0.26)
}

}  // namespace
}  // namespace vssw::compare

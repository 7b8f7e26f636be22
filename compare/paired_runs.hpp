#pragma once
// Paired statistics of an engine against a reference over the same runs of a record ensemble (records x intensity
// levels), on continuous and paired data rather than on two marginal shares:
//  - peaks: d = ln(engine peak / reference peak) on every run where both stand; the median of d, exp(median) being
//    the median peak ratio, with a distribution-free interval over records (a record's runs go together: runs of one
//    record at several levels are not independent): order statistics of the records' own medians;
//  - overturning: the discordant runs b (the engine overturned, the reference stood) and c (the reverse) and the
//    exact McNemar test of b against c (McNemar 1947, Psychometrika 12:153; the exact form: a two-sided binomial test
//    of b in b + c trials at p = 1/2, Fay 2010, R Journal 2(1):19).
// Pure functions, no I/O; the draws are compare/ensemble_statistics.hpp's (a seed gives the same numbers anywhere).
#include <string>
#include <vector>

#include "compare/ensemble_statistics.hpp"

namespace vssw::compare {

// Two-sided exact McNemar p-value: min(1, 2 P(X <= min(b, c))), X ~ Binomial(b + c, 1/2); 1 for b = c = 0.
// Throws InputError for a negative count.
double mcnemar_exact_p(long b, long c);

// P(X <= k) for X ~ Binomial(n, 1/2) (0 for k < 0, 1 for k >= n). Throws InputError for n < 0.
double binomial_half_cdf(long n, long k);

// The distribution-free interval for a median from n independent values each as likely below it as above (the sign
// test's interval; Conover 1999, Practical Nonparametric Statistics, 3.2): [x_(k), x_(n+1-k)] of the sorted values,
// k the largest with 2 P(X <= k - 1) <= 1 - confidence, X ~ Binomial(n, 1/2); its coverage 1 - 2 P(X <= k - 1) >=
// confidence for any continuous distribution. Returns k, 0 when no k reaches the confidence (n < 6 at 95 %: even
// [min, max] covers only 1 - 2^(1-n)). Throws InputError for n < 0 or a confidence outside (0, 1).
long median_order_statistic(long n, double confidence);

// The paired peaks' median and its interval over records: `median` the median of the pooled values of `by_record`
// (record i's values, any number, none allowed; the verdict's statistic), lo and hi the median_order_statistic
// interval of the records' own medians (records without a value left out), n the records it rests on. Fewer records
// than the confidence needs: lo and hi NaN and `reason` "not resolved: N records (...)"; no value at all: NaN, n 0.
// Coverage measured by simulation in tests/test_peak_ratio_coverage.cpp (docs/earthquakes.md, "Verdicts").
struct RecordMedian {
    Interval median;
    long values = 0;     // pooled values (runs) it rests on
    long records = 0;    // records with at least one value
    std::string reason;  // why the interval is not resolved ("" when it is)
};
RecordMedian record_median_interval(const std::vector<std::vector<double>>& by_record, double confidence = 0.95);

// The interval record_median_interval replaced, kept as the comparison the coverage test measures (on 4 records it
// covers about 79 %): the median of the pooled values of `by_record` and its percentile bootstrap interval over
// records (each replicate draws as many records with replacement and pools their values; one value per record is
// the naive bootstrap over runs).
// A replicate that drew no value is left out and counted in `failed`; Interval::n is the replicates used. No value
// at all: NaN interval with n 0. Throws as bootstrap_fit for bad options.
struct MedianBootstrap {
    Interval median;  // of the values
    long values = 0;  // pooled values (runs) it rests on
    long records = 0; // records with at least one value
    long failed = 0;  // replicates left out
};
MedianBootstrap bootstrap_record_median(const std::vector<std::vector<double>>& by_record,
                                        const BootstrapOptions& options = {});

}  // namespace vssw::compare

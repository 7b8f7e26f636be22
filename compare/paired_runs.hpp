#pragma once
// Paired statistics of an engine against a reference over the same runs of a record ensemble (records x intensity
// levels), on continuous and paired data rather than on two marginal shares:
//  - peaks: d = ln(engine peak / reference peak) on every run where both stand; the median of d with a percentile
//    bootstrap interval that resamples records (a record's runs go together: runs of one record at several levels
//    are not independent), exp(median) being the median peak ratio;
//  - overturning: the discordant runs b (the engine overturned, the reference stood) and c (the reverse) and the
//    exact McNemar test of b against c (McNemar 1947, Psychometrika 12:153; the exact form: a two-sided binomial test
//    of b in b + c trials at p = 1/2, Fay 2010, R Journal 2(1):19).
// Pure functions, no I/O; the draws are compare/ensemble_statistics.hpp's (a seed gives the same numbers anywhere).
#include <vector>

#include "compare/ensemble_statistics.hpp"

namespace vssw::compare {

// Two-sided exact McNemar p-value: min(1, 2 P(X <= min(b, c))), X ~ Binomial(b + c, 1/2); 1 for b = c = 0.
// Throws InputError for a negative count.
double mcnemar_exact_p(long b, long c);

// The median of the pooled values of `by_record` (record i's values, any number, none allowed) and its percentile
// bootstrap interval over records (each replicate draws as many records with replacement and pools their values).
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

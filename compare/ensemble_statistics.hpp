#pragma once
// The statistics of an ensemble comparison (engines against the analytic model over a set of earthquake records):
// a proportion's confidence interval, a lognormal collapse fragility fitted from incremental dynamic analysis (IDA)
// with right-censored records, bootstrap intervals of the fit (and a paired one of two fits' medians over the same
// records), quantiles of a set of values, and the count of runs inside a sensitivity band. Pure functions, no I/O;
// the random draws are the standard's exactly specified std::mt19937_64 and an index draw of our own, so a seed
// gives the same numbers with any standard library.
//
// Units: intensities (IM) in whatever unit the caller uses (e.g. PGA in g); a fit's median carries that unit, its
// beta is the dimensionless standard deviation of ln IM. Probabilities and confidences are fractions in [0, 1].
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace vssw::compare {

// A point estimate and its interval [lo, hi]; n is the count it rests on (trials for a proportion, bootstrap
// replicates used for a bootstrap interval). All NaN when it cannot be computed.
struct Interval {
    double value, lo, hi;
    long n;
};

// Standard normal CDF Phi(z) = erfc(-z / sqrt 2) / 2 (Abramowitz & Stegun 1964, 26.2.29), accurate in both tails.
double normal_cdf(double z);
// Its inverse Phi^-1(p) for 0 < p < 1 (-inf at 0, +inf at 1, NaN outside [0, 1]): Abramowitz & Stegun 26.2.23 as
// the start, then Halley steps on normal_cdf to full double precision (for 0.975: 1.959963984540054).
double normal_quantile(double p);

// ln Phi(w) and the inverse Mills ratio phi(w)/Phi(w), accurate in both tails (below w = -35 by the asymptotic series
// of Abramowitz & Stegun 26.2.12): what a likelihood of normal probabilities needs (also compare/stripe_fragility).
double log_normal_cdf(double w);
double inverse_mills(double w);

// Wilson score interval for a proportion (Wilson 1927, JASA 22:209; Brown, Cai & DasGupta 2001, Stat. Sci. 16:101,
// Eq. 4): with p = k/n and z = Phi^-1((1 + confidence)/2),
//   centre = (p + z^2/(2n)) / (1 + z^2/n),  half = z / (1 + z^2/n) * sqrt(p (1 - p)/n + z^2/(4 n^2)),
// i.e. the two roots in p' of (p - p')^2 = z^2 p' (1 - p')/n. value = k/n; lo is exactly 0 for k = 0 and hi exactly
// 1 for k = n. n = 0: NaN interval (n 0). Throws InputError unless 0 <= k <= n and 0 < confidence < 1.
Interval wilson_interval(long successes, long n, double confidence = 0.95);

// One record of an incremental dynamic analysis. collapsed: im is the intensity at which the structure first
// collapsed (overturned). Not collapsed: im is the largest intensity run, at which it still stood; its collapse
// intensity is only known to exceed im (right-censored). im > 0 and finite.
struct IdaRecord {
    double im;
    bool collapsed;
};
// The same from a list of collapse intensities: nullopt (or NaN) = did not collapse up to `cap` (the largest
// intensity run, the same for every record); a value above cap is an InputError.
std::vector<IdaRecord> ida_records(const std::vector<std::optional<double>>& collapse_im, double cap);

// Lognormal fragility P(collapse | IM = x) = Phi(ln(x / median) / beta).
struct LognormalFit {
    double median = 0.0;  // theta [unit of IM]; NaN when not fitted
    double beta = 0.0;    // dispersion of ln IM [-]; NaN when not fitted
    long records = 0;     // records given
    long collapsed = 0;   // of them collapsed (the rest right-censored)
    bool censored_mle = false;  // fitted by the censored maximum likelihood (some record censored)
    std::string reason;   // why not fitted (empty when fitted)
    bool ok() const { return reason.empty(); }
};

// Fits theta and beta to IDA records (Baker 2015, Earthquake Spectra 31(1):579-599, "Efficient analytical fragility
// function fitting using dynamic structural analysis", section on incremental dynamic analysis):
//  - no record censored: Baker's IDA estimates (his Eqs. 2-3), ln theta = (1/n) sum ln IM_i and
//    beta^2 = 1/(n - 1) sum (ln(IM_i/theta))^2.
//    theta is the maximum-likelihood estimate; beta is the MLE times sqrt(n/(n - 1)) (the unbiased variance of ln IM).
//  - some record censored: the maximum-likelihood (theta, beta) of
//      L = prod_collapsed phi(ln(IM_i/theta)/beta) / (beta IM_i) * prod_censored [1 - Phi(ln(IM_j/theta)/beta)],
//    found by Newton's method with backtracking in Olsen's parameters (gamma = 1/beta, delta = ln theta/beta), where
//    ln L is concave (Olsen 1978, Econometrica 46:1211); no small-sample correction (beta as the MLE, with n).
// Fewer than 2 collapsed records, all collapse intensities equal, or (not seen in practice: ln L is concave) Newton
// not converging in 100 iterations: NaN fit with the reason. Throws InputError for an im not finite and positive.
LognormalFit fit_lognormal_ida(const std::vector<IdaRecord>& records);

// P(collapse | IM = x) = Phi(ln(x / median) / beta); 0 for x <= 0; NaN for a fit that is not ok().
double fragility(double x, double median, double beta);
double fragility(double x, const LognormalFit& fit);

// Student's t quantile: the t with P(T <= t) = p for T with `dof` >= 1 degrees of freedom (0 < p < 1), by bisection
// on the closed-form distribution of integer degrees of freedom (Abramowitz & Stegun 1964, 26.7.3-4); for 0.975:
// 12.706 at 1, 2.776 at 4, 2.093 at 19. Throws InputError for dof < 1 or p outside (0, 1).
double student_t_quantile(double p, long dof);

// The smallest record counts at which a percentile bootstrap interval of a fragility median is shown (below them its
// ends are NaN and the reason says why): measured coverage of the nominal 95 % interval on lognormal capacities
// (tests/test_fragility_coverage.cpp; docs/earthquakes.md): stripes 0.76-0.83 at 3 records, 0.90 at 4, 0.92-0.94 at
// 5-20; the censored IDA fit 0.62 at 3, 0.80 at 4, 0.89 at 8, 0.92 at 12. Shown where it misses at most about twice
// as often as it claims. Without censoring the IDA median's interval is Student's t on ln IM, exact at any n >= 2.
inline constexpr long kMinStripeIntervalRecords = 5;
inline constexpr long kMinCensoredIntervalRecords = 12;

// Bootstrap (Efron & Tibshirani 1993, An Introduction to the Bootstrap, Ch. 13 percentile interval): `replicates`
// resamples of the records, n drawn with replacement each, refitted; the interval is the type-7 quantiles
// (quantile() below) at (1 -/+ confidence)/2 of the replicates' estimates. When any record is censored every
// replicate is fitted by the censored MLE (beta with divisor n even in a replicate that drew no censored record), so
// that all replicates estimate the same thing. A replicate whose fit fails (fewer than 2 collapsed records drawn,
// or all drawn collapses the same record) is left out and counted in `failed`; Interval::n is the number used.
// The full fit failing: NaN intervals with n 0. Throws InputError for replicates < 1, a confidence outside (0, 1)
// or a record fit_lognormal_ida refuses.
struct BootstrapOptions {
    int replicates = 2000;
    double confidence = 0.95;
    std::uint64_t seed = 20150401;  // std::mt19937_64's seed
};
// The percentile interval of bootstrap replicates' estimates around `value` (type-7 quantiles at (1 -/+ confidence)
// / 2; NaN with n 0 for none); InputError unless replicates >= 1 and 0 < confidence < 1.
Interval percentile_interval(double value, std::vector<double> replicates, double confidence);
void check_bootstrap_options(const BootstrapOptions& options);
// The median's interval of an IDA fit without censored records is instead exp(ln theta -/+ t s / sqrt(n)), s the
// deviation of ln IM (beta) and t Student's at n - 1 degrees of freedom: exact for lognormal capacities, where the
// percentile bootstrap covers 0.64 at 3 records and 0.79 at 4; its n is then the records. Below
// kMinCensoredIntervalRecords (censored) or kMinStripeIntervalRecords (stripes) the intervals' ends are NaN and
// interval_reason ("not resolved: ...") says why.
struct FitBootstrap {
    LognormalFit fit;  // the fit to all records (the intervals' values)
    Interval median;   // [unit of IM]
    Interval beta;     // [-]
    long failed = 0;   // replicates left out
    std::string interval_reason;  // why the intervals are not shown (empty when they are)
};
FitBootstrap bootstrap_fit(const std::vector<IdaRecord>& records, const BootstrapOptions& options = {});

// Paired bootstrap of median(engine) / median(reference) over the same records: engine[i] and reference[i] are
// record i under the two models; each replicate draws one set of record indices and refits both. value is the
// ratio of the full fits (NaN, with n 0, when either fails). A replicate is left out (counted in failed) when
// either fit fails. Without censored records on either side the interval is instead the paired t interval of
// d_i = ln(engine_i / reference_i), exp(mean d -/+ t s_d / sqrt(n)) (the ratio of the two fits' medians is exactly
// exp(mean d)); with censoring, fewer than kMinCensoredIntervalRecords pairs leave the ends NaN with the reason.
// Throws InputError when the two lists differ in length.
struct RatioBootstrap {
    Interval ratio;  // [-]
    long failed = 0;
    std::string reason;  // why the interval is not shown (empty when it is)
};
RatioBootstrap bootstrap_median_ratio(const std::vector<IdaRecord>& engine, const std::vector<IdaRecord>& reference,
                                      const BootstrapOptions& options = {});

// Uniform index in [0, n) from one or more draws of `rng`: a draw x in the top 2^64 mod n values is rejected (so
// that every residue is equally likely), then x mod n. The same on every standard library, unlike
// std::uniform_int_distribution. n >= 1.
std::uint64_t uniform_index(std::mt19937_64& rng, std::uint64_t n);

// Sample quantile of type 7 (Hyndman & Fan 1996, Am. Stat. 50:361; R's default, numpy's "linear"): for the sorted
// values x_0 <= ... <= x_(n-1) and h = (n - 1) p, x_floor(h) + (h - floor(h)) (x_floor(h)+1 - x_floor(h)).
// NaN values are left out; none left: NaN. Throws InputError unless 0 <= p <= 1.
double quantile(const std::vector<double>& values, double p);
// Lower quartile, median and upper quartile (type 7) of the non-NaN values; n of them used, nan the count left out.
struct Quartiles {
    double q1, median, q3;
    long n, nan;
};
Quartiles quartiles(const std::vector<double>& values);

// One run for the sensitivity band: the reference model's value, the band [lo, hi] spanned by the perturbed
// reference runs, and the engine's value (any unit, the same for all four).
struct BandRun {
    double reference, lo, hi, engine;
};
// inside: runs with lo <= engine <= hi (closed band, not widened). outside: indices of the other runs, in order,
// NaN engine or band included. reference_outside: indices whose reference value itself lies outside its band (a
// band that does not hold its own reference is worth a look). Throws InputError for a band with lo > hi.
struct BandCount {
    long runs = 0, inside = 0;
    std::vector<std::size_t> outside;
    std::vector<std::size_t> reference_outside;
};
BandCount count_inside_band(const std::vector<BandRun>& runs);

}  // namespace vssw::compare

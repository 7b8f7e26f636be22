#include "compare/ensemble_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "analytic/error.hpp"
#include "compare/record_bootstrap.hpp"

namespace vssw::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kSqrt2Pi = 2.50662827463100050242;  // sqrt(2 pi)
constexpr double kPi = 3.14159265358979323846;

Interval nan_interval(long n) { return {kNaN, kNaN, kNaN, n}; }



// Type-7 quantile of values already sorted, none NaN, at least one.
double quantile_sorted(const std::vector<double>& x, double p) {
    const double h = static_cast<double>(x.size() - 1) * p;
    const auto lo = static_cast<std::size_t>(std::floor(h));
    if (lo + 1 >= x.size()) return x.back();
    // On a value, or between equal ones, that value: an infinity (an overturned run's peak, study/
    // overturned_runs.hpp) is not turned into 0 * inf or inf - inf, NaN. Finite values give what interpolation gives.
    const double f = h - static_cast<double>(lo);
    if (f == 0.0 || x[lo + 1] == x[lo]) return x[lo];
    return x[lo] + f * (x[lo + 1] - x[lo]);
}

std::vector<double> sorted_without_nan(const std::vector<double>& values) {
    std::vector<double> x;
    x.reserve(values.size());
    for (double v : values)
        if (!std::isnan(v)) x.push_back(v);
    std::sort(x.begin(), x.end());
    return x;
}

// Censored maximum likelihood in Olsen's parameters d = mu/beta, g = 1/beta (mu = ln theta), on logs shifted by
// `shift` (the collapsed records' mean log, which keeps d near 0). Per record, with y = ln IM - shift:
//   collapsed: l = -(g y - d)^2 / 2 + ln g     (dropping the constants -ln sqrt(2 pi) - ln IM)
//   censored:  l = ln Phi(d - g y)              (= ln[1 - Phi((ln IM - mu)/beta)])
// Both concave in (d, g) (ln Phi is log-concave), so Newton's method with backtracking finds the one maximum.
struct CensoredData {
    std::vector<double> collapsed;  // shifted logs
    std::vector<double> censored;   // shifted logs of the censoring intensities
};

struct Derivatives {
    double value = 0.0;           // ln L
    double gd = 0.0, gg = 0.0;    // gradient
    double hdd = 0.0, hdg = 0.0, hgg = 0.0;  // Hessian
};

Derivatives log_likelihood(const CensoredData& data, double d, double g, bool with_derivatives) {
    Derivatives r;
    for (double y : data.collapsed) {
        const double z = g * y - d;
        r.value += -0.5 * z * z + std::log(g);
        if (!with_derivatives) continue;
        r.gd += z;
        r.gg += -z * y + 1.0 / g;
        r.hdd += -1.0;
        r.hdg += y;
        r.hgg += -y * y - 1.0 / (g * g);
    }
    for (double c : data.censored) {
        const double w = d - g * c;
        r.value += log_normal_cdf(w);
        if (!with_derivatives) continue;
        const double lambda = inverse_mills(w);  // d ln Phi / dw
        const double curvature = -lambda * (w + lambda);  // d^2 ln Phi / dw^2
        r.gd += lambda;
        r.gg += -lambda * c;
        r.hdd += curvature;
        r.hdg += -curvature * c;
        r.hgg += curvature * c * c;
    }
    return r;
}

// Maximises ln L from (d, g); returns false when it does not converge in kMaxIterations. Converged: the Newton
// decrement grad . s (twice the predicted gain, about n times the squared relative step since ln L ~ n) is below
// kDecrementTolerance (1 + |ln L|), i.e. the step is below about 1e-9 relative; that last step is taken, leaving
// an error of about its square, below rounding. A stricter test would chase the rounding noise of the gradient.
bool newton_censored(const CensoredData& data, double& d, double& g) {
    constexpr int kMaxIterations = 100;
    constexpr int kMaxHalvings = 60;
    constexpr double kDecrementTolerance = 1e-18;
    constexpr double kArmijo = 1e-4;  // sufficient-increase fraction of the backtracking line search
    for (int it = 0; it < kMaxIterations; ++it) {
        const Derivatives f = log_likelihood(data, d, g, true);
        const double det = f.hdd * f.hgg - f.hdg * f.hdg;  // > 0: the Hessian is negative definite
        if (!(det > 0.0) || !std::isfinite(det)) return false;
        const double sd = -(f.hgg * f.gd - f.hdg * f.gg) / det;  // s = -H^-1 grad
        const double sg = -(-f.hdg * f.gd + f.hdd * f.gg) / det;
        const double decrement = f.gd * sd + f.gg * sg;  // grad . s >= 0
        const bool converged = decrement <= kDecrementTolerance * (1.0 + std::abs(f.value));
        if (converged && g + sg > 0.0) {
            d += sd;
            g += sg;
            return true;
        }
        double t = 1.0;
        int halvings = 0;
        for (; halvings < kMaxHalvings; ++halvings, t *= 0.5) {
            if (g + t * sg <= 0.0) continue;
            const double value = log_likelihood(data, d + t * sd, g + t * sg, false).value;
            if (value >= f.value + kArmijo * t * decrement) break;
        }
        const bool moved = halvings < kMaxHalvings && (d + t * sd != d || g + t * sg != g);
        // No increase possible: at the maximum to rounding when the predicted gain is at rounding level of ln L.
        if (!moved) return decrement <= 1e-12 * (1.0 + std::abs(f.value));
        d += t * sd;
        g += t * sg;
    }
    return false;
}

LognormalFit not_fitted(LognormalFit fit, std::string reason) {
    fit.median = kNaN;
    fit.beta = kNaN;
    fit.reason = std::move(reason);
    return fit;
}

// The fit; mle: beta as the maximum-likelihood estimate (divisor n) also without censoring, as the bootstrap's
// replicates of a censored sample use (a replicate that draws no censored record keeps the same estimator).
LognormalFit fit_impl(const std::vector<IdaRecord>& records, bool mle) {
    LognormalFit fit;
    fit.records = static_cast<long>(records.size());
    double sum = 0.0;
    for (const IdaRecord& r : records) {
        if (!r.collapsed) continue;
        ++fit.collapsed;
        sum += std::log(r.im);
    }
    if (fit.collapsed < 2)
        return not_fitted(fit, "fewer than 2 collapsed records (" + std::to_string(fit.collapsed) + " of " +
                                   std::to_string(fit.records) + ")");
    const double k = static_cast<double>(fit.collapsed);
    const double mean = sum / k;
    CensoredData data;
    double squares = 0.0;
    for (const IdaRecord& r : records) {
        const double y = std::log(r.im) - mean;
        if (r.collapsed) {
            data.collapsed.push_back(y);
            squares += y * y;
        } else {
            data.censored.push_back(y);
        }
    }
    if (squares == 0.0) return not_fitted(fit, "all collapse intensities equal (beta would be 0)");
    if (data.censored.empty()) {  // Baker's closed form; with mle, the divisor n of the MLE
        fit.median = std::exp(mean);
        fit.beta = std::sqrt(squares / (mle ? k : k - 1.0));
        return fit;
    }
    fit.censored_mle = true;
    double g = 1.0 / std::sqrt(squares / k);  // start: the collapsed records' own MLE
    double d = 0.0;
    if (!newton_censored(data, d, g))
        return not_fitted(fit, "censored maximum likelihood did not converge");
    fit.median = std::exp(mean + d / g);
    fit.beta = 1.0 / g;
    return fit;
}

void check_records(const std::vector<IdaRecord>& records) {
    for (const IdaRecord& r : records)
        require(std::isfinite(r.im) && r.im > 0.0, "an IDA record's intensity", "finite and positive", r.im);
}

bool any_censored(const std::vector<IdaRecord>& records) {
    return std::any_of(records.begin(), records.end(), [](const IdaRecord& r) { return !r.collapsed; });
}



// P(|T| <= t) for Student's T with integer dof (Abramowitz & Stegun 26.7.3-4), theta = atan(t / sqrt(dof)):
// odd dof, (2/pi) (theta + sin cos (1 + 2/3 cos^2 + 2*4/(3*5) cos^4 + ...)) (the sum empty at 1);
// even dof, sin (1 + 1/2 cos^2 + 1*3/(2*4) cos^4 + ...), up to cos^(dof - 2) in both.
double student_t_two_sided(double t, long dof) {
    const double theta = std::atan(t / std::sqrt(static_cast<double>(dof)));
    const double c2 = std::cos(theta) * std::cos(theta);
    const bool odd = dof % 2 == 1;
    double term = 1.0, sum = odd && dof == 1 ? 0.0 : 1.0;
    for (long k = 1; 2 * k <= dof - (odd ? 3 : 2); ++k) {
        const double two_k = 2.0 * static_cast<double>(k);
        term *= c2 * (odd ? two_k / (two_k + 1.0) : (two_k - 1.0) / two_k);
        sum += term;
    }
    return odd ? 2.0 / kPi * (theta + std::sin(theta) * std::cos(theta) * sum) : std::sin(theta) * sum;
}

// exp(mean -/+ t s / sqrt(n)) of ln values: the t interval of their mean, back in the values' unit.
Interval log_t_interval(const std::vector<double>& logs, double confidence) {
    const double n = static_cast<double>(logs.size());
    double mean = 0.0, squares = 0.0;
    for (double y : logs) mean += y / n;
    for (double y : logs) squares += (y - mean) * (y - mean);
    const long dof = static_cast<long>(logs.size()) - 1;
    const double half = student_t_quantile(0.5 * (1.0 + confidence), dof) * std::sqrt(squares / (n - 1.0) / n);
    return {std::exp(mean), std::exp(mean - half), std::exp(mean + half), static_cast<long>(logs.size())};
}

}  // namespace

double student_t_quantile(double p, long dof) {
    require(dof >= 1, "Student's t degrees of freedom", "at least 1", static_cast<double>(dof));
    require(p > 0.0 && p < 1.0, "Student's t probability", "in (0, 1)", p);
    if (p < 0.5) return -student_t_quantile(1.0 - p, dof);
    const double target = 2.0 * p - 1.0;  // P(|T| <= t)
    double lo = 0.0, hi = 1.0;
    while (student_t_two_sided(hi, dof) < target) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {  // bisection to the last bits
        const double mid = 0.5 * (lo + hi);
        (student_t_two_sided(mid, dof) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / kSqrt2); }

// ln Phi(w), accurate in both tails: log1p(-Phi(-w)) above 0; below -35 (Phi(w) < 1e-267, near underflow) the
// asymptotic series Phi(w) = phi(w)/|w| (1 - 1/w^2 + 3/w^4 - ...) (Abramowitz & Stegun 26.2.12), whose next term,
// 15/w^6, is below 1e-8 of the sum there.
double log_normal_cdf(double w) {
    if (w > 0.0) return std::log1p(-normal_cdf(-w));
    if (w > -35.0) return std::log(normal_cdf(w));
    const double w2 = w * w;
    return -0.5 * w2 - std::log(-w * kSqrt2Pi) + std::log1p(-1.0 / w2 + 3.0 / (w2 * w2));
}

// The inverse Mills ratio phi(w)/Phi(w), with the same asymptotic series below -35.
double inverse_mills(double w) {
    if (w > -35.0) return std::exp(-0.5 * w * w) / kSqrt2Pi / normal_cdf(w);
    const double w2 = w * w;
    return -w / (1.0 - 1.0 / w2 + 3.0 / (w2 * w2));
}

// The percentile interval of replicate estimates around `value`.
Interval percentile_interval(double value, std::vector<double> replicates, double confidence) {
    if (replicates.empty()) return nan_interval(0);
    std::sort(replicates.begin(), replicates.end());
    const double alpha = 1.0 - confidence;
    return {value, quantile_sorted(replicates, 0.5 * alpha), quantile_sorted(replicates, 1.0 - 0.5 * alpha),
            static_cast<long>(replicates.size())};
}

void check_bootstrap_options(const BootstrapOptions& options) {
    require(options.replicates >= 1, "bootstrap replicates", "at least 1", options.replicates);
    require(options.confidence > 0.0 && options.confidence < 1.0, "bootstrap confidence", "in (0, 1)",
            options.confidence);
}

double normal_quantile(double p) {
    if (std::isnan(p) || p < 0.0 || p > 1.0) return kNaN;
    if (p == 0.0) return -kInf;
    if (p == 1.0) return kInf;
    if (p == 0.5) return 0.0;
    const double q = std::min(p, 1.0 - p);  // 1 - p is exact for p >= 0.5 (Sterbenz)
    // Abramowitz & Stegun 26.2.23: the upper-tail point of probability q, |error| < 4.5e-4.
    const double t = std::sqrt(-2.0 * std::log(q));
    double x = -(t - (2.515517 + t * (0.802853 + t * 0.010328)) /
                         (1.0 + t * (1.432788 + t * (0.189269 + t * 0.001308))));
    // Halley's method on Phi(x) = q in the lower tail, where normal_cdf is accurate to a few ulps relative: cubic
    // convergence from 4.5e-4 reaches rounding level in 2-3 steps.
    for (int i = 0; i < 8; ++i) {
        const double u = (normal_cdf(x) - q) * kSqrt2Pi * std::exp(0.5 * x * x);
        const double step = u / (1.0 + 0.5 * x * u);
        x -= step;
        if (std::abs(step) <= 1e-16 * std::abs(x)) break;
    }
    return p < 0.5 ? x : -x;
}

Interval wilson_interval(long successes, long n, double confidence) {
    require(n >= 0, "the number of trials", "at least 0", static_cast<double>(n));
    require(successes >= 0 && successes <= n, "the number of successes", "in [0, trials]",
            static_cast<double>(successes));
    require(confidence > 0.0 && confidence < 1.0, "the confidence", "in (0, 1)", confidence);
    if (n == 0) return nan_interval(0);
    const double z = normal_quantile(0.5 * (1.0 + confidence));
    const double nn = static_cast<double>(n);
    const double p = static_cast<double>(successes) / nn;
    const double z2n = z * z / nn;
    const double centre = (p + 0.5 * z2n) / (1.0 + z2n);
    const double half = z / (1.0 + z2n) * std::sqrt(p * (1.0 - p) / nn + 0.25 * z2n / nn);
    // The interval holds p in exact arithmetic ((p - p')^2 <= z^2 p'(1 - p')/n at p' = p); the clamps keep it so
    // under rounding, and make the ends exact at k = 0 and k = n, where one root is 0 or 1.
    const double lo = successes == 0 ? 0.0 : std::clamp(centre - half, 0.0, p);
    const double hi = successes == n ? 1.0 : std::clamp(centre + half, p, 1.0);
    return {p, lo, hi, n};
}

std::vector<IdaRecord> ida_records(const std::vector<std::optional<double>>& collapse_im, double cap) {
    require(std::isfinite(cap) && cap > 0.0, "the largest intensity run (cap)", "finite and positive", cap);
    std::vector<IdaRecord> out;
    out.reserve(collapse_im.size());
    for (const std::optional<double>& im : collapse_im) {
        if (!im || std::isnan(*im)) {
            out.push_back({cap, false});
            continue;
        }
        require(std::isfinite(*im) && *im > 0.0 && *im <= cap, "a collapse intensity", "in (0, cap]", *im);
        out.push_back({*im, true});
    }
    return out;
}

LognormalFit fit_lognormal_ida(const std::vector<IdaRecord>& records) {
    check_records(records);
    return fit_impl(records, false);
}

double fragility(double x, double median, double beta) {
    if (std::isnan(x) || !(median > 0.0) || !(beta > 0.0)) return kNaN;
    if (x <= 0.0) return 0.0;
    return normal_cdf(std::log(x / median) / beta);
}

double fragility(double x, const LognormalFit& fit) { return fit.ok() ? fragility(x, fit.median, fit.beta) : kNaN; }

std::uint64_t uniform_index(std::mt19937_64& rng, std::uint64_t n) {
    const std::uint64_t rejected = (UINT64_MAX % n + 1) % n;  // 2^64 mod n: the top values that would favour some
    std::uint64_t x = rng();
    while (rejected != 0 && x >= 0 - rejected) x = rng();  // 0 - rejected = 2^64 - rejected
    return x % n;
}

FitBootstrap bootstrap_fit(const std::vector<IdaRecord>& records, const BootstrapOptions& options) {
    check_records(records);
    check_bootstrap_options(options);
    const bool mle = any_censored(records);
    FitBootstrap out = bootstrap_records(
        records, fit_impl(records, false), [mle](const std::vector<IdaRecord>& sample) { return fit_impl(sample, mle); },
        options);
    if (mle) {
        unresolve_below(out, static_cast<long>(records.size()), kMinCensoredIntervalRecords);
    } else if (out.fit.ok()) {
        std::vector<double> logs;
        for (const IdaRecord& r : records) logs.push_back(std::log(r.im));
        out.median = log_t_interval(logs, options.confidence);
        out.median.value = out.fit.median;  // the same number; the fit's own, to the bit
    }
    return out;
}

RatioBootstrap bootstrap_median_ratio(const std::vector<IdaRecord>& engine, const std::vector<IdaRecord>& reference,
                                      const BootstrapOptions& options) {
    require(engine.size() == reference.size(), "the engine's record count", "the reference's",
            static_cast<double>(engine.size()));
    check_records(engine);
    check_records(reference);
    check_bootstrap_options(options);
    const bool engine_mle = any_censored(engine), reference_mle = any_censored(reference);
    RatioBootstrap out = bootstrap_paired_ratio(
        engine, reference, fit_impl(engine, false), fit_impl(reference, false),
        [engine_mle](const std::vector<IdaRecord>& sample) { return fit_impl(sample, engine_mle); },
        [reference_mle](const std::vector<IdaRecord>& sample) { return fit_impl(sample, reference_mle); }, options);
    if (engine_mle || reference_mle) {
        unresolve_below(out, static_cast<long>(engine.size()), kMinCensoredIntervalRecords);
    } else if (std::isfinite(out.ratio.value)) {
        std::vector<double> d;
        for (std::size_t i = 0; i < engine.size(); ++i) d.push_back(std::log(engine[i].im / reference[i].im));
        const double value = out.ratio.value;
        out.ratio = log_t_interval(d, options.confidence);
        out.ratio.value = value;  // the two fits' ratio, to the bit
    }
    return out;
}

double quantile(const std::vector<double>& values, double p) {
    require(p >= 0.0 && p <= 1.0, "the quantile's probability", "in [0, 1]", p);
    const std::vector<double> x = sorted_without_nan(values);
    return x.empty() ? kNaN : quantile_sorted(x, p);
}

Quartiles quartiles(const std::vector<double>& values) {
    const std::vector<double> x = sorted_without_nan(values);
    const long n = static_cast<long>(x.size());
    const long nan = static_cast<long>(values.size()) - n;
    if (x.empty()) return {kNaN, kNaN, kNaN, 0, nan};
    return {quantile_sorted(x, 0.25), quantile_sorted(x, 0.5), quantile_sorted(x, 0.75), n, nan};
}

BandCount count_inside_band(const std::vector<BandRun>& runs) {
    BandCount out;
    out.runs = static_cast<long>(runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const BandRun& r = runs[i];
        require(!(r.lo > r.hi), "a sensitivity band's lower end", "at most its upper end", r.lo);
        if (r.engine >= r.lo && r.engine <= r.hi)
            ++out.inside;
        else
            out.outside.push_back(i);
        if (!(r.reference >= r.lo && r.reference <= r.hi)) out.reference_outside.push_back(i);
    }
    return out;
}

}  // namespace vssw::compare

#include "motions/special_functions.hpp"

#include <cmath>
#include <limits>

namespace vssw::motions {
namespace {

// Relative size of a series term or continued-fraction correction below which the sum is complete (double's epsilon).
constexpr double kEps = 1e-16;
// Far more terms than either expansion takes for the arguments the generator uses (shape parameters below 1e5).
constexpr int kMaxTerms = 100000;
// Lentz's guard against a zero denominator.
constexpr double kTiny = 1e-300;

// Bisection of an increasing f on [lo, hi] for f(x) = p, to 1e-16 relative (or adjacent doubles).
template <class F>
double bisect(F f, double p, double lo, double hi) {
    for (int i = 0; i < 2000; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi || hi - lo <= kEps * std::fabs(hi)) break;
        (f(mid) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The continued fraction of I_x(a, b) (modified Lentz), converging for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
    double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
    if (std::fabs(d) < kTiny) d = kTiny;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m <= kMaxTerms; ++m) {
        const double m2 = 2.0 * m;
        double aa = m * (b - m) * x / ((a - 1.0 + m2) * (a + m2));
        d = 1.0 + aa * d;
        c = 1.0 + aa / c;
        if (std::fabs(d) < kTiny) d = kTiny;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        h *= d * c;
        aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + 1.0 + m2));
        d = 1.0 + aa * d;
        c = 1.0 + aa / c;
        if (std::fabs(d) < kTiny) d = kTiny;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double step = d * c;
        h *= step;
        if (std::fabs(step - 1.0) < kEps) break;
    }
    return h;
}

}  // namespace

double gamma_p(double a, double x) {
    if (!(x > 0.0)) return 0.0;
    const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {  // the series converges fast here
        double term = 1.0 / a, sum = term;
        for (int n = 1; n <= kMaxTerms && std::fabs(term) > std::fabs(sum) * kEps; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::fmin(1.0, sum * std::exp(log_prefactor));
    }
    // Q(a, x) by its continued fraction (modified Lentz).
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i <= kMaxTerms; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double step = d * c;
        h *= step;
        if (std::fabs(step - 1.0) < kEps) break;
    }
    return std::fmax(0.0, 1.0 - std::exp(log_prefactor) * h);
}

double gamma_p_inverse(double a, double p) {
    double hi = a + 1.0;
    while (gamma_p(a, hi) < p && hi < std::numeric_limits<double>::max() / 4) hi *= 2.0;
    return bisect([a](double x) { return gamma_p(a, x); }, p, 0.0, hi);
}

double beta_i(double a, double b, double x) {
    if (!(x > 0.0)) return 0.0;
    if (!(x < 1.0)) return 1.0;
    const double log_front =
        std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
    if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(log_front) * beta_fraction(a, b, x) / a;
    return 1.0 - std::exp(log_front) * beta_fraction(b, a, 1.0 - x) / b;
}

double beta_i_inverse(double a, double b, double p) {
    return bisect([a, b](double x) { return beta_i(a, b, x); }, p, 0.0, 1.0);
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double normal_quantile(double p) { return bisect(normal_cdf, p, -40.0, 40.0); }

}  // namespace vssw::motions

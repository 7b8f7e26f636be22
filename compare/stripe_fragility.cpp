#include "compare/stripe_fragility.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "compare/record_bootstrap.hpp"

namespace vssw::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kNewtonIterations = 200;
// Newton stops when the predicted gain of ln L (the Newton decrement's half square) is this small: ln L is a sum of
// counts times logs of order 1-100, so 1e-12 is round-off.
constexpr double kDecrement = 1e-12;
// Backtracking halves a Newton step down to this fraction of it: 40 halvings, past any step that could still raise
// a concave ln L in doubles.
constexpr double kSmallestStep = 1e-12;
// A fit the data do not support is "not resolved", never a number (docs/earthquakes.md, "Verdicts"). beta above this: the shares hardly
// change over the levels (flat stripes gave beta 2e7); between 16 % and 84 % collapse the intensity would grow
// e^(2 beta) = 55-fold, where the rocking walls measured span beta 0.25-0.6 (PGA, PGV) and 1.2 at most (Arias).
constexpr double kMaxResolvedBeta = 2.0;
// beta below this: the shares jump from 16 % to 84 % within +-2 % of the intensity, finer than the intensity's own
// uncertainty (+-1 %, docs/earthquakes.md) and than any ensemble's levels (beta 7e-17 was fitted).
constexpr double kMinResolvedBeta = 0.02;
// Fewer records than this: a median and beta from two records are no fit (the median's standard error beta/sqrt(n)).
constexpr long kMinResolvedRecords = 3;
constexpr const char* kFalling = "the share collapsed falls as the intensity rises";
constexpr const char* kSeparated =
    "the stripes do not overlap (no run stands at a level above one where a run collapsed): no finite beta";

// The counts the likelihood needs: per level ln x_j, runs n_j and collapses z_j.
struct Stripes {
    std::vector<double> log_level;
    std::vector<double> runs, collapsed;
};

Stripes count(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records) {
    Stripes s;
    s.runs.assign(levels.size(), 0.0);
    s.collapsed.assign(levels.size(), 0.0);
    for (double x : levels) s.log_level.push_back(std::log(x));
    for (const StripeOutcomes& r : records)
        for (std::size_t j = 0; j < levels.size(); ++j) {
            if (r[j] < 0) continue;
            s.runs[j] += 1.0;
            s.collapsed[j] += r[j] > 0 ? 1.0 : 0.0;
        }
    return s;
}

// ln L and its gradient and Hessian in (gamma, delta), u_j = gamma ln x_j - delta.
struct Local {
    double value = 0.0, g_gamma = 0.0, g_delta = 0.0, h_gg = 0.0, h_gd = 0.0, h_dd = 0.0;
};
Local local(const Stripes& s, double gamma, double delta) {
    Local l;
    for (std::size_t j = 0; j < s.runs.size(); ++j) {
        if (s.runs[j] == 0.0) continue;
        const double u = gamma * s.log_level[j] - delta, z = s.collapsed[j], stood = s.runs[j] - z;
        l.value += z * log_normal_cdf(u) + stood * log_normal_cdf(-u);
        const double up = inverse_mills(u), down = inverse_mills(-u);  // phi/Phi(u), phi/Phi(-u)
        const double d1 = z * up - stood * down;                            // d lnL / du
        const double d2 = -z * up * (up + u) - stood * down * (down - u);  // d2 lnL / du2 (< 0)
        const double x = s.log_level[j];
        l.g_gamma += d1 * x;
        l.g_delta -= d1;
        l.h_gg += d2 * x * x;
        l.h_gd -= d2 * x;
        l.h_dd += d2;
    }
    return l;
}

LognormalFit not_fitted(LognormalFit fit, const std::string& why) {
    fit.median = fit.beta = kNaN;
    fit.reason = "not resolved: " + why;  // every stripe fit not made is one the data do not support
    return fit;
}

LognormalFit fit(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records) {
    LognormalFit out;
    out.censored_mle = false;
    const Stripes s = count(levels, records);
    double runs = 0.0, collapsed = 0.0, mean_log = 0.0;
    for (std::size_t j = 0; j < s.runs.size(); ++j) {
        runs += s.runs[j];
        collapsed += s.collapsed[j];
        mean_log += s.runs[j] * s.log_level[j];
    }
    for (const StripeOutcomes& r : records)
        for (int o : r)
            if (o >= 0) {
                ++out.records;
                break;
            }
    out.collapsed = static_cast<long>(collapsed);
    if (out.records < kMinResolvedRecords)
        return not_fitted(out, fmt::format("{} records (a fit needs {})", out.records,
                                           kMinResolvedRecords));
    if (collapsed == 0.0 || collapsed == runs)
        return not_fitted(out, collapsed == 0.0 ? "no run collapsed" : "every run collapsed");
    // A finite maximum needs the outcomes to overlap: some run standing at a higher level than some run collapsing.
    // Otherwise (every run up to a level stands, every run from it collapses) ln L climbs for ever as beta -> 0.
    // The mirror image (every collapse below every standing run) has its maximum at beta -> 0 with a falling share.
    double lowest_collapse = HUGE_VAL, highest_standing = -HUGE_VAL;
    double highest_collapse = -HUGE_VAL, lowest_standing = HUGE_VAL;
    for (std::size_t j = 0; j < s.runs.size(); ++j) {
        if (s.runs[j] == 0.0) continue;
        if (s.collapsed[j] > 0.0) {
            lowest_collapse = std::min(lowest_collapse, s.log_level[j]);
            highest_collapse = std::max(highest_collapse, s.log_level[j]);
        }
        if (s.collapsed[j] < s.runs[j]) {
            highest_standing = std::max(highest_standing, s.log_level[j]);
            lowest_standing = std::min(lowest_standing, s.log_level[j]);
        }
    }
    if (!(highest_standing > lowest_collapse)) return not_fitted(out, kSeparated);
    if (!(highest_collapse > lowest_standing)) return not_fitted(out, kFalling);
    // Start at beta 0.5 and the median at the runs' mean log level; Newton with backtracking on the concave ln L.
    double gamma = 2.0, delta = gamma * mean_log / runs;
    Local l = local(s, gamma, delta);
    for (int i = 0; i < kNewtonIterations; ++i) {
        const double det = l.h_gg * l.h_dd - l.h_gd * l.h_gd;
        if (!(det > 0.0)) return not_fitted(out, "the likelihood has no curvature here (too few distinct levels)");
        const double step_g = -(l.h_dd * l.g_gamma - l.h_gd * l.g_delta) / det;
        const double step_d = -(-l.h_gd * l.g_gamma + l.h_gg * l.g_delta) / det;
        const double decrement = 0.5 * (l.g_gamma * step_g + l.g_delta * step_d);
        if (decrement < kDecrement) {
            if (!(gamma > 0.0)) return not_fitted(out, kFalling);
            if (1.0 / gamma > kMaxResolvedBeta || 1.0 / gamma < kMinResolvedBeta)
                return not_fitted(out, fmt::format("beta {:.3g} outside [{:g}, {:g}] (the stripes {})",
                                                   1.0 / gamma, kMinResolvedBeta, kMaxResolvedBeta,
                                                   1.0 / gamma > kMaxResolvedBeta ? "are flat" : "barely overlap"));
            out.median = std::exp(delta / gamma);
            out.beta = 1.0 / gamma;
            return out;
        }
        double t = 1.0;
        Local next = local(s, gamma + t * step_g, delta + t * step_d);
        while (!(next.value >= l.value) && t > kSmallestStep) {
            t *= 0.5;
            next = local(s, gamma + t * step_g, delta + t * step_d);
        }
        if (!(next.value >= l.value)) return not_fitted(out, "no Newton step raises the likelihood (round-off)");
        gamma += t * step_g;
        delta += t * step_d;
        l = next;
    }
    return not_fitted(out, "the likelihood's maximum was not found in " + std::to_string(kNewtonIterations) +
                               " Newton steps");
}

void check(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records) {
    for (double x : levels) require(std::isfinite(x) && x > 0.0, "a stripe's intensity", "finite and positive", x);
    for (const StripeOutcomes& r : records)
        require(r.size() == levels.size(), "a record's stripe outcomes", "one per level",
                static_cast<double>(r.size()));
}

}  // namespace

LognormalFit fit_lognormal_stripes(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records) {
    check(levels, records);
    return fit(levels, records);
}

FitBootstrap bootstrap_stripes(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records,
                               const BootstrapOptions& options) {
    check(levels, records);
    check_bootstrap_options(options);
    const auto refit = [&levels](const std::vector<StripeOutcomes>& sample) { return fit(levels, sample); };
    FitBootstrap out = bootstrap_records(records, fit(levels, records), refit, options);
    unresolve_below(out, out.fit.records, kMinStripeIntervalRecords);
    return out;
}

RatioBootstrap bootstrap_stripe_median_ratio(const std::vector<double>& levels,
                                             const std::vector<StripeOutcomes>& engine,
                                             const std::vector<StripeOutcomes>& reference,
                                             const BootstrapOptions& options) {
    require(engine.size() == reference.size(), "the engine's record count", "the reference's",
            static_cast<double>(engine.size()));
    check(levels, engine);
    check(levels, reference);
    check_bootstrap_options(options);
    const auto refit = [&levels](const std::vector<StripeOutcomes>& sample) { return fit(levels, sample); };
    RatioBootstrap out = bootstrap_paired_ratio(engine, reference, fit(levels, engine), fit(levels, reference), refit,
                                                refit, options);
    unresolve_below(out, static_cast<long>(engine.size()), kMinStripeIntervalRecords);
    return out;
}

}  // namespace vssw::compare

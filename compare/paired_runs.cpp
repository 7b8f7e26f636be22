#include "compare/paired_runs.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::compare {

double binomial_half_cdf(long n, long k) {
    if (n < 0) throw InputError("a binomial's trials must be non-negative");
    if (k >= n) return 1.0;
    // Each term C(n, i) 2^-n in logs (no overflow for any n).
    double tail = 0.0;
    for (long i = 0; i <= k; ++i)
        tail += std::exp(std::lgamma(static_cast<double>(n) + 1.0) - std::lgamma(static_cast<double>(i) + 1.0) -
                         std::lgamma(static_cast<double>(n - i) + 1.0) - static_cast<double>(n) * std::log(2.0));
    return tail;
}

double mcnemar_exact_p(long b, long c) {
    if (b < 0 || c < 0) throw InputError("McNemar's discordant counts must be non-negative");
    if (b + c == 0) return 1.0;
    return std::min(1.0, 2.0 * binomial_half_cdf(b + c, std::min(b, c)));
}

long median_order_statistic(long n, double confidence) {
    if (n < 0) throw InputError("a median's interval needs a non-negative count of values");
    if (!(confidence > 0.0 && confidence < 1.0)) throw InputError("a confidence must lie in (0, 1)");
    long k = 0;
    while (k + 1 <= n / 2 && 2.0 * binomial_half_cdf(n, k) <= 1.0 - confidence) ++k;
    return k;
}

RecordMedian record_median_interval(const std::vector<std::vector<double>>& by_record, double confidence) {
    RecordMedian out;
    std::vector<double> pooled, medians;
    for (const std::vector<double>& r : by_record) {
        if (r.empty()) continue;
        pooled.insert(pooled.end(), r.begin(), r.end());
        medians.push_back(quantile(r, 0.5));
    }
    const long k = median_order_statistic(static_cast<long>(medians.size()), confidence);
    out.values = static_cast<long>(pooled.size());
    out.records = static_cast<long>(medians.size());
    if (pooled.empty()) {
        out.median = {NAN, NAN, NAN, 0};
        return out;
    }
    out.median = {quantile(pooled, 0.5), NAN, NAN, out.records};
    if (k == 0) {
        long needed = out.records;
        while (median_order_statistic(needed, confidence) == 0) ++needed;
        out.reason = fmt::format("not resolved: {} record{} (a distribution-free {:g} % interval of the median "
                                 "needs {})",
                                 out.records, out.records == 1 ? "" : "s", 100.0 * confidence, needed);
        return out;
    }
    std::sort(medians.begin(), medians.end());
    out.median.lo = medians[static_cast<std::size_t>(k - 1)];
    out.median.hi = medians[medians.size() - static_cast<std::size_t>(k)];
    return out;
}

MedianBootstrap bootstrap_record_median(const std::vector<std::vector<double>>& by_record,
                                        const BootstrapOptions& options) {
    check_bootstrap_options(options);
    MedianBootstrap out;
    std::vector<double> pooled;
    for (const std::vector<double>& r : by_record) {
        pooled.insert(pooled.end(), r.begin(), r.end());
        out.records += r.empty() ? 0 : 1;
    }
    out.values = static_cast<long>(pooled.size());
    if (pooled.empty()) {
        out.median = {NAN, NAN, NAN, 0};
        return out;
    }
    std::mt19937_64 rng(options.seed);
    std::vector<double> medians, sample;
    for (int b = 0; b < options.replicates; ++b) {
        sample.clear();
        for (std::size_t i = 0; i < by_record.size(); ++i) {
            const std::vector<double>& r = by_record[uniform_index(rng, by_record.size())];
            sample.insert(sample.end(), r.begin(), r.end());
        }
        if (sample.empty()) {
            ++out.failed;
            continue;
        }
        medians.push_back(quantile(sample, 0.5));
    }
    out.median = percentile_interval(quantile(pooled, 0.5), std::move(medians), options.confidence);
    return out;
}

}  // namespace vssw::compare

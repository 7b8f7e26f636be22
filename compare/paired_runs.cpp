#include "compare/paired_runs.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "analytic/error.hpp"

namespace vssw::compare {

double mcnemar_exact_p(long b, long c) {
    if (b < 0 || c < 0) throw InputError("McNemar's discordant counts must be non-negative");
    const long n = b + c, k = std::min(b, c);
    if (n == 0) return 1.0;
    // P(X <= k) for X ~ Binomial(n, 1/2), each term C(n, i) 2^-n in logs (no overflow for any n).
    double tail = 0.0;
    for (long i = 0; i <= k; ++i)
        tail += std::exp(std::lgamma(static_cast<double>(n) + 1.0) - std::lgamma(static_cast<double>(i) + 1.0) -
                         std::lgamma(static_cast<double>(n - i) + 1.0) - static_cast<double>(n) * std::log(2.0));
    return std::min(1.0, 2.0 * tail);
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

#pragma once
// The record bootstrap every ensemble fit shares (the IDA fit of compare/ensemble_statistics.hpp and the stripe fit of
// compare/stripe_fragility.hpp): resample records with replacement, refit, and take percentile intervals; a paired
// version draws one set of record indices per replicate for an engine and the reference. A replicate whose fit fails
// is left out and counted. Templates over the record type and the refit, so that one loop serves both fits.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "compare/ensemble_statistics.hpp"

namespace vssw::compare {

// Leaves a percentile interval's ends out below `min_records` records (compare/ensemble_statistics.hpp: its coverage
// there is far below nominal). The values stay: they are the fit's.
inline std::string too_few_records(long records, long min_records) {
    return "not resolved: " + std::to_string(records) + " records (a percentile interval needs " +
           std::to_string(min_records) + ": below, it covers well under 95 %)";
}
inline void leave_out_ends(Interval& i) { i.lo = i.hi = NAN; }
inline void unresolve_below(FitBootstrap& f, long records, long min_records) {
    if (!f.fit.ok() || records >= min_records) return;
    f.interval_reason = too_few_records(records, min_records);
    leave_out_ends(f.median);
    leave_out_ends(f.beta);
}
inline void unresolve_below(RatioBootstrap& r, long records, long min_records) {
    if (!std::isfinite(r.ratio.value) || records >= min_records) return;
    r.reason = too_few_records(records, min_records);
    leave_out_ends(r.ratio);
}

// `full` is the fit to all records (the intervals' values); refit(sample) fits a resample.
template <class Record, class Refit>
FitBootstrap bootstrap_records(const std::vector<Record>& records, const LognormalFit& full, Refit refit,
                               const BootstrapOptions& options) {
    FitBootstrap out;
    out.fit = full;
    if (!full.ok()) {
        out.median = out.beta = {NAN, NAN, NAN, 0};
        return out;
    }
    std::mt19937_64 rng(options.seed);
    std::vector<Record> sample(records.size());
    std::vector<double> medians, betas;
    for (int b = 0; b < options.replicates; ++b) {
        for (Record& r : sample) r = records[uniform_index(rng, records.size())];
        const LognormalFit fit = refit(sample);
        if (!fit.ok()) {
            ++out.failed;
            continue;
        }
        medians.push_back(fit.median);
        betas.push_back(fit.beta);
    }
    out.median = percentile_interval(full.median, std::move(medians), options.confidence);
    out.beta = percentile_interval(full.beta, std::move(betas), options.confidence);
    return out;
}

// median(engine) / median(reference), record i of each the same record; the full fits given, refit_* per resample.
template <class Record, class RefitEngine, class RefitReference>
RatioBootstrap bootstrap_paired_ratio(const std::vector<Record>& engine, const std::vector<Record>& reference,
                                      const LognormalFit& engine_fit, const LognormalFit& reference_fit,
                                      RefitEngine refit_engine, RefitReference refit_reference,
                                      const BootstrapOptions& options) {
    RatioBootstrap out;
    if (!engine_fit.ok() || !reference_fit.ok()) {
        out.ratio = {NAN, NAN, NAN, 0};
        return out;
    }
    std::mt19937_64 rng(options.seed);
    const std::size_t n = engine.size();
    std::vector<Record> engine_sample(n), reference_sample(n);
    std::vector<double> ratios;
    for (int b = 0; b < options.replicates; ++b) {
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t pick = uniform_index(rng, n);
            engine_sample[i] = engine[pick];
            reference_sample[i] = reference[pick];
        }
        const LognormalFit e = refit_engine(engine_sample), r = refit_reference(reference_sample);
        if (!e.ok() || !r.ok()) {
            ++out.failed;
            continue;
        }
        ratios.push_back(e.median / r.median);
    }
    out.ratio = percentile_interval(engine_fit.median / reference_fit.median, std::move(ratios), options.confidence);
    return out;
}

}  // namespace vssw::compare

#pragma once
// A lognormal collapse fragility fitted to a multiple stripe analysis: every record of an ensemble scaled to each of
// a few intensity levels, each run overturning or not (Baker 2015, Earthquake Spectra 31(1):579-599, the section on
// multiple stripe analysis): at level x_j, z_j of n_j runs collapsed, and (theta, beta) maximise
//   ln L = sum_j [ z_j ln Phi(u_j) + (n_j - z_j) ln Phi(-u_j) ],  u_j = ln(x_j / theta) / beta,
// a probit regression on ln x: in (gamma, delta) = (1/beta, ln theta / beta), u_j = gamma ln x_j - delta and ln L is
// concave, so Newton's method with backtracking finds its one maximum when there is one. There is none when the
// stripes do not overlap (no run stands at a level above one where a run collapsed: beta -> 0) or when no run
// (or every run) collapses: then the fit is not made, with the reason.
//
// Bootstrap intervals resample records (a record's runs at every level go together), with the same seeded draws as
// compare/ensemble_statistics.hpp, so that a seed gives the same numbers with any standard library.
#include <vector>

#include "compare/ensemble_statistics.hpp"

namespace vssw::compare {

// One record's outcome at each level: 1 overturned, 0 stood, -1 no result (a failed run, left out).
using StripeOutcomes = std::vector<int>;

// The fit to records x levels; levels are intensities > 0 (e.g. PGA in g), one outcome per level in each record.
// records: records with at least one result; collapsed: runs that overturned. Throws InputError for a level that is
// not finite and positive, or a record whose outcomes do not match the levels.
LognormalFit fit_lognormal_stripes(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records);

// Percentile intervals of the median and beta over resampled records (bootstrap_fit's rules: a replicate whose fit
// fails is left out and counted).
FitBootstrap bootstrap_stripes(const std::vector<double>& levels, const std::vector<StripeOutcomes>& records,
                               const BootstrapOptions& options = {});

// Paired bootstrap of median(engine) / median(reference) over the same records (engine[i] and reference[i] are record
// i under the two models), as bootstrap_median_ratio.
RatioBootstrap bootstrap_stripe_median_ratio(const std::vector<double>& levels,
                                             const std::vector<StripeOutcomes>& engine,
                                             const std::vector<StripeOutcomes>& reference,
                                             const BootstrapOptions& options = {});

}  // namespace vssw::compare

#pragma once
// `vssw check`'s earthquake bounds ([[earthquake]] in a bounds file): runs each named record ensemble once for the
// engines its bounds name (validation/earthquake.hpp, into a temporary folder removed after) and holds each engine's
// measure against its [min, max].
#include <string>
#include <vector>

#include "validation/bounds.hpp"

namespace vssw::validation {

// InputError (naming the bounds file) for an ensemble that does not read or an engine not in this build: `vssw check`
// calls it before anything runs.
void plan_earthquake_bounds(const std::vector<EarthquakeBound>& bounds, const std::string& path);

// Runs the ensembles and gives one verdict per bound, in the bounds' order (case: the study's name; a NaN, e.g. a
// fragility that could not be fitted, does not hold).
std::vector<BoundVerdict> check_earthquake_bounds(const std::vector<EarthquakeBound>& bounds,
                                                           int threads);

}  // namespace vssw::validation

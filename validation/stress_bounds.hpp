#pragma once
// `vssw check`'s stress bounds ([[stress]] in a bounds file): runs the named stress cases in their quick form on the
// named engines (every backend compiled in when none is named) and holds each verdict against the allowed ones.
#include <string>
#include <vector>

#include "validation/bounds.hpp"
#include "stress/run.hpp"

namespace vssw::validation {

// The stress run the bounds ask for (their cases in quick form, on their engines). InputError (naming the file) for an
// unknown case or engine: `vssw check` plans it before anything runs.
stress::RunOptions plan_stress_bounds(const std::vector<StressBound>& bounds, const std::string& path,
                                      int threads);

// Runs the planned cases: one verdict per (case, engine) of each bound, in the bounds' order.
std::vector<BoundVerdict> check_stress_bounds(const std::vector<StressBound>& bounds,
                                                       const stress::RunOptions& run);

}  // namespace vssw::validation

#pragma once
// `vssw check`'s stress bounds ([[stress]] in a bounds file): runs the named stress cases in their quick form on the
// named engines (every backend compiled in when none is named) and holds each verdict against the allowed ones.
#include <string>
#include <vector>

#include "compare/bounds.hpp"

namespace vssw::cli {

// One verdict per (case, engine) of each bound, in the bounds' order. InputError (naming the file) for an unknown
// case or engine, before anything runs.
std::vector<compare::BoundVerdict> check_stress_bounds(const std::vector<compare::StressBound>& bounds,
                                                       const std::string& path, int threads);

}  // namespace vssw::cli

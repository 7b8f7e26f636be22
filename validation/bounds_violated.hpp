#pragma once
// `vssw check` found a metric out of its bounds: the program exits 1 (not a failure of the program itself).
#include <stdexcept>

namespace vssw::validation {

struct BoundsViolated : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace vssw::validation

#pragma once
// What the coverage tests share (tests/test_fragility_coverage.cpp, tests/test_peak_ratio_coverage.cpp): the count of
// simulated intervals that hold the true value, among those shown (an interval not resolved claims nothing).
#include <cmath>

#include "compare/ensemble_statistics.hpp"

namespace vssw::testing {

struct Coverage {
    int covered = 0, shown = 0;
    double share() const { return shown > 0 ? static_cast<double>(covered) / shown : NAN; }
};

// Counts `i` when it is resolved (both ends finite), as covering when lo <= truth <= hi.
inline void count_coverage(Coverage& c, const compare::Interval& i, double truth) {
    if (!std::isfinite(i.lo) || !std::isfinite(i.hi)) return;
    ++c.shown;
    c.covered += i.lo <= truth && truth <= i.hi ? 1 : 0;
}

}  // namespace vssw::testing

#pragma once
// Running the stress set: every (case, backend) pair in a child process of its own (multibody/host/child_process.hpp: a
// case that hangs, crashes or aborts inside an engine library cannot take the whole run down) with a time limit,
// several at a time on a pool of threads that only wait for their children.
#include <string>
#include <vector>

#include "multibody/host/child_process.hpp"
#include "stress/case.hpp"
#include "stress/verdict.hpp"

namespace vssw::stress {

// Time limits per case and backend [s]: the quick set's runs took up to 15 s each on 2 cores under load 21
// (simbody-rigid holding the threshold pulse), 30 s timed that one out with a second run beside it; the full set's 600
// s harmonic and 0.01 x steps take up to minutes (simbody-rigid's harmonic 297 s idle, so the full limit is twice
// that); the limits leave room for a loaded machine (docs/guide/stress.md). The [[stress]] bounds of `vssw check` use
// the quick one.
constexpr double kQuickTimeLimit = 120.0;
constexpr double kFullTimeLimit = 600.0;

struct RunOptions {
    std::vector<std::string> engines;  // backends to run (each must be compiled in: InputError otherwise)
    bool quick = false;                // the quick set (Case::quick) with shortened durations
    double time_limit_s = kQuickTimeLimit;  // per case and backend [s]
    int threads = 0;                   // children at once (0: the available cores)
    // Only these cases (names; any of the set, run at the quick durations when `quick`); empty: the whole set or the
    // quick set. An unknown name is an InputError.
    std::vector<std::string> cases;
};

// The verdicts, in case order then engine order.
std::vector<CaseResult> run_cases(const RunOptions& options);

// The stress case of that name; InputError naming it and listing the set otherwise.
const Case& require_case(const std::string& name);

// A child's end as a verdict: its own answer when it completed, otherwise failed (timed out, crashed, threw).
CaseResult result_of(const multibody::ChildResult& child, const std::string& name, const std::string& engine);

}  // namespace vssw::stress

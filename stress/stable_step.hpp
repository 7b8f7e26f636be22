#pragma once
// Each engine's largest stable step on the Fig. 6 walls (`vssw stress`, full set): the free vibration from 0.5 alpha
// at growing steps, held against the engine's own answer at a quarter of its default step.
#include <optional>
#include <string>
#include <vector>

namespace vssw::stress {

// Stable: the run ends without failure or NaN and its period (4 x the first impact's time) and first-impact
// restitution are within these of the engine's own small-step answer. Stability, not accuracy: four times the
// suite's 0.5 % period target, and 5 % on the restitution (the engines' VSSW impact differs from Eq. (19) by up to
// 15 %, so only a change against themselves means anything).
constexpr double kStablePeriodTol = 0.02;
constexpr double kStableRestitutionTol = 0.05;
// The search: the default step doubled until a run is not stable (at most 2^8 = 256 times the default), then
// geometric bisection between the last stable and the first unstable step, 4 halvings of the ratio (to 2^(1/16),
// 4.4 %). It assumes one boundary: a step above which runs stay unstable.
constexpr int kMaxDoublings = 8;
constexpr int kBisections = 4;

struct StableStep {
    std::string engine;
    std::string wall;  // "fig6-vssw" or "fig6-pw"
    double default_dt = 0.0;
    double reference_dt = 0.0;           // default / 4
    double reference_period = 0.0, reference_restitution = 0.0;
    std::optional<double> largest_stable_dt;   // unset: not even the default step was stable (or no reference)
    std::optional<double> first_unstable_dt;   // unset: stable up to 256 x the default
    std::string unstable_reason;               // why first_unstable_dt was not stable
    int probes = 0;
    double time_s = 0.0;
};

// Every engine given except the analytic model (whose step is its tolerance's), on both walls; each probe in a child
// process with the time limit. Runs the (engine, wall) searches `threads` at a time (0: the available cores).
std::vector<StableStep> find_stable_steps(const std::vector<std::string>& engines, double time_limit_s, int threads);

}  // namespace vssw::stress

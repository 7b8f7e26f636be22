#pragma once
// The response measures of one analytic run, by the one definition every output uses (peak_rotation, peak_time,
// overturned; docs/model/engines-and-metrics.md, "One measure per name"). An overturned run has no rocking peak of its
// own: its peak is the model's collapse angle, reached (or judged reached: a wall that folded past the roller's lock)
// at the overturning. multibody runs read these through compare/response.hpp.
#include <optional>

#include "analytic/model.hpp"
#include "analytic/simulate.hpp"

namespace vssw {

struct AnalyticResponse {
    double peak = 0.0;       // |theta1| [rad]: the collapse angle when overturned, else largest_rotation's
    double peak_time = 0.0;  // [s]: the overturning, else when the largest rotation was reached
    bool overturned = false;
    std::optional<double> t_overturn;  // [s]
};

// `model` is the one that ran (its collapse angle is where this run counts as overturned: a stop angle's when it has
// one, so a threshold trial's run stopped there gives that angle).
AnalyticResponse response_of(const SimulationResult& result, const RockingModel& model);

}  // namespace vssw

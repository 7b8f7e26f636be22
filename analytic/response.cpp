#include "analytic/response.hpp"

namespace vssw {

AnalyticResponse response_of(const SimulationResult& result, const RockingModel& model) {
    AnalyticResponse r;
    r.overturned = result.overturned;
    if (result.overturned) {
        // The overturning's own |theta1| is not the peak: a unilateral wall can be judged overturned once it folded,
        // short of the collapse angle in theta1 (Rinaldi x 0.6 on a 4 m x 0.4 m wall, hinge 0.7: 3.80 against
        // 4.27 alpha1), and an engine's step overshoots the angle. Every backend gives the angle it counts as collapse.
        r.peak = model.collapse_angle();
        r.peak_time = result.t_overturn;
        r.t_overturn = result.t_overturn;
        return r;
    }
    const LargestRotation largest = largest_rotation(result);
    r.peak = largest.abs_theta;
    r.peak_time = largest.t;
    return r;
}

}  // namespace vssw

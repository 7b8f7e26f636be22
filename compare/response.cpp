#include "compare/response.hpp"

#include <cmath>
#include <limits>

#include "multibody/kit/scene_geometry.hpp"

namespace vssw::compare {

Response response_of(const multibody::Trajectory& run, const multibody::WallScene& scene) {
    Response r;
    r.overturned = run.overturned;
    r.slip = run.slip;
    if (run.located && run.located->supports_computed) {
        r.base_friction_needed = run.located->base_friction_needed;
        if (scene.vssw) r.hinge_friction_needed = run.located->hinge_friction_needed;
    }
    if (run.located) {
        r.peak = run.located->max_abs_theta1;
        r.peak_time = run.located->t_max_abs_theta1;
        r.t_overturn = run.located->t_overturn;
        r.energy_error = run.located->energy_balance_error;
        r.tension_at = run.located->roller_tension_at;
        return r;
    }
    r.peak_time = run.samples.empty() ? std::numeric_limits<double>::quiet_NaN() : run.samples.front().t;
    for (const multibody::TrajectorySample& s : run.samples)
        if (std::abs(s.theta1) > r.peak) {
            r.peak = std::abs(s.theta1);
            r.peak_time = s.t;
        }
    if (run.overturned && !run.samples.empty()) {
        // An engine's run ends at the step that judged it overturned (multibody::RunMonitor): past the scene's
        // collapse angle, or folded past the unstable equilibrium short of it. Either way its peak is that angle.
        r.peak = multibody::collapse_angle(scene);
        r.peak_time = run.samples.back().t;
        r.t_overturn = run.samples.back().t;
    }
    return r;
}

}  // namespace vssw::compare

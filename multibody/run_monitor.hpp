#pragma once
// What every engine adapter checks after each step, in one place: failures (NaN, blow-up, sliding, sinking), each
// an EngineFailure naming the engine, the reason and the time; and reasons to stop (a threshold trial's stop angle,
// overturning at the scene's collapse angle, rest once the ground motion is over). Engine-free.
#include <string>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// The lower block's base corners after a step, relative to the ground (which may move): horizontal offsets from
// their places at rest (+b and -b) and heights above the ground's top.
struct BaseCorners {
    double right_dx, right_y, left_dx, left_y;
};

class RunMonitor {
public:
    enum class Verdict { go_on, stop, overturned, at_rest };

    // slide_limit and penetration_limit in units of b.
    RunMonitor(std::string engine, const WallScene& scene, const Excitation& ex, double dt, double slide_limit,
               double penetration_limit);

    // Throws EngineFailure on a failure; otherwise says whether the run goes on.
    Verdict check(double t, double theta1, double theta1_dot, const BaseCorners& corners);
    // True when the verdict ends the run, having marked the trajectory overturned or at rest as it says.
    static bool ends_run(Verdict verdict, Trajectory& out);

private:
    std::string engine_;
    double b_, friction_, collapse_, v_ref_, alpha_, motion_end_, stop_angle_;
    bool stop_at_rest_;
    double slide_limit_, penetration_limit_;
    int quiet_steps_ = 0, quiet_needed_;
};

}  // namespace vssw::multibody

#pragma once
// The VSSW's top off the roller (a roller that can only push: docs/guide/program.md "The model checks its own
// assumptions"). Where the bilateral roller would pull, the pivot-side top corner leaves the roller line and the wall
// moves with two degrees of freedom, q = (theta1, theta2), base pivot and hinge kept (analytic/two_block.hpp). The slot
// between the two top guides is narrow (2b (1 - cos theta2)), so a flight off the roller ends in one of: - the corner
// lands back on the roller (plastic: the kinetic-energy projection onto the one-DOF mechanism):
//    the one-DOF model takes over;
// - the far top corner lands on the other guide (plastic): the wall moves on that guide as a one-DOF mechanism
//    until the guide would pull (back to free flight) or theta1 reaches 0. There both guides' constraints have the
//    same Jacobian (both top corners are at the same height at rest), so the base impact is the one-DOF model's and
//    the far guide is the new side's roller;
// - theta1 reaching 0 in free flight: the slot has closed (theta2 ~ 0) and base and guides strike at once, taken
//    as the roller landing an instant before the one-DOF base impact (off_roller.cpp says why);
// - the upper block turning past the roller's lock of Eq. (26) (the wall folded): overturning; - the collapse angle, or
// the end of the run. Integrated with Dormand-Prince 8(5,3) on (theta1, theta2, theta1', theta2', work of the ground);
// events located on its continuous extension.
#include <functional>
#include <vector>

#include "dop853.hpp"
#include "ground_motion.hpp"
#include "result_parts.hpp"
#include "two_block.hpp"

namespace vssw {

struct OffRollerStart {
    double t, theta1, theta1_dot, work_ground;  // leaving the roller, on the one-DOF mechanism
    int side;
};

struct OffRollerEnd {
    enum class How { on_roller, base_impact, collapse, end_time } how;
    double t, theta1, theta1_dot, work_ground;  // on_roller: after the landing; base_impact: theta1 = 0, before it
    double dissipated = 0.0;                    // by the landings on the way [J/m]
    double max_abs_theta = 0.0;
    std::vector<TurningPoint> peaks;
};

struct OffRollerSetup {
    const GroundMotion* horizontal;
    const GroundMotion* vertical;
    StepControl step;
    double t_end, collapse_angle, event_time_tol;
    long max_steps;  // the run's step budget: the flight's steps count against it with the run's (`steps` below)
    std::function<double(double)> next_breakpoint;  // the ground motions' next breakpoint after t (or t_end)
    // Called for each accepted interval (t0, t1] with the state at any time in it, so the caller can fill its output
    // grid; may be empty.
    std::function<void(double, double, const std::function<Vec<5>(double)>&)> emit;
    // The energy balance at (t, state) with the flight's landings' dissipation so far; throws past its ceiling.
    std::function<void(double, const Vec<5>&, double)> check_energy;
};

// Throws std::runtime_error (a failed run) where the flight leaves the model (see above).
OffRollerEnd fly_off_roller(const VsswGeometry& w, const OffRollerStart& start, const OffRollerSetup& setup,
                            long& steps);

}  // namespace vssw

#pragma once
// What the supports must do along a one-DOF VSSW run: each state of the run is embedded in the two blocks (theta2 and
// its rates from the model's own kinematics, Eq. 2 or Eq. 3) and Newton-Euler on each block (analytic/two_block.hpp)
// gives the roller's reaction, the base and hinge forces and the friction they need. The monitor records the extremes
// into SupportDemand (result_parts.hpp); for a parapet it is inactive.
#include <optional>

#include "model.hpp"
#include "result_parts.hpp"
#include "two_block.hpp"

namespace vssw {

class SupportMonitor {
public:
    explicit SupportMonitor(const RockingModel& model);
    bool active() const { return plus_.has_value(); }

    // The two-block state (q, q', q'') of the one-DOF motion on `side` at (theta1, theta1', theta1'').
    struct Embedding {
        Vec2 q, qdot, qddot;
    };
    Embedding embed(int side, double theta, double theta_dot, double theta_ddot) const;
    const TwoBlockWall& wall(int side) const { return side > 0 ? *plus_ : *minus_; }

    // The supports' forces at that state under the ground accelerations a_h, a_v.
    TwoBlockReactions reactions(int side, double theta, double theta_dot, double theta_ddot, double a_h,
                                double a_v) const;
    // Records the state at time t into `demand`; returns the roller's reaction [N/m] (positive pushing).
    double record(double t, int side, double theta, double theta_dot, double theta_ddot, double a_h, double a_v,
                  SupportDemand& demand) const;

private:
    const RockingModel& model_;
    std::optional<TwoBlockWall> plus_, minus_;
};

}  // namespace vssw

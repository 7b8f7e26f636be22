#include "support_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace vssw {

SupportMonitor::SupportMonitor(const RockingModel& model) : model_(model) {
    if (const VsswGeometry* w = model.vssw_geometry()) {
        plus_.emplace(*w, 1);
        minus_.emplace(*w, -1);
    }
}

SupportMonitor::Embedding SupportMonitor::embed(int side, double theta, double theta_dot, double theta_ddot) const {
    // The model gives theta2(q) for q = |theta1| on side +1; side -1 is its mirror, theta2 -> -theta2(-theta1), so
    // dtheta2/dtheta1 is even in the side and the second derivative odd.
    const RockingModel::UpperRotation u = model_.upper_rotation(side * theta);
    const double theta2 = side * u.theta2;
    const double theta2_dot = u.d1 * theta_dot;
    const double theta2_ddot = u.d1 * theta_ddot + side * u.d2 * theta_dot * theta_dot;
    return {Vec2(theta, theta2), Vec2(theta_dot, theta2_dot), Vec2(theta_ddot, theta2_ddot)};
}

TwoBlockReactions SupportMonitor::reactions(int side, double theta, double theta_dot, double theta_ddot, double a_h,
                                            double a_v) const {
    const Embedding e = embed(side, theta, theta_dot, theta_ddot);
    return wall(side).reactions(e.q, e.qdot, e.qddot, a_h, a_v, Guide::roller);
}

double SupportMonitor::record(double t, int side, double theta, double theta_dot, double theta_ddot, double a_h,
                              double a_v, SupportDemand& d) const {
    const TwoBlockReactions r = reactions(side, theta, theta_dot, theta_ddot, a_h, a_v);
    d.computed = true;
    if (r.roller < d.min_roller_reaction) {
        d.min_roller_reaction = r.roller;
        d.t_min_roller_reaction = t;
    }
    if (r.roller < 0.0 && !d.roller_tension_at) d.roller_tension_at = t;
    if (r.base_pulls) {
        if (!d.base_pulls_at) d.base_pulls_at = t;
    } else {
        d.base_friction = std::max(d.base_friction, r.base_friction);
    }
    if (r.hinge_pulls) {
        if (!d.hinge_pulls_at) d.hinge_pulls_at = t;
    } else {
        d.hinge_friction = std::max(d.hinge_friction, r.hinge_friction);
    }
    return r.roller;
}

}  // namespace vssw

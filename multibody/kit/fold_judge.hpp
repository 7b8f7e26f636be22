#pragma once
// Whether a wall past the unstable equilibrium can still come back, judged during the shaking or on a still ground
// (RunMonitor).
//
// The argument (docs/earthquakes.md, "Overturning, the same for every backend"): on side s at q = |theta1| the
// mechanism's equation (Eq. 10) is M theta1'' + C theta1'^2 = -a_h X(q) - s V'(q), and the capacity curve
// c(q) = V'(q) / X(q) (RockingModel::holding_acceleration) is the |a_h| that holds the wall still at q. Past the
// unstable equilibrium c < 0: only an inward acceleration of at least h(q) = -c(q) can hold the wall there. Let A be
// the largest |a_h| left in the record from now on, and H(q) the smallest h over [q, collapse angle]. A wall at q with
// A < H(q) feels an outward generalised force at every later moment for as long as it stays beyond q. If its rate is
// not inward now, it cannot turn inward: whenever theta1' = 0 there, M theta1'' is that outward force, > 0 outward, so
// the rate leaves 0 outward again and q never falls below its value now. The wall goes on to the collapse angle (or
// folds against the far guide, as the engines' walls do): it has overturned, and the run can end now instead of
// kFoldedFor after the record's end. On a still ground (a free vibration: A = 0 throughout; RunMonitor asks only
// when no friction was given, since sliding blocks are not the rigid mechanism, and only past the larger of the two
// sides' equilibria) the same argument says a wall past its side's unstable equilibrium, not moving inward, has
// overturned. A free vibration gets there released past it (a heavy N lowers it below alpha1) or, with N off-centre,
// landing on the side whose equilibrium is lower; its run ends there rather than at the collapse angle (near which a
// falling block's pivot slides: the engines measured it as a slide, not an overturning).
//
// Held for the rigid mechanism only: a flexible top support (its ring after the shaking can turn the upper block) and
// rounded corners (the blocks roll, the pivot moves) are left to the folded rule (RunMonitor: after the shaking, or in
// a free vibration from the release).
#include <array>
#include <cstddef>
#include <vector>

#include "analytic/ground_motion.hpp"
#include "multibody/engine.hpp"

namespace vssw::multibody {

class FoldJudge {
public:
    // The scene and the motion are read when the judge is first asked (most runs never pass an unstable equilibrium,
    // and the grid of H costs 1.1 M instructions, 1-3 % of a short run: callgrind): both must outlive the judge.
    FoldJudge(const WallScene& scene, const GroundMotion& motion);
    FoldJudge(const WallScene&&, const GroundMotion&) = delete;  // a temporary would be gone when the judge reads it
    FoldJudge(const WallScene&, const GroundMotion&&) = delete;
    // True when the wall at theta1 with rate theta1_dot at time t cannot come back (above). Call in time order.
    bool cannot_come_back(double t, double theta1, double theta1_dot);
    // H(q) above [m/s^2] on side `side`: 0 short of the unstable equilibrium, and where the mechanism does not hold.
    double hold_back(int side, double q);
    // A above: the largest |a_h| of the motion at t or later [m/s^2] (a record's samples from the one before t; an
    // analytic signal's peak until its end; 0 for a still ground).
    double largest_left(double t);

private:
    void build();  // H's grid on both sides and the motion's largest |a_h| from each sample on, once

    const WallScene* scene_;
    const GroundMotion* motion_;
    bool active_ = false, built_ = false;
    double collapse_ = 0.0;
    std::array<double, 2> unstable_{};                // per side (index 0: side +1, 1: side -1)
    std::array<std::vector<double>, 2> hold_back_;    // H on a grid from the unstable equilibrium to the collapse
    std::vector<double> times_, largest_after_;       // a record's sample times and the max |a| from each on
    double analytic_peak_ = 0.0, duration_ = 0.0;
    bool sampled_ = false;
    std::size_t cursor_ = 0;
};

}  // namespace vssw::multibody

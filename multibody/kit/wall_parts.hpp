#pragma once
// The failure checks on every part of the wall that RunMonitor makes after each step, beyond the lower block's
// rotation and its base: no corner of the lower block inside the ground; while the upper block stands, none of its
// corners inside the ground, the other block (through the hinge) or past a roller guide; and no mechanical energy
// above what the ground motion can have given. Engine-free: each adapter gives
// the state of its two blocks (WallState), and these checks derive every corner, the top and the energy from it, so
// that all seven engines are held to one definition.
//
// Why contacts and energy and not a list of "plausible" motions: whatever the wall does without a body passing
// through another and without energy it was not given is something rigid blocks can do (rocking, the upper block
// jumping off the hinge or leaving the roller, the whole wall folding and falling) and is a response, judged by
// RunMonitor's verdicts. A block that falls through the hinge or the ground, or a top lower than the blocks allow, is
// not: it shows as a corner inside a body. The top's lowest possible height is thus bounded by the corner checks.
#include <cmath>
#include <limits>
#include <string>

#include "multibody/engine.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw::multibody {

// One block after a step, relative to the ground (which may move): its centre [m], clockwise rotation [rad], the
// centre's velocity [m/s] and the rotation rate [rad/s]. An adapter whose engine keeps a rotation matrix (ODE, Bullet,
// DART) may also give the rotation's cosine and sine as the matrix holds them, which TurnedBlock then uses instead of
// computing them from the angle (NaN: not given). They are the angle's own to rounding (the angle is atan2 of the
// same two entries), and the C library's sin and cos, two a step, were about 0.5 % of an ODE run (perf).
struct BlockState {
    double x, y, angle, vx, vy, omega;
    double cos_angle = std::numeric_limits<double>::quiet_NaN(), sin_angle = std::numeric_limits<double>::quiet_NaN();
};

// What every adapter gives RunMonitor after each step: both blocks (upper ignored for a parapet).
struct WallState {
    BlockState lower, upper;
    double top_offset = 0.0;  // the roller guides' offset from the ground, u_d (a flexible top support; 0 rigid) [m]
};

// The upper block of a parapet's WallState: none.
inline constexpr BlockState kNoBlock{0.0, 0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0};

// A point of a block given in its own frame (lx along its width, ly along its height), relative to the ground.
struct PlanePoint {
    double x, y;
};
PlanePoint point_of(const BlockState& block, double lx, double ly);

// A block with the cosine and sine of its rotation computed once: a step's checks place up to ten points on the
// blocks and project on four axes, and the C library's cos and sin were most of the monitor's time when called per
// point (perf and callgrind, ODE under a record). RunMonitor turns each block once per step and hands the turned blocks
// to every check. Its points are point_of's to the bit (the same products of the same values).
struct TurnedBlock {
    explicit TurnedBlock(const BlockState& block)
        : k(block),
          c(std::isnan(block.cos_angle) ? std::cos(block.angle) : block.cos_angle),
          s(std::isnan(block.sin_angle) ? std::sin(block.angle) : block.sin_angle) {}
    PlanePoint at(double lx, double ly) const { return {k.x + lx * c + ly * s, k.y - lx * s + ly * c}; }
    const BlockState& k;
    double c, s;  // clockwise (scene_geometry.cpp's turn)
};

// The wall placed at rotation theta1 (pose_at), still but for the lower block's rate, its blocks lifted by
// `contact_gap` (the lower by one, the upper by two, as Simbody's corner spheres lift them): the release state of a
// run, and the state a synthetic run feeds RunMonitor (tests).
WallState still_state_at(const WallScene& scene, double theta1, double theta1_dot = 0.0, double contact_gap = 0.0);

// How much mechanical energy a run may gain beyond what the ground motion can have given it, as a share of V_r (the
// potential energy of the wall turned to its reference angle alpha). Measured at the engines' defaults: at most
// 3.4e-3 V_r (Bullet, moving supports, a threshold trial of the Fig. 6 VSSW; CrossEngine for ODE, Bullet, Box2D and
// MuJoCo), 2.3e-4 V_r on the Fig. 6 wall free and under the pulse P (Siconos; every engine), 4e-5 V_r under Rinaldi
// at 0.55 to 1 g. 0.05 is 15 times the worst; a blow-up gains many V_r.
constexpr double kEnergyGainShare = 0.05;

class WallParts {
public:
    // penetration: how far [m] a corner may sink into a body (FailureLimits::penetration times b). contact_gap: the
    // distance the adapter's contacts keep between touching bodies (Simbody's corner spheres: their radius; 0 else).
    // energy_gain: kEnergyGainShare, or +infinity for a test that feeds motions no mechanics gave.
    WallParts(std::string engine, const WallScene& scene, const Excitation& ex, double penetration,
              double energy_gain, double contact_gap = 0.0);
    // The same with the scene's figures already computed (RunMonitor's, built once per run).
    WallParts(std::string engine, const WallScene& scene, const MechanismFigures& figures, const Excitation& ex,
              double penetration, double energy_gain, double contact_gap = 0.0);

    // Throws EngineFailure naming the part and the time when a corner is inside a body, the state is not finite, or
    // the energy is above E(0) plus the most the ground motion can have given. Call once per step, in time order,
    // with the lower block already turned (RunMonitor's, shared with its base check): lower.k is s.lower.
    void check(double t, const WallState& s, const TurnedBlock& lower);

private:
    void check_contacts(double t, const WallState& s, const TurnedBlock& lower, const TurnedBlock* upper) const;
    // The wall's mechanical energy; top: the block N presses on, turned (the upper one of a VSSW, else the lower).
    double energy(const WallState& s, const TurnedBlock& top) const;
    double input_bound(double t, const WallState& s);

    std::string engine_;
    BlockSizes sizes_;
    bool vssw_;
    double g_, N_;
    double load_x_;  // N's point on the top face from its centre, toward theta1 > 0 [m]
    double gap_;
    double radius_;  // the blocks' corner radius r [m] (rounded_corners.hpp)
    double penetration_, energy_gain_, upright_range_;
    const GroundMotion* motion_;
    bool no_motion_;  // the motion is zero throughout (GroundMotion::is_zero): it gives no work
    WallState rest_, last_;
    double top_rest_y_;  // N's point at rest, the zero of its potential: computed once, not each step
    double e0_, input_ = 0.0, t_last_ = 0.0;
    double a_last_ = NAN;  // |a_h(t_last_)|, the last check's end: evaluated once per step, not twice
};

}  // namespace vssw::multibody

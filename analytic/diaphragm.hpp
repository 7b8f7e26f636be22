#pragma once
// A flexible top support: the roller at the top of a VSSW carried by a diaphragm, a damped single-degree-of-freedom
// oscillator of period T_d and damping ratio zeta_d shaken by the ground (docs/model/top-support.md). Its relative
// displacement u_d(t) obeys
//     u_d'' + 2 zeta_d omega_d u_d' + omega_d^2 u_d = -a_h(t),   omega_d = 2 pi / T_d,   u_d(0) = u_d'(0) = 0,  (9d)
// and the top support's absolute acceleration is a_h + u_d'' = -(2 zeta_d omega_d u_d' + omega_d^2 u_d). T_d = 0 is the
// paper's rigid diaphragm (Eq. 9: the top moves with the ground, u_d = 0).
#include <vector>

#include "ground_motion.hpp"

namespace vssw {

// Ranges a diaphragm's figures are checked against (InputError naming the value otherwise). A floor or roof diaphragm
// of masonry buildings has periods of 0.05 to 1 s; 10 s is ten times the softest. Damping below 1: the closed form
// below is the under-damped one (a critically damped floor is no floor an engineer meets; 2 to 10 % is usual).
constexpr double kMaxDiaphragmPeriod = 10.0;  // [s]
constexpr double kMaxDiaphragmDamping = 0.99;
constexpr double kDefaultDiaphragmDamping = 0.05;

struct Diaphragm {
    double period = 0.0;                          // T_d [s]; 0: rigid (the paper's Eq. 9)
    double damping = kDefaultDiaphragmDamping;    // zeta_d [-]
    bool is_rigid() const { return period == 0.0; }
};

// InputError unless the period is in [0, kMaxDiaphragmPeriod] and the damping in [0, kMaxDiaphragmDamping], naming
// the value and the option (`period_name`, `damping_name`: how the caller's user gave them).
void require_diaphragm(const Diaphragm& d, const char* period_name = "diaphragm period T_d (s)",
                       const char* damping_name = "diaphragm damping ratio zeta_d");

// The top support's motion relative to the ground: u_d, u_d', u_d'' [m, m/s, m/s^2].
struct TopOffset {
    double u = 0.0, v = 0.0, a = 0.0;
};

// Eq. (9d) integrated once for a ground motion: exactly (to rounding) for an acceleration linear between the nodes
// (a record's samples; an analytic signal sampled at its breakpoints, its extrema and at least kNodesPerPeriod nodes
// per diaphragm period and kNodesPerSwing between extrema, whose linear interpolation is the only error: at most
// h^2/8 max|a''| with h the node spacing, below 1e-4 of the peak for a sine sampled 128 times per half period).
// After the ground motion ends the diaphragm rings down freely, also in closed form. Every backend reads the same
// object, so the model and the engines see one top motion.
class TopSupportMotion {
public:
    static constexpr int kNodesPerPeriod = 200;  // nodes per diaphragm period T_d (analytic signals)
    static constexpr int kNodesPerSwing = 128;   // nodes between two extrema or breakpoints of an analytic signal

    TopSupportMotion() = default;  // rigid: u_d = 0
    TopSupportMotion(const GroundMotion& ground, const Diaphragm& d);

    bool is_rigid() const { return omega_ == 0.0; }
    // u_d, u_d', u_d'' at t (0 before t = 0; the free ring-down after the motion's end).
    TopOffset operator()(double t) const;
    // The top support's absolute acceleration a_h + u_d'' = -(2 zeta omega u_d' + omega^2 u_d).
    double absolute_acceleration(double t) const;
    // The largest |u_d| at the nodes [m]: a scale of the top's drift (the tests' tolerances and quasi-static check
    // read it), not its peak, which can fall between two nodes and be larger.
    double peak_offset() const { return peak_u_; }

private:
    // The node i's state and the acceleration piece that starts there: a(t) = a0 + slope (t - t_i) up to node i + 1.
    struct Node {
        double t, u, v, a0, slope;
    };
    TopOffset advance(const Node& n, double tau) const;

    double omega_ = 0.0, zeta_ = 0.0, omega_damped_ = 0.0;
    std::vector<Node> nodes_;  // the last one starts the free ring-down (a = 0 for ever)
    double peak_u_ = 0.0;
};

}  // namespace vssw

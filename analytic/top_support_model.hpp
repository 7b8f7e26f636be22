#pragma once
// The exact VSSW's equation of motion with its top held at an offset w(t) from the ground, Eq. (10d)
// (docs/model/top-support.md): the terms of
//   M q'' + C q'^2 + dM/dt q' + F = -a_h X - (g + a_v) Y - N L
// in the mechanism's frame (q = |theta1| >= 0; w = sigma u_d, the roller's offset toward the pivot's side), with the
// rheonomic constraint of Eq. (2d), sin psi = (R1/R2) sin(alpha1 - q) + w / (2 R2). w = 0 gives Eq. (10)'s terms.
// Not yet integrated by the simulator (docs/model/top-support.md, "What the model can follow"): the terms and the
// mechanism's range, checked against the bodies' positions.
#include "geometry.hpp"

namespace vssw {

struct TopOffsetState {
    double w = 0.0, w_dot = 0.0, w_ddot = 0.0;  // the roller's offset toward the pivot's side and its rates
};

struct RheonomicTerms {
    double M;      // generalised inertia (Eq. 11's, on Eq. 2d)
    double C;      // dM/dq / 2
    double dM_dt;  // the moving constraint's velocity term
    double F;      // the forcing by the top's motion: linear in w'', quadratic in w'
    double X, Y;   // the levers of the ground's pseudo-force and of the weights, as in Eq. (10)
    double L;      // N's lever, N at the top face's centre
};

// At q >= 0; InputError-free: a state past Eq. (26) or outside Eq. (9e) gives NaN or numbers of no mechanism (ask
// holds_mechanism first).
RheonomicTerms top_support_terms(const VsswGeometry& w, double q, const TopOffsetState& top);

// Eq. (9e): the upper block turns about the hinge opposite the pivot (theta2 <= 0 in the mechanism's frame), which
// holds while the top's offset toward the pivot's side does not pass the hinge's own travel,
// w <= 2 R1 (sin alpha1 - sin(alpha1 - q)); and Eq. (2d) has a solution (|sin psi| <= 1).
bool holds_mechanism(const VsswGeometry& w, double q, double offset);

}  // namespace vssw

#pragma once
// The VSSW as two rigid blocks with two degrees of freedom, q = (theta1, theta2): the lower block pivots on its base
// corner, the upper block on the intermediate hinge, and the top roller is a separate, unilateral constraint. It gives
//   (a) the roller's reaction along any one-DOF run (the Lagrange multiplier of the exact mechanism, Eq. 2) and the
//       base and hinge forces, with the friction the no-sliding assumption needs (Newton-Euler, any prescribed motion);
//   (b) the two-DOF motion when the roller would have to pull: the upper block leaves the roller line, theta1 and
//       theta2 move freely, and the return of the top corner to the line is a plastic impact onto the one-DOF
//       mechanism.
//
// Coordinates (side +1, theta1 >= 0, as ExactVssw in model.cpp): origin at the base pivot, x horizontal towards the
// side the wall rocks to, y up; both rotations clockwise positive. Every point of the mechanism is written once as
//   p(q) = Rot(theta1) r_lower + Rot(theta2) r_upper,   Rot(t) (x, y) = (x cos t + y sin t, -x sin t + y cos t),
// with r_lower its rest offset from the base pivot (the hinge's, for a point of the upper block) and r_upper its rest
// offset from the hinge (zero on the lower block): G1 = Rot(theta1)(-b, h1) = R1(-sin a, cos a) with a = alpha1 -
// theta1 (Eq. 1a); hinge = Rot(theta1)(-2b, 2h1) = 2 G1; G2 = hinge + Rot(theta2)(b, h2) = hinge + R2(sin psi, cos psi)
// with psi = alpha2 + theta2 (Eq. 1b); the roller corner = hinge + Rot(theta2)(2b, 2h2); the far top corner = hinge +
// Rot(theta2)(0, 2h2); the top centre (where N acts) = hinge + Rot(theta2)(b, 2h2). Because each term turns with one
// angle only, the Jacobian and the acceleration follow exactly: d/dt Rot(t) r = t' Rot(t) (r_y, -r_x) and
// d2/dt2 Rot(t) r = t'' Rot(t) (r_y, -r_x) - t'^2 Rot(t) r. Nothing else is differentiated by hand.
//
// Side -1 (theta1 <= 0) is the mirror image x -> -x, theta -> -theta, a_h -> -a_h. Since Mirror Rot(-t) Mirror =
// Rot(t), the mirrored mechanism is the same formula with the rest offsets' x negated: that is the one place the side
// enters (with the roller's direction, which is the mirrored one). For side -1 the origin is that side's base pivot
// (the lower block's -x corner); x, y, theta, a_h keep their physical directions, so q, forces and positions of side
// -1 are the mirror images of side +1's.
//
// Lagrangian (per unit depth of wall). T = 1/2 q'^T M q' with M = sum_i m_i J_Gi^T J_Gi + diag(I1, I2); Lagrange's
// equations give M q'' + c = Q with c = sum_i m_i J_Gi^T (dJ_Gi/dt q') and the generalised forces of the weights and
// the ground's pseudo-forces (-m_i a_h, -m_i (g + a_v)) at G_i and of N = (0, -N) at the top centre,
// Q = sum_i J_Gi^T F_i + J_top^T (0, -N). Energies relative to rest agree with ExactVssw's: V_w = g sum_i m_i
// (y_Gi(q) - y_Gi(0)) and the work of N = -N (y_top(q) - y_top(0)), so an energy balance carries over.
//
// Guides. The top is held between two frictionless vertical lines a wall-thickness apart (docs/guide/report.md, "The
// validation report"): the roller, x = 0 through the base pivot, holds the pivot-side top corner C; the other guide, x
// = -2b side, holds the far top corner F. Each guide's gap is n . p + offset >= 0 with n its inward normal: the
// roller's g(q) = -side x_C (the corner's distance from the roller line, positive inside the wall's line), the far
// guide's side x_F + 2b. A guide pushes its corner along n with a force lambda >= 0 [N/m], whose generalised force is
// J_g^T lambda (J_g = dg/dq): M q'' + c = Q + J_g^T lambda. As a bilateral constraint (on the roller: the exact one-DOF
// mechanism, Eq. 2), g = 0 and g'' = J_g q'' + dJ_g/dt q' = 0 give
//   lambda = -(J_g M^-1 (Q - c) + dJ_g/dt q') / (J_g M^-1 J_g^T),  q'' = M^-1 (Q - c + J_g^T lambda).
// Landing (plastic impact of a corner on its guide, no rebound): an impulse Lambda J_g^T takes q'- to
//   q'+ = q'- + M^-1 J_g^T Lambda,  Lambda = -J_g q'- / (J_g M^-1 J_g^T),
// which is the M-orthogonal projection of q'- onto the tangent t of the mechanism (J_g t = 0): q'+ = t (t^T M q'-) /
// (t^T M t), the J-^T M J+ / J+^T M J+ form. It dissipates (J_g q'-)^2 / (2 J_g M^-1 J_g^T) >= 0.
//
// The slot is narrow: with C on the roller, F is 2b cos(theta2) behind it, so the roller corner can leave its line by
// at most 2b (1 - cos theta2) ~ b theta2^2 (0.1 mm for Table 1 #7 at 0.8 alpha1) before F reaches the other guide.
// A two-DOF phase therefore ends on either guide: watch both gaps.
//
// Newton-Euler (any prescribed q, q', q''): the upper block's two force equations and its moment equation about G2
// give the hinge force (2 components) and the roller force; the lower block's force equations give the base force;
// the lower block's moment equation is what remains, returned as a residual (zero when q'' satisfies the equation of
// motion of the mechanism the forces describe, one-DOF with the roller or two-DOF with roller force zero).
#include <Eigen/Dense>

#include "wall.hpp"

namespace vssw {

using Vec2 = Eigen::Vector2d;        // a point or force in the plane [m], [N/m], or a generalised vector over q
using Mat2 = Eigen::Matrix2d;
using Row2 = Eigen::RowVector2d;     // a scalar's gradient over q

// Points of the mechanism that the module names.
enum class WallPoint {
    lower_centroid,  // G1
    upper_centroid,  // G2
    hinge,           // the lower block's top corner on the far face, on which the upper block turns
    roller_corner,   // the upper block's top corner on the pivot's face (on the roller in the one-DOF mechanism)
    far_top_corner,  // the upper block's top corner on the other face (facing the other guide, x = -2b side)
    top_centre,      // where N acts: the upper block's top face's centre, or e from it (geometry.hpp)
};

// The two vertical guides that hold the top (see the header comment).
enum class Guide {
    roller,  // x = 0 through the base pivot; holds the pivot-side top corner (the paper's roller)
    far,     // a wall-thickness behind it; holds the far top corner
};

// Forces in the plane [N/m], physical x and y (x towards the +1 side).
struct TwoBlockReactions {
    Vec2 base;                // ground on the lower block, at the base pivot
    Vec2 hinge;               // lower block on the upper block, at the hinge
    double roller = 0.0;      // the guide's force on its corner (the roller's unless another guide is named),
                              // positive when it pushes (along the guide's inward normal)
    double base_normal = 0.0, base_tangential = 0.0;    // base.y, base.x
    // Along n = Rot(theta1)(0, 1) (the lower block's top face normal, positive compressing the hinge) and
    // t = Rot(theta1)(1, 0) (the face itself, x-positive at rest).
    double hinge_normal = 0.0, hinge_tangential = 0.0;
    double base_friction = 0.0, hinge_friction = 0.0;   // |T| / N needed; +infinity when N <= 0
    bool base_pulls = false, hinge_pulls = false;       // N < 0: a contact would have to hold the blocks together
    // The lower block's moment equation about G1: I1 theta1'' minus the clockwise moments of the base and hinge
    // forces [N m/m]; zero when the prescribed motion satisfies the equation of motion.
    double moment_residual = 0.0;
};

class TwoBlockWall {
public:
    // side: +1 (theta1 >= 0) or -1 (theta1 <= 0); InputError otherwise.
    TwoBlockWall(const VsswGeometry& w, int side);

    const VsswGeometry& wall() const { return w_; }
    int side() const { return side_; }

    // Kinematics of a named point: position, Jacobian d p / d q (columns theta1, theta2), and its acceleration with
    // q'' = 0 (dJ/dt q'), so that p'' = J q'' + point_bias.
    Vec2 position(WallPoint p, const Vec2& q) const;
    Mat2 jacobian(WallPoint p, const Vec2& q) const;
    Vec2 point_bias(WallPoint p, const Vec2& q, const Vec2& qdot) const;

    // The configuration of the one-DOF mechanism at theta1 (theta2 from Eq. 2, sign of the side); InputError past
    // Eq. (26)'s limit, where the roller line cannot be reached, or on the wrong side.
    Vec2 on_roller(double theta1) const;
    // The same with the far top corner on the far guide (the upper block leaning back against it).
    Vec2 on_far_guide(double theta1) const;

    // Lagrangian terms: M(q), c(q, q') (velocity products), Q(q, a_h, a_v) (weights with g + a_v, the ground's
    // horizontal pseudo-force, N).
    Mat2 mass_matrix(const Vec2& q) const;
    Vec2 velocity_terms(const Vec2& q, const Vec2& qdot) const;
    Vec2 generalized_forces(const Vec2& q, double a_h, double a_v) const;

    // Energies relative to rest [J/m], as ExactVssw defines them (model.hpp).
    double kinetic(const Vec2& q, const Vec2& qdot) const;
    double weight_potential(const Vec2& q) const;
    double overburden_work(const Vec2& q) const;
    // Potential of constant ground accelerations' pseudo-forces, sum_i m_i (a_h x_Gi + a_v y_Gi) relative to rest:
    // T + V_w - W_N + this is conserved while a_h and a_v are constant.
    double ground_potential(const Vec2& q, double a_h, double a_v) const;

    // Free two-DOF motion (roller not touching): q'' = M^-1 (Q - c).
    Vec2 free_acceleration(const Vec2& q, const Vec2& qdot, double a_h, double a_v) const;

    // A guide's gap [m] (>= 0 allowed; the roller's is zero on Eq. 2), its gradient over q, and its rate.
    double gap(const Vec2& q, Guide guide = Guide::roller) const;
    Row2 gap_jacobian(const Vec2& q, Guide guide = Guide::roller) const;
    double gap_rate(const Vec2& q, const Vec2& qdot, Guide guide = Guide::roller) const;
    // Tangent of the one-DOF mechanism on a guide at q: (1, dtheta2/dtheta1) with J_g t = 0.
    Vec2 mechanism_tangent(const Vec2& q, Guide guide = Guide::roller) const;

    // A guide as a bilateral constraint (on the roller: the exact one-DOF mechanism; q should be on the guide's line).
    struct ConstrainedMotion {
        Vec2 qddot;
        double roller = 0.0;  // Lagrange multiplier = the guide's force [N/m], positive pushing
    };
    ConstrainedMotion constrained_motion(const Vec2& q, const Vec2& qdot, double a_h, double a_v,
                                         Guide guide = Guide::roller) const;

    // Plastic landing of a corner on its guide at q (on the line): the post-impact velocity, its theta1 (the one-DOF
    // model's velocity), the impulse [N s/m] (>= 0 when the corner was approaching) and the energy dissipated [J/m].
    struct Landing {
        Vec2 qdot;
        double theta1_dot = 0.0;
        double impulse = 0.0;
        double dissipated = 0.0;
    };
    Landing land(const Vec2& q, const Vec2& qdot, Guide guide = Guide::roller) const;

    // Newton-Euler reactions for a prescribed motion of both bodies (see the header comment), with the top held by
    // the named guide (the other one idle).
    TwoBlockReactions reactions(const Vec2& q, const Vec2& qdot, const Vec2& qddot, double a_h, double a_v,
                                Guide guide = Guide::roller) const;

private:
    struct Offsets {
        Vec2 lower, upper;  // rest offsets from the base pivot and from the hinge (mirrored for side -1)
    };
    Offsets offsets(WallPoint p) const;
    struct GuideLine {
        WallPoint corner;  // the corner it holds
        Vec2 normal;       // inward normal: the direction it pushes
        double offset;     // gap = normal . position + offset
    };
    GuideLine guide_line(Guide guide) const;

    VsswGeometry w_;
    int side_;
};

}  // namespace vssw

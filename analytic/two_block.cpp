#include "two_block.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "closed_forms.hpp"
#include "error.hpp"
#include "fast_sincos.hpp"

namespace vssw {
namespace {

// A turn by t, its cosine and sine computed once: the reactions evaluate a dozen points at the same two angles at
// every step of a run, and the sines and cosines were most of their cost.
struct Turn {
    double c, s;
    explicit Turn(double t) : Turn(fast_sincos(t)) {}
    explicit Turn(SinCos sc) : c(sc.cos), s(sc.sin) {}
};
// Rot(t) turns a rest offset clockwise by t (the sense of positive theta1 and theta2).
Vec2 rot(const Turn& t, const Vec2& r) { return {r.x() * t.c + r.y() * t.s, -r.x() * t.s + r.y() * t.c}; }
Vec2 rot(double t, const Vec2& r) { return rot(Turn(t), r); }
// d/dt Rot(t) r = Rot(t) perp(r): the derivative of a clockwise rotation.
Vec2 perp(const Vec2& r) { return {r.y(), -r.x()}; }

// Clockwise moment about the origin of r of a force f applied at r: -(r x f)_z.
double clockwise_moment(const Vec2& r, const Vec2& f) { return r.y() * f.x() - r.x() * f.y(); }

// Tested before require() is called: its std::string arguments would be built at every call otherwise, and the
// supports' monitor makes ten of these checks at every step (8 % of a record run's instructions, callgrind). The
// throwing part is kept out of line so that the test itself inlines.
[[gnu::cold, gnu::noinline]] void refuse_non_finite(double v, const char* name) {
    require(false, name, "a finite number", v);
}
inline void require_finite(double v, const char* name) {
    if (!std::isfinite(v)) refuse_non_finite(v, name);
}
void require_finite(const Vec2& v, const char* name0, const char* name1) {
    require_finite(v.x(), name0);
    require_finite(v.y(), name1);
}

double sq(double x) { return x * x; }

}  // namespace

TwoBlockWall::TwoBlockWall(const VsswGeometry& w, int side) : w_(w), side_(side) {
    require(side == 1 || side == -1, "side", "+1 or -1", side);
}

TwoBlockWall::Offsets TwoBlockWall::offsets(WallPoint p) const {
    // The rest offsets of side +1 (see the header); the mirror negates their x for side -1.
    const double b = w_.b, h1 = w_.h1, h2 = w_.h2;
    const Vec2 hinge(-2.0 * b, 2.0 * h1);
    Offsets o{Vec2::Zero(), Vec2::Zero()};
    switch (p) {
        case WallPoint::lower_centroid: o = {Vec2(-b, h1), Vec2::Zero()}; break;
        case WallPoint::hinge: o = {hinge, Vec2::Zero()}; break;
        case WallPoint::upper_centroid: o = {hinge, Vec2(b, h2)}; break;
        case WallPoint::roller_corner: o = {hinge, Vec2(2.0 * b, 2.0 * h2)}; break;
        case WallPoint::far_top_corner: o = {hinge, Vec2(0.0, 2.0 * h2)}; break;
        // N's point: the top face's centre moved by e toward the side theta1 > 0, which the mirror sees as -e.
        case WallPoint::top_centre: o = {hinge, Vec2(b + side_ * w_.eccentricity * b, 2.0 * h2)}; break;
    }
    o.lower.x() *= side_;
    o.upper.x() *= side_;
    return o;
}

Vec2 TwoBlockWall::position(WallPoint p, const Vec2& q) const {
    require_finite(q, "theta1", "theta2");
    const Offsets o = offsets(p);
    return rot(q(0), o.lower) + rot(q(1), o.upper);
}

Mat2 TwoBlockWall::jacobian(WallPoint p, const Vec2& q) const {
    require_finite(q, "theta1", "theta2");
    const Offsets o = offsets(p);
    Mat2 J;
    J.col(0) = rot(q(0), perp(o.lower));
    J.col(1) = rot(q(1), perp(o.upper));
    return J;
}

Vec2 TwoBlockWall::point_bias(WallPoint p, const Vec2& q, const Vec2& qdot) const {
    require_finite(q, "theta1", "theta2");
    require_finite(qdot, "theta1'", "theta2'");
    // The centripetal part of d2/dt2 Rot(t) r: -t'^2 Rot(t) r for each block's term.
    const Offsets o = offsets(p);
    return -sq(qdot(0)) * rot(q(0), o.lower) - sq(qdot(1)) * rot(q(1), o.upper);
}

Vec2 TwoBlockWall::on_roller(double theta1) const {
    require_finite(theta1, "theta1");
    require(side_ * theta1 >= 0.0, side_ > 0 ? "theta1 on side +1" : "theta1 on side -1",
            side_ > 0 ? ">= 0" : "<= 0", theta1);
    const std::optional<double> theta2 = eq2_theta2_exact(w_, theta1);
    require(theta2.has_value(), "theta1", "within Eq. (26)'s roller limit", theta1);
    return {theta1, *theta2};
}

Mat2 TwoBlockWall::mass_matrix(const Vec2& q) const {
    const Mat2 J1 = jacobian(WallPoint::lower_centroid, q);
    const Mat2 J2 = jacobian(WallPoint::upper_centroid, q);
    Mat2 M = w_.m1 * J1.transpose() * J1 + w_.m2 * J2.transpose() * J2;
    M(0, 0) += w_.I1;
    M(1, 1) += w_.I2;
    return M;
}

Vec2 TwoBlockWall::velocity_terms(const Vec2& q, const Vec2& qdot) const {
    // Lagrange's equations of T = 1/2 sum m_i |v_Gi|^2 + rotational terms: the velocity products are
    // sum_i m_i J_Gi^T (dJ_Gi/dt q'); the rotational terms have constant inertia and add none.
    return w_.m1 * jacobian(WallPoint::lower_centroid, q).transpose() *
               point_bias(WallPoint::lower_centroid, q, qdot) +
           w_.m2 * jacobian(WallPoint::upper_centroid, q).transpose() *
               point_bias(WallPoint::upper_centroid, q, qdot);
}

Vec2 TwoBlockWall::generalized_forces(const Vec2& q, double a_h, double a_v) const {
    require_finite(a_h, "a_h");
    require_finite(a_v, "a_v");
    const double g_eff = w_.g + a_v;
    const Vec2 F1(-w_.m1 * a_h, -w_.m1 * g_eff), F2(-w_.m2 * a_h, -w_.m2 * g_eff), FN(0.0, -w_.N);
    return jacobian(WallPoint::lower_centroid, q).transpose() * F1 +
           jacobian(WallPoint::upper_centroid, q).transpose() * F2 +
           jacobian(WallPoint::top_centre, q).transpose() * FN;
}

double TwoBlockWall::kinetic(const Vec2& q, const Vec2& qdot) const {
    require_finite(qdot, "theta1'", "theta2'");
    return 0.5 * qdot.dot(mass_matrix(q) * qdot);
}

double TwoBlockWall::weight_potential(const Vec2& q) const {
    const Vec2 rest = Vec2::Zero();
    auto height = [&](const Vec2& at) {
        return w_.m1 * position(WallPoint::lower_centroid, at).y() +
               w_.m2 * position(WallPoint::upper_centroid, at).y();
    };
    return w_.g * (height(q) - height(rest));
}

double TwoBlockWall::overburden_work(const Vec2& q) const {
    return -w_.N * (position(WallPoint::top_centre, q).y() - position(WallPoint::top_centre, Vec2::Zero()).y());
}

double TwoBlockWall::ground_potential(const Vec2& q, double a_h, double a_v) const {
    require_finite(a_h, "a_h");
    require_finite(a_v, "a_v");
    auto moment = [&](const Vec2& at) {
        return Vec2(w_.m1 * position(WallPoint::lower_centroid, at) + w_.m2 * position(WallPoint::upper_centroid, at));
    };
    return Vec2(a_h, a_v).dot(moment(q) - moment(Vec2::Zero()));
}

Vec2 TwoBlockWall::free_acceleration(const Vec2& q, const Vec2& qdot, double a_h, double a_v) const {
    // M is symmetric positive definite (a kinetic energy): LDLT.
    return mass_matrix(q).ldlt().solve(generalized_forces(q, a_h, a_v) - velocity_terms(q, qdot));
}

TwoBlockWall::GuideLine TwoBlockWall::guide_line(Guide guide) const {
    // The roller is the line x = 0, pushing towards -side; the far guide the line x = -2b side, pushing towards side.
    if (guide == Guide::roller) return {WallPoint::roller_corner, Vec2(-side_, 0.0), 0.0};
    return {WallPoint::far_top_corner, Vec2(side_, 0.0), 2.0 * w_.b};
}

Vec2 TwoBlockWall::on_far_guide(double theta1) const {
    require_finite(theta1, "theta1");
    require(side_ * theta1 >= 0.0, side_ > 0 ? "theta1 on side +1" : "theta1 on side -1",
            side_ > 0 ? ">= 0" : "<= 0", theta1);
    // F = hinge + Rot(theta2)(0, 2h2) (the offset has no x to mirror): side x_F + 2b = 0 fixes sin(theta2).
    const double hinge_x = position(WallPoint::hinge, Vec2(theta1, 0.0)).x();
    return {theta1, std::asin(-side_ * (2.0 * w_.b + side_ * hinge_x) / (2.0 * w_.h2))};
}

double TwoBlockWall::gap(const Vec2& q, Guide guide) const {
    const GuideLine l = guide_line(guide);
    return l.normal.dot(position(l.corner, q)) + l.offset;
}

Row2 TwoBlockWall::gap_jacobian(const Vec2& q, Guide guide) const {
    const GuideLine l = guide_line(guide);
    return l.normal.transpose() * jacobian(l.corner, q);
}

double TwoBlockWall::gap_rate(const Vec2& q, const Vec2& qdot, Guide guide) const {
    require_finite(qdot, "theta1'", "theta2'");
    return gap_jacobian(q, guide) * qdot;
}

Vec2 TwoBlockWall::mechanism_tangent(const Vec2& q, Guide guide) const {
    // J_g (1, t2) = 0. dg/dtheta2 (the corner's horizontal speed per unit theta2') vanishes only with the upper block
    // turned a right angle, far outside any mechanism of the wall.
    const Row2 Jg = gap_jacobian(q, guide);
    return {1.0, -Jg(0) / Jg(1)};
}

TwoBlockWall::ConstrainedMotion TwoBlockWall::constrained_motion(const Vec2& q, const Vec2& qdot, double a_h,
                                                                 double a_v, Guide guide) const {
    const GuideLine l = guide_line(guide);
    const Eigen::LDLT<Mat2> M = mass_matrix(q).ldlt();
    const Row2 Jg = gap_jacobian(q, guide);
    const Vec2 free = M.solve(generalized_forces(q, a_h, a_v) - velocity_terms(q, qdot));
    const Vec2 Minv_JgT = M.solve(Jg.transpose());
    // g'' = J_g q'' + dJ_g/dt q' = 0, with dJ_g/dt q' = n . (the corner's bias).
    const double gap_bias = l.normal.dot(point_bias(l.corner, q, qdot));
    const double lambda = -(Jg * free + gap_bias) / (Jg * Minv_JgT);
    return {free + Minv_JgT * lambda, lambda};
}

TwoBlockWall::Landing TwoBlockWall::land(const Vec2& q, const Vec2& qdot, Guide guide) const {
    const Eigen::LDLT<Mat2> M = mass_matrix(q).ldlt();
    const Row2 Jg = gap_jacobian(q, guide);
    const Vec2 Minv_JgT = M.solve(Jg.transpose());
    const double effective = Jg * Minv_JgT;  // J_g M^-1 J_g^T: the inverse of the corner's effective mass
    const double rate = gap_rate(q, qdot, guide);
    Landing out;
    out.impulse = -rate / effective;
    out.qdot = qdot + Minv_JgT * out.impulse;
    out.theta1_dot = out.qdot(0);
    out.dissipated = 0.5 * sq(rate) / effective;
    return out;
}

TwoBlockReactions TwoBlockWall::reactions(const Vec2& q, const Vec2& qdot, const Vec2& qddot, double a_h,
                                          double a_v, Guide guide) const {
    require_finite(qddot, "theta1''", "theta2''");
    require_finite(a_h, "a_h");
    require_finite(a_v, "a_v");
    require_finite(q, "theta1", "theta2");
    require_finite(qdot, "theta1'", "theta2'");
    const Turn t1(q(0)), t2(q(1));
    auto position_of = [&](WallPoint p) {
        const Offsets o = offsets(p);
        return Vec2(rot(t1, o.lower) + rot(t2, o.upper));
    };
    // p'' = J q'' + dJ/dt q' with J's columns Rot perp(offset) and the centripetal -t'^2 Rot(offset) (see jacobian()).
    auto acceleration = [&](WallPoint p) {
        const Offsets o = offsets(p);
        return Vec2(qddot(0) * rot(t1, perp(o.lower)) + qddot(1) * rot(t2, perp(o.upper)) -
                    sq(qdot(0)) * rot(t1, o.lower) - sq(qdot(1)) * rot(t2, o.upper));
    };
    const double g_eff = w_.g + a_v;
    const Vec2 F1(-w_.m1 * a_h, -w_.m1 * g_eff), F2(-w_.m2 * a_h, -w_.m2 * g_eff), FN(0.0, -w_.N);
    const Vec2 G1 = position_of(WallPoint::lower_centroid), G2 = position_of(WallPoint::upper_centroid);
    const GuideLine l = guide_line(guide);
    const Vec2 H = position_of(WallPoint::hinge), C = position_of(l.corner);
    const Vec2 T = position_of(WallPoint::top_centre);
    const Vec2 push = l.normal;  // the guide's direction on its corner

    // Upper block, unknowns (H_x, H_y, lambda): m2 a_G2 = H + lambda push + F2 + FN (two rows) and I2 theta2'' =
    // the clockwise moments about G2, (H - G2).y H_x - (H - G2).x H_y + moment(C - G2, push) lambda (third row).
    // The force rows give H = force_rhs - lambda push; put into the moment row, lambda times the moment of `push`
    // about the hinge, moment(C - H, push) = -+(C - H).y (nonzero unless the block lies flat), is what is left: a
    // 3 x 3 system solved by hand (a general LU was 9 % of a record run's instructions, callgrind).
    const Vec2 force_rhs = w_.m2 * acceleration(WallPoint::upper_centroid) - F2 - FN;
    const double moment_rhs = w_.I2 * qddot(1) - clockwise_moment(T - G2, FN);
    const Vec2 d = H - G2;
    const double lambda = (moment_rhs - clockwise_moment(d, force_rhs)) / clockwise_moment(C - H, push);

    TwoBlockReactions r;
    r.hinge = force_rhs - lambda * push;
    r.roller = lambda;
    // Lower block: m1 a_G1 = B - H + F1; its moment equation is the residual.
    r.base = w_.m1 * acceleration(WallPoint::lower_centroid) - F1 + r.hinge;
    r.moment_residual =
        w_.I1 * qddot(0) - clockwise_moment(-G1, r.base) - clockwise_moment(H - G1, Vec2(-r.hinge));

    r.base_normal = r.base.y();
    r.base_tangential = r.base.x();
    r.hinge_normal = r.hinge.dot(rot(t1, Vec2(0.0, 1.0)));
    r.hinge_tangential = r.hinge.dot(rot(t1, Vec2(1.0, 0.0)));
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    r.base_friction = r.base_normal > 0.0 ? std::abs(r.base_tangential) / r.base_normal : kInfinity;
    r.hinge_friction = r.hinge_normal > 0.0 ? std::abs(r.hinge_tangential) / r.hinge_normal : kInfinity;
    r.base_pulls = r.base_normal < 0.0;
    r.hinge_pulls = r.hinge_normal < 0.0;
    return r;
}

}  // namespace vssw

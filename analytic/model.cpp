#include "model.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "closed_forms.hpp"
#include "error.hpp"
#include "fast_sincos.hpp"

namespace vssw {
namespace {

constexpr double kHalfPi = 1.5707963267948966;
// The exact kinematics lock at Eq. (26) (theta2'/theta1' is infinite there), so overturning is declared this close
// to it: a relative margin that keeps the inertia finite (M ~ 1/(theta_lim - q)) where the event is located.
constexpr double kRollerLimitMargin = 1e-6;

double sq(double x) { return x * x; }

// Overturning angle of the VSSW: the roller is violated at Eq. (26) when h1 > h2; otherwise (Eq. 26 does not exist)
// the lower body's pivot-side face reaches the ground at pi/2, which ends the two-block mechanism.
double vssw_collapse_angle(const VsswGeometry& w) {
    if (const auto lim = eq26_limit_rotation(w)) return std::min(*lim * (1.0 - kRollerLimitMargin), kHalfPi);
    return kHalfPi;
}

// What the two VSSW kinematics share: the wall, the impact law, the reference and collapse angles, and the height of
// N's point (the centre of the top face) for a given lower-body angle and theta2.
class VsswModel : public RockingModel {
public:
    explicit VsswModel(const VsswGeometry& w) : w_(w) {}
    // The impact happens at q = 0, where Eq. (2) and Eq. (3) have the same slope: Eq. (19) serves both kinematics.
    double restitution() const override { return eq19_restitution(w_); }
    double reference_angle() const override { return w_.alpha1; }
    double collapse_angle() const override { return vssw_collapse_angle(w_); }  // the exact kinematics'
    double gravity() const override { return w_.g; }
    double overburden() const override { return w_.N; }
    double eccentricity() const override { return w_.eccentricity * w_.b; }
    double flat_share() const override { return 1.0 - w_.corner_radius; }
    const VsswGeometry* vssw_geometry() const override { return &w_; }

protected:
    // Hinge height 2 R1 cos(a) plus the top centre's height above the hinge, (b, 2 h2) turned by theta2.
    double top_centre_height(double cos_a, double sin_theta2, double cos_theta2) const {
        return 2.0 * w_.R1 * cos_a + 2.0 * w_.h2 * cos_theta2 - w_.b * sin_theta2;
    }
    VsswGeometry w_;
};

// The paper's kinematics lock where Eq. (3) has turned the upper body by alpha2 + pi/2 (A2 = alpha2 - k q = -pi/2):
// cos A2 = 0 there and the mass function of Eq. (11a) is infinite (sec^2 A2), so a wall driven towards it creeps
// ever slower and never arrives. With the hinge high (k = h1/h2 large) this comes before Eq. (26); the run counts it as
// overturning once |cos A2| falls below kPaperLockCos, where M(q) is already 1e6 times its value at rest: a wall
// that far out has left the paper's mechanism for good (docs/model/paper.md "Where each kinematics stops being valid").
constexpr double kPaperLockCos = 1e-3;

double paper_lock_angle(const VsswGeometry& w) { return (w.alpha2 + kHalfPi - std::asin(kPaperLockCos)) / w.k; }

class PaperVssw final : public VsswModel {
public:
    explicit PaperVssw(const VsswGeometry& w) : VsswModel(w), eq11_(w), e_(eccentricity()) {}
    double collapse_angle() const override { return std::min(vssw_collapse_angle(w_), paper_lock_angle(w_)); }
    ModelTerms terms(double q) const override {
        const Eq11Coefficients c = eq11_(q);
        const double R1 = w_.R1;
        // N's point at e from the top centre rises by -e sin(theta2) = e sin(k q) (Eq. 3): its lever is e k cos(k q).
        return {R1 * R1 * c.C_A, R1 * R1 * c.C_S, R1 * c.C_H, R1 * c.C_V, R1 * c.C_N, w_.k * std::cos(w_.k * q)};
    }
    RockingRates rates(int side, double q, double theta_dot, double a_h, double a_v) const override {
        // rocking_rates_scaled's Eq. (10) with the levers' common factor cos^3 A2 taken out of their three terms.
        const Eq11Evaluator::Scaled c = eq11_.scaled(q);
        const double sign = side;
        const double rhs = -c.cos3 * (a_h * c.X + sign * ((a_v + w_.g) * c.Y + w_.N * (c.L + sign * e_ * c.Le))) -
                           sign * c.C * theta_dot * theta_dot;
        return {rhs / c.M, -a_h * c.X - sign * a_v * c.Y};
    }
    double mass_moment_height(double q) const override {
        return eq6_potential(w_, q, eq3_theta2_linear(w_, q)) / w_.g;
    }
    double load_height(double q) const override {
        const double theta2 = eq3_theta2_linear(w_, q);
        return top_centre_height(std::cos(w_.alpha1 - q), std::sin(theta2), std::cos(theta2));
    }
    double load_height_per_eccentricity(double q) const override { return std::sin(w_.k * q); }
    std::string name() const override { return "vssw/paper"; }
    UpperRotation upper_rotation(double q) const override { return {-w_.k * q, -w_.k, 0.0}; }  // Eq. (3)
    std::optional<Kinematics> kinematics() const override { return Kinematics::paper; }

private:
    Eq11Evaluator eq11_;
    double e_;  // N's eccentricity [m]
};

// Exact kinematics: psi = alpha2 + theta2 from Eq. (2), sin(psi) = s sin(alpha1 - q). G1 = R1(-sin a, cos a) with
// a = alpha1 - q (Eq. 1a); G2 = hinge + R2(sin psi, cos psi) (Eq. 1b); the top roller keeps x_G2 = x_hinge / 2.
class ExactVssw final : public VsswModel {
public:
    explicit ExactVssw(const VsswGeometry& w) : VsswModel(w), e_(eccentricity()) {}

    struct Angles {
        double sa, ca, spsi, cpsi, dpsi, ddpsi;
    };
    Angles angles(double q) const {
        Angles g{};
        const SinCos a = fast_sincos(w_.alpha1 - q);
        g.sa = a.sin;
        g.ca = a.cos;
        g.spsi = w_.s * g.sa;
        // Past Eq. (26) there is no configuration; the floor keeps a trial step finite so the step is rejected.
        const double cpsi2 = std::max(1.0 - sq(g.spsi), 1e-30);
        g.cpsi = std::sqrt(cpsi2);
        // 1/cos(psi) as cos(psi) / cos^2(psi): the square root and the division run side by side instead of one
        // after the other (the same number to rounding; the integrator's stages use rates() below, with no division
        // before the last).
        const double inv_cpsi = g.cpsi * (1.0 / cpsi2);
        g.dpsi = -w_.s * g.ca * inv_cpsi;
        g.ddpsi = -w_.s * (g.sa * g.cpsi + g.ca * g.spsi * g.dpsi) * inv_cpsi * inv_cpsi;
        return g;
    }

    ModelTerms terms(double q) const override {
        const Angles g = angles(q);
        const double R1 = w_.R1, R2 = w_.R2;
        const double dx2 = R1 * g.ca, ddx2 = R1 * g.sa;
        const double dy2 = 2.0 * R1 * g.sa - R2 * g.spsi * g.dpsi;
        const double ddy2 = -2.0 * R1 * g.ca - R2 * (g.cpsi * sq(g.dpsi) + g.spsi * g.ddpsi);
        const double s2 = g.spsi * w_.cos_a2 - g.cpsi * w_.sin_a2;  // sin(theta2), theta2 = psi - alpha2
        const double c2 = g.cpsi * w_.cos_a2 + g.spsi * w_.sin_a2;  // cos(theta2)
        ModelTerms t{};
        t.M = w_.m1 * R1 * R1 + w_.I1 + w_.m2 * (sq(dx2) + sq(dy2)) + w_.I2 * sq(g.dpsi);
        t.C = w_.m2 * (dx2 * ddx2 + dy2 * ddy2) + w_.I2 * g.dpsi * g.ddpsi;  // M'/2
        t.X = (w_.m1 + w_.m2) * R1 * g.ca;
        t.Y = w_.m1 * R1 * g.sa + w_.m2 * dy2;
        t.L = 2.0 * R1 * g.sa - (2.0 * w_.h2 * s2 + w_.b * c2) * g.dpsi;
        t.Le = -c2 * g.dpsi;  // N's point at e from the top centre rises by -e sin(theta2)
        return t;
    }
    // terms(q) multiplied through by cos^4 psi: psi', psi'' and the terms have powers of cos psi as denominators.
    // With D = cos psi psi' = -s cos a and DD = cos^3 psi psi'' = -s (sin a cos^2 psi + cos a sin psi D):
    RockingRates rates(int side, double q, double theta_dot, double a_h, double a_v) const override {
        const SinCos a = fast_sincos(w_.alpha1 - q);
        const double sa = a.sin, ca = a.cos, spsi = w_.s * sa;
        const double cpsi2 = std::max(1.0 - sq(spsi), 1e-30);  // as in angles()
        const double cpsi = std::sqrt(cpsi2);
        const double D = -w_.s * ca, DD = -w_.s * (sa * cpsi2 + ca * spsi * D);
        const double R1 = w_.R1, R2 = w_.R2;
        const double dx2 = R1 * ca, ddx2 = R1 * sa;
        const double dy2_c = 2.0 * R1 * sa * cpsi - R2 * spsi * D;                           // cos psi y2'
        const double ddy2_c3 = -2.0 * R1 * ca * cpsi2 * cpsi - R2 * (D * D * cpsi2 + spsi * DD);  // cos^3 psi y2''
        const double s2 = spsi * w_.cos_a2 - cpsi * w_.sin_a2, c2 = cpsi * w_.cos_a2 + spsi * w_.sin_a2;
        const double cpsi3 = cpsi2 * cpsi, cpsi4 = cpsi2 * cpsi2;
        const double Y_c = w_.m1 * R1 * sa * cpsi + w_.m2 * dy2_c;  // cos psi Y
        ModelTerms t{};
        t.M = cpsi2 * ((w_.m1 * R1 * R1 + w_.I1) * cpsi2 + w_.m2 * (sq(dx2) * cpsi2 + sq(dy2_c)) + w_.I2 * D * D);
        t.C = w_.m2 * (dx2 * ddx2 * cpsi4 + dy2_c * ddy2_c3) + w_.I2 * D * DD;
        const double X = (w_.m1 + w_.m2) * R1 * ca;
        t.X = X * cpsi4;
        t.Y = Y_c * cpsi3;
        t.L = cpsi3 * (2.0 * R1 * sa * cpsi - (2.0 * w_.h2 * s2 + w_.b * c2) * D);
        t.Le = -cpsi3 * c2 * D;
        return rocking_rates_scaled(t, X, Y_c / cpsi, side, theta_dot, a_h, a_v, w_.g, w_.N, e_);
    }
    double mass_moment_height(double q) const override {
        const Angles g = angles(q);
        return w_.m1 * w_.R1 * g.ca + w_.m2 * (2.0 * w_.R1 * g.ca + w_.R2 * g.cpsi);
    }
    double load_height(double q) const override {
        const Angles g = angles(q);
        const double s2 = g.spsi * w_.cos_a2 - g.cpsi * w_.sin_a2, c2 = g.cpsi * w_.cos_a2 + g.spsi * w_.sin_a2;
        return top_centre_height(g.ca, s2, c2);
    }
    double load_height_per_eccentricity(double q) const override {
        const Angles g = angles(q);
        return -(g.spsi * w_.cos_a2 - g.cpsi * w_.sin_a2);  // -sin(theta2)
    }
    std::string name() const override { return "vssw/exact"; }
    std::optional<Kinematics> kinematics() const override { return Kinematics::exact; }
    UpperRotation upper_rotation(double q) const override {  // Eq. (2): theta2 = psi - alpha2
        const Angles g = angles(q);
        return {std::atan2(g.spsi, g.cpsi) - w_.alpha2, g.dpsi, g.ddpsi};
    }

private:
    double e_;  // N's eccentricity [m]
};

// Housner's block rocking on a base corner; N on the top face at e from its centre, (e - b, 2h) from the pivot at rest.
class Parapet final : public RockingModel {
public:
    explicit Parapet(const ParapetGeometry& p) : p_(p) {}
    ModelTerms terms(double q) const override {
        const SinCos a = fast_sincos(p_.alpha - q), turn = fast_sincos(q);
        return {p_.I_O, 0.0, p_.m * p_.R * a.cos, p_.m * p_.R * a.sin, p_.b * turn.cos - 2.0 * p_.h * turn.sin,
                -turn.cos};
    }
    double mass_moment_height(double q) const override { return p_.m * p_.R * std::cos(p_.alpha - q); }
    double load_height(double q) const override { return 2.0 * p_.h * std::cos(q) + p_.b * std::sin(q); }
    double eccentricity() const override { return p_.eccentricity * p_.b; }
    double flat_share() const override { return 1.0 - p_.corner_radius; }
    double load_height_per_eccentricity(double q) const override { return -std::sin(q); }
    double restitution() const override { return housner_restitution(p_.alpha); }
    double reference_angle() const override { return p_.alpha; }
    // The block lies on its face at pi/2; passing alpha alone is not collapse under forcing (the paper, Sect. 2).
    double collapse_angle() const override { return kHalfPi; }
    double gravity() const override { return p_.g; }
    double overburden() const override { return p_.N; }
    std::string name() const override { return "parapet"; }

private:
    ParapetGeometry p_;
};

}  // namespace

Kinematics parse_kinematics(const std::string& text) {
    if (text == "paper") return Kinematics::paper;
    if (text == "exact") return Kinematics::exact;
    throw InputError("kinematics must be 'paper' or 'exact', got '" + text + "'");
}

const char* to_string(Kinematics k) { return k == Kinematics::paper ? "paper" : "exact"; }

RockingRates rocking_rates(const ModelTerms& t, int side, double theta_dot, double a_h, double a_v, double g,
                           double N, double e) {
    const double sign = side;
    const double ground = -a_h * t.X - sign * a_v * t.Y;
    const double rhs = ground - sign * (g * t.Y + N * (t.L + sign * e * t.Le) + t.C * theta_dot * theta_dot);
    return {rhs / t.M, ground};
}

RockingRates rocking_rates_scaled(const ModelTerms& t, double X, double Y, int side, double theta_dot,
                                  double a_h, double a_v, double g, double N, double e) {
    const double sign = side;
    const double rhs =
        -a_h * t.X - sign * (a_v * t.Y + g * t.Y + N * (t.L + sign * e * t.Le) + t.C * theta_dot * theta_dot);
    return {rhs / t.M, -a_h * X - sign * a_v * Y};
}

RockingRates RockingModel::rates(int side, double q, double theta_dot, double a_h, double a_v) const {
    return rocking_rates(terms(q), side, theta_dot, a_h, a_v, gravity(), overburden(), eccentricity());
}

double RockingModel::acceleration(int side, double theta, double theta_dot, double a_h, double a_v) const {
    return rocking_rates(terms(side * theta), side, theta_dot, a_h, a_v, gravity(), overburden(), eccentricity())
        .acceleration;
}

double RockingModel::ground_force(int side, double theta, double a_h, double a_v) const {
    return rocking_rates(terms(side * theta), side, 0.0, a_h, a_v, gravity(), overburden(), eccentricity())
        .ground_force;
}

double RockingModel::weight_potential(double theta) const {
    return gravity() * (mass_moment_height(std::abs(theta)) - mass_moment_height(0.0));
}

double RockingModel::overburden_work(double theta) const {
    const double q = std::abs(theta), e = eccentricity();
    if (e == 0.0) return -overburden() * (load_height(q) - load_height(0.0));
    // Mirrored, the wall sees N at -e (model.hpp).
    const double side_e = theta < 0.0 ? -e : e;
    return -overburden() * (load_height(q) - load_height(0.0) +
                            side_e * (load_height_per_eccentricity(q) - load_height_per_eccentricity(0.0)));
}

double RockingModel::kinetic(double theta, double theta_dot) const {
    return 0.5 * terms(std::abs(theta)).M * sq(theta_dot);
}

// |V_r| keeps it real where V_r < 0 (a heavy overburden puts alpha1 past the unstable equilibrium; found by the
// property sweep, tests/test_properties.cpp).
double RockingModel::reference_velocity() const {
    return std::sqrt(2.0 * std::abs(reference_energy()) / terms(0.0).M);
}

double RockingModel::reference_energy() const {
    const double v = potential(reference_angle());
    if (eccentricity() == 0.0) return v;  // the two sides are one (the potential reads |theta1|)
    const double other = potential(-reference_angle());
    return std::abs(other) > std::abs(v) ? other : v;
}

double RockingModel::unstable_equilibrium(int side) const {
    require(side == 1 || side == -1, "side of rocking", "+1 or -1", side);
    // The potential rises from rest to one maximum and falls to the collapse (a heavy overburden moves the maximum
    // below alpha1, never makes two): a scan brackets it, golden sections shrink the bracket to round-off.
    constexpr int kScan = 256;
    constexpr int kGoldenSteps = 80;  // 0.618^80 of a scan cell: below double's resolution of the angle
    const double top = collapse_angle();
    // Each potential evaluated once where it is compared (the same values as evaluating it again: every run's
    // monitor computes this, 0.4 M instructions of a free vibration's run before).
    auto v = [&](double q) { return potential(side * q); };
    int best = 1;
    double v_best = v(top * best / kScan);
    for (int i = 2; i < kScan; ++i)
        if (const double v_i = v(top * i / kScan); v_i > v_best) best = i, v_best = v_i;
    double lo = top * (best - 1) / kScan, hi = top * (best + 1) / kScan;
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int k = 0; k < kGoldenSteps; ++k) {
        const double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
        if (v(a) < v(b))
            lo = a;
        else
            hi = b;
    }
    return 0.5 * (lo + hi);
}

double RockingModel::unstable_equilibrium() const {
    const double positive = unstable_equilibrium(1);
    if (eccentricity() == 0.0) return positive;  // the two sides are one
    return std::max(positive, unstable_equilibrium(-1));
}

double RockingModel::rest_threshold(double a_v, int side) const {
    const double flat = flat_share();
    if (flat >= 1.0) return holding_acceleration(side, 0.0, a_v);
    const ModelTerms t = terms(0.0);  // Eq. (12r) / (17r): Y and L at rest are b times a lever
    return ((gravity() + a_v) * t.Y * flat + overburden() * (t.L * flat + side * eccentricity() * t.Le)) / t.X;
}

double RockingModel::holding_acceleration(int side, double q, double a_v) const {
    const ModelTerms t = terms(q);
    return ((gravity() + a_v) * t.Y + overburden() * (t.L + side * eccentricity() * t.Le)) / t.X;
}

double RockingModel::rest_threshold(double a_v) const { return rest_threshold(a_v, easier_side()); }

int RockingModel::easier_side() const { return rest_threshold(0.0, 1) < rest_threshold(0.0, -1) ? 1 : -1; }

double restitution_from_peaks(const RockingModel& m, double peak_before, double peak_after) {
    return std::sqrt(m.potential(peak_after) / m.potential(peak_before));
}

std::unique_ptr<RockingModel> make_vssw_model(const VsswGeometry& w, Kinematics kinematics) {
    if (kinematics == Kinematics::paper) return std::make_unique<PaperVssw>(w);
    return std::make_unique<ExactVssw>(w);
}

std::unique_ptr<RockingModel> make_parapet_model(const ParapetGeometry& p) { return std::make_unique<Parapet>(p); }

namespace {

// Every term of the wrapped model, the impact ratio replaced.
class WithRestitution final : public RockingModel {
public:
    WithRestitution(std::unique_ptr<RockingModel> model, double e) : model_(std::move(model)), e_(e) {}
    ModelTerms terms(double q) const override { return model_->terms(q); }
    RockingRates rates(int side, double q, double theta_dot, double a_h, double a_v) const override {
        return model_->rates(side, q, theta_dot, a_h, a_v);
    }
    double mass_moment_height(double q) const override { return model_->mass_moment_height(q); }
    double load_height(double q) const override { return model_->load_height(q); }
    double eccentricity() const override { return model_->eccentricity(); }
    double flat_share() const override { return model_->flat_share(); }
    double load_height_per_eccentricity(double q) const override { return model_->load_height_per_eccentricity(q); }
    double restitution() const override { return e_; }
    double reference_angle() const override { return model_->reference_angle(); }
    double collapse_angle() const override { return model_->collapse_angle(); }
    double gravity() const override { return model_->gravity(); }
    double overburden() const override { return model_->overburden(); }
    const VsswGeometry* vssw_geometry() const override { return model_->vssw_geometry(); }
    UpperRotation upper_rotation(double q) const override { return model_->upper_rotation(q); }
    std::optional<Kinematics> kinematics() const override { return model_->kinematics(); }
    std::string name() const override { return model_->name() + fmt::format(", impact ratio {:.6g}", e_); }

private:
    std::unique_ptr<RockingModel> model_;
    double e_;
};

// The same model ending its runs at a smaller angle: a trial that needs to know only whether the wall gets there.
class WithStopAngle final : public RockingModel {
public:
    WithStopAngle(std::unique_ptr<RockingModel> model, double stop) : model_(std::move(model)), stop_(stop) {}
    ModelTerms terms(double q) const override { return model_->terms(q); }
    RockingRates rates(int side, double q, double theta_dot, double a_h, double a_v) const override {
        return model_->rates(side, q, theta_dot, a_h, a_v);
    }
    double mass_moment_height(double q) const override { return model_->mass_moment_height(q); }
    double load_height(double q) const override { return model_->load_height(q); }
    double eccentricity() const override { return model_->eccentricity(); }
    double flat_share() const override { return model_->flat_share(); }
    double load_height_per_eccentricity(double q) const override { return model_->load_height_per_eccentricity(q); }
    double restitution() const override { return model_->restitution(); }
    double reference_angle() const override { return model_->reference_angle(); }
    double collapse_angle() const override { return std::min(stop_, model_->collapse_angle()); }
    double gravity() const override { return model_->gravity(); }
    double overburden() const override { return model_->overburden(); }
    const VsswGeometry* vssw_geometry() const override { return model_->vssw_geometry(); }
    UpperRotation upper_rotation(double q) const override { return model_->upper_rotation(q); }
    std::optional<Kinematics> kinematics() const override { return model_->kinematics(); }
    std::string name() const override { return model_->name() + fmt::format(", stopped at {:.6g} rad", stop_); }

private:
    std::unique_ptr<RockingModel> model_;
    double stop_;
};

}  // namespace

std::unique_ptr<RockingModel> with_stop_angle(std::unique_ptr<RockingModel> model, double stop) {
    require(std::isfinite(stop) && stop > 0.0, "stop angle", "a positive finite angle in rad", stop);
    return std::make_unique<WithStopAngle>(std::move(model), stop);
}

std::unique_ptr<RockingModel> with_restitution(std::unique_ptr<RockingModel> model, double e) {
    require(std::isfinite(e) && e >= 0.0 && e <= 1.0, "impact ratio (restitution)", "a number in [0, 1]", e);
    return std::make_unique<WithRestitution>(std::move(model), e);
}

ImpactLaw parse_impact_law(const std::string& text) {
    if (text == "eq19") return {};
    if (text == "whole-mechanism") return {ImpactLaw::Kind::whole_mechanism, 0.0};
    std::size_t used = 0;
    double e = std::numeric_limits<double>::quiet_NaN();
    try {
        e = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(e) || e < 0.0 || e > 1.0)
        throw InputError("impact law must be 'eq19', 'whole-mechanism' or a restitution in [0, 1], got '" + text +
                         "'");
    return {ImpactLaw::Kind::ratio, e};
}

std::string to_string(const ImpactLaw& law) {
    switch (law.kind) {
        case ImpactLaw::Kind::eq19: return "eq19";
        case ImpactLaw::Kind::whole_mechanism: return "whole-mechanism";
        case ImpactLaw::Kind::ratio: break;
    }
    return fmt::format("{:.6g}", law.ratio);
}

std::unique_ptr<RockingModel> with_impact_law(std::unique_ptr<RockingModel> model, const ImpactLaw& law) {
    switch (law.kind) {
        case ImpactLaw::Kind::eq19: return model;
        case ImpactLaw::Kind::whole_mechanism:
            // A single block has one mechanism: its plastic impact is Housner's, the model's own.
            // On a squat wall the projection is negative (t/h 0.5: -0.30): contacts that can only push cannot
            // reverse the wall at its landing, so the plastic impact leaves it at rest.
            if (const VsswGeometry* w = model->vssw_geometry())
                return with_restitution(std::move(model), std::max(0.0, restitution_whole_mechanism(*w)));
            return model;
        case ImpactLaw::Kind::ratio: break;
    }
    return with_restitution(std::move(model), law.ratio);
}

}  // namespace vssw

#include "closed_forms.hpp"

#include <algorithm>
#include <cmath>

#include "error.hpp"
#include "fast_sincos.hpp"

namespace vssw {
namespace {

double sq(double x) { return x * x; }

// Sines and cosines of A1 = alpha1 - |theta1|, A2 = alpha2 - k |theta1| (Eq. 11) or of any pair of angles.
struct AnglePair {
    double sA1, cA1, sA2, cA2;
    AnglePair(double A1, double A2) : sA1(std::sin(A1)), cA1(std::cos(A1)), sA2(std::sin(A2)), cA2(std::cos(A2)) {}
    // sin A1 times the bracket (2 + tan A2 / tan A1) that recurs in Eqs. (7), (11), (23)-(25), written without the
    // division by sin A1, which is 0 at theta1 = alpha1 (where the bracket alone is infinite).
    double lever_times_sin() const { return 2.0 * sA1 + (sA2 / cA2) * cA1; }
};

// Eq. (11a) written once for any (A1, A2); at theta1 = 0 it is the inertia bracket of Eqs. (21b), (24), (25).
double mass_coefficient(const VsswGeometry& w, const AnglePair& a) {
    const double ratio = sq(w.sin_a2 * a.cA1 / (w.sin_a1 * a.cA2));
    return w.m1 + w.m2 * (sq(a.cA1) + sq(a.lever_times_sin())) + (w.I1 + ratio * w.I2) / sq(w.R1);
}

double mass_coefficient(const VsswGeometry& w, double A1, double A2) { return mass_coefficient(w, AnglePair(A1, A2)); }

}  // namespace

std::optional<double> eq2_theta2_exact(const VsswGeometry& w, double theta1) {
    const double arg = w.s * std::sin(w.alpha1 - std::abs(theta1));
    if (std::abs(arg) > 1.0) return std::nullopt;
    return std::copysign(1.0, theta1) * (std::asin(arg) - w.alpha2);
}

double eq3_theta2_linear(const VsswGeometry& w, double theta1) { return -w.k * theta1; }

double eq3_roller_drift(const VsswGeometry& w, double theta1) {
    const double q = std::abs(theta1);
    return -2.0 * w.R1 * std::sin(w.alpha1 - q) + 2.0 * w.R2 * std::sin(w.alpha2 - w.k * q);
}

std::optional<double> eq3_validity_limit(const VsswGeometry& w, double fraction) {
    constexpr double kHalfPi = 1.5707963267948966;
    const double limit = eq26_limit_rotation(w).value_or(kHalfPi);
    auto exceeded = [&](double q) { return std::abs(eq3_roller_drift(w, q)) >= fraction * 2.0 * w.b; };
    // The drift grows from zero (second order in theta1); scan for the first excess, then bisect.
    constexpr int kScan = 2000;
    double lo = 0.0;
    for (int i = 1; i <= kScan; ++i) {
        double hi = limit * i / kScan;
        if (exceeded(hi)) {
            for (int j = 0; j < 60; ++j) {
                const double mid = 0.5 * (lo + hi);
                (exceeded(mid) ? hi : lo) = mid;
            }
            return 0.5 * (lo + hi);
        }
        lo = hi;
    }
    return std::nullopt;
}

double eq4_velocity_ratio(const VsswGeometry& w, double theta1, double theta2) {
    return std::sin(w.alpha2) * std::cos(w.alpha1 - theta1) / (std::sin(w.alpha1) * std::cos(w.alpha2 + theta2));
}

double eq6_potential(const VsswGeometry& w, double theta1, double theta2) {
    return w.R1 * w.g *
           ((w.m1 + 2.0 * w.m2) * std::cos(w.alpha1 - theta1) +
            w.m2 * std::sin(w.alpha1) / std::sin(w.alpha2) * std::cos(w.alpha2 + theta2));
}

double eq7_kinetic(const VsswGeometry& w, double theta1, double theta2, double theta1_dot) {
    return 0.5 * sq(w.R1) * mass_coefficient(w, w.alpha1 - theta1, w.alpha2 + theta2) * sq(theta1_dot);
}

double eq8_overburden_work(const VsswGeometry& w, double theta1, double theta2) {
    return -w.N * w.R1 *
           (2.0 * std::sin(w.alpha1 - theta1) +
            std::tan(w.alpha2) * std::cos(w.alpha1) * (std::cos(theta2) + 2.0 * std::sin(theta2) / std::tan(w.alpha2)));
}

Eq11Evaluator::Eq11Evaluator(const VsswGeometry& w)
    : alpha1_(w.alpha1),
      k_(w.k),
      sin_a2_(w.sin_a2),
      cos_a2_(w.cos_a2),
      m2_(w.m2),
      mass0_(w.m1 + w.I1 / sq(w.R1)),
      inertia2_(w.I2 / sq(w.R1) * sq(w.sin_a2 / w.sin_a1)),
      m12_(w.m1 + 2.0 * w.m2),
      m2_cos_(w.m2 * w.cos_a1 / w.cos_a2),
      n_cos_(w.tan_a2 * w.cos_a1),
      n_sin_(2.0 * w.cos_a1),
      mass0_r_(mass0_ * sq(w.R1)),
      m2_r_(m2_ * sq(w.R1)),
      inertia2_r_(inertia2_ * sq(w.R1)),
      m12_r_(m12_ * w.R1),
      m2_cos_r_(m2_cos_ * w.R1),
      n_cos_r_(n_cos_ * w.R1),
      n_sin_r_(n_sin_ * w.R1),
      two_r_(2.0 * w.R1) {}

Eq11Coefficients Eq11Evaluator::operator()(double abs_theta1) const {
    const double q = abs_theta1;
    // sin and cos of k q serve both A2 = alpha2 - k q and C_N: two sincos calls per evaluation instead of three.
    const SinCos kq = fast_sincos(k_ * q), A1 = fast_sincos(alpha1_ - q);
    const double sA1 = A1.sin, cA1 = A1.cos;
    const double sA2 = sin_a2_ * kq.cos - cos_a2_ * kq.sin, cA2 = cos_a2_ * kq.cos + sin_a2_ * kq.sin;
    const double secA2 = 1.0 / cA2;
    const double tA2 = sA2 * secA2;
    const double sec2A2 = secA2 * secA2;
    // sin A1 times the bracket (2 + tan A2 / tan A1) of Eqs. (7), (11): no division by sin A1 (0 at theta1 = alpha1).
    const double L = 2.0 * sA1 + tA2 * cA1;
    const double upper_rotary = inertia2_ * cA1 * sec2A2;  // I2 (theta2'/theta1')^2 / (R1^2 cA1), Eq. (4)

    Eq11Coefficients c{};
    // Eq. (11a), as mass_coefficient: m1 + m2 (cA1^2 + L^2) + (I1 + (sin a2 cA1 / (sin a1 cA2))^2 I2) / R1^2.
    c.C_A = mass0_ + m2_ * (cA1 * cA1 + L * L) + upper_rotary * cA1;
    // The m2 term of Eq. (11b), m2 sA1 {cA1 [1 - lever^2] + sA1 lever (-k cot A1 sec^2 A2 + csc^2 A1 tan A2)},
    // rearranged with L = sA1 lever so that nothing divides by sA1: m2 [sA1 cA1 - L (2 cA1 - tA2 sA1) - k cA1 sec^2 A2 L].
    c.C_S = upper_rotary * (sA1 - cA1 * k_ * tA2) +
            m2_ * (sA1 * cA1 - L * (2.0 * cA1 - tA2 * sA1) - k_ * cA1 * sec2A2 * L);
    c.C_H = m12_ * cA1 - m2_cos_ * cA2;
    c.C_V = m12_ * sA1 + m2_cos_ * sA2;
    c.C_N = 2.0 * sA1 + n_cos_ * kq.cos - n_sin_ * kq.sin;
    return c;
}

Eq11Coefficients eq11_coefficients(const VsswGeometry& w, double abs_theta1) { return Eq11Evaluator(w)(abs_theta1); }

double eq12_threshold(const VsswGeometry& w, double a_v, int side) {
    require(side == 1 || side == -1, "side of tipping", "+1 or -1", side);
    const double g_eff = w.g + a_v;
    // eps = 0: (1 + 0) k = k exactly, so a centred N gives Eq. (12)'s number bit for bit.
    if (w.corner_radius > 0.0) {
        // Eq. (12r): the pivots at b - r; N's eccentric lever k e is measured from the hinge and keeps its size.
        const double flat = 1.0 - w.corner_radius;  // (b - r) / b
        const double lever_N = (2.0 + w.k) * flat + w.k * side * w.eccentricity;
        return std::tan(w.alpha1) * (g_eff * (w.m1 + w.m2 * (2.0 + w.k)) * flat + w.N * lever_N) / (w.m1 + w.m2);
    }
    const double lever_N = 2.0 + w.k * (1.0 + side * w.eccentricity);
    return std::tan(w.alpha1) * (g_eff * (w.m1 + w.m2 * (2.0 + w.k)) + w.N * lever_N) / (w.m1 + w.m2);
}

double eq12_threshold(const VsswGeometry& w, double a_v) {
    return eq12_threshold(w, a_v, w.eccentricity > 0.0 ? -1 : 1);  // side eps <= 0: the shorter lever of N
}

double eq13_threshold_no_overburden(const VsswGeometry& w, double a_v) {
    return 2.0 * (w.g + a_v) * std::tan(w.alpha1);
}

double eq14_threshold_over_g(double b, double h, double h1, double xi, double eccentricity) {
    return b * xi * (1.0 - std::abs(eccentricity)) / (h - h1) + 2.0 * b * (1.0 + xi) / h1;
}

double eq15_optimal_hinge_ratio(double xi, double eccentricity, double corner_radius) {
    if (corner_radius == 0.0 || eccentricity == 0.0)  // Eq. (15e), and (15) at eps = 0: as printed, to the bit
        return 1.0 / (1.0 + std::sqrt(xi * (1.0 - std::abs(eccentricity)) / (2.0 * (1.0 + xi))));
    const double flat = 1.0 - corner_radius;  // (b - r) / b
    return 1.0 / (1.0 + std::sqrt(xi * std::max(0.0, flat - std::abs(eccentricity)) / (2.0 * flat * (1.0 + xi))));
}

double eq16_cracking_hinge_ratio(double xi, double t) {
    return 1.0 + (xi + t - std::sqrt((2.0 + t + 2.0 * xi) * (t + xi))) / (2.0 + xi);
}

double eq17_parapet_threshold(const ParapetGeometry& p, int side) {
    require(side == 1 || side == -1, "side of tipping", "+1 or -1", side);
    if (p.corner_radius > 0.0) {  // Eq. (17r): the pivot at b - r, N's point still e from the centre
        const double flat = 1.0 - p.corner_radius;
        return p.b / p.h * p.g * (flat * (1.0 + p.xi) - p.xi * side * p.eccentricity);
    }
    return p.b / p.h * p.g * (1.0 + p.xi * (1.0 - side * p.eccentricity));  // eps = 0: Eq. (17) bit for bit
}

double eq17_parapet_threshold(const ParapetGeometry& p) {
    return eq17_parapet_threshold(p, p.eccentricity < 0.0 ? -1 : 1);  // side eps >= 0: N nearer the pivot
}

double eq18_threshold_ratio(double xi) {
    return 3.0 + 2.0 * std::sqrt(2.0 * xi / (1.0 + xi)) - 1.0 / (1.0 + xi);
}

constexpr double kEq19I2Sign = -1.0;  // Eq. (19): m1 R1^2 + I1 - I2 k

// VSSW_MUTANT_WHOLE_MECHANISM_SIGN is defined only for the test program vssw_mutant_impact (tests/CMakeLists.txt): a
// core whose whole-mechanism impact, the reference's (the set mechanism), has k of the wrong sign, which `vssw check
// --bounds bounds/ci.toml` must catch. Never defined in vssw itself.
#ifdef VSSW_MUTANT_WHOLE_MECHANISM_SIGN
constexpr double kWholeMechanismKSign = -1.0;
#else
constexpr double kWholeMechanismKSign = +1.0;  // the upper block's lever (2 + k)
#endif

double eq19_restitution(const VsswGeometry& w) {
    const double a1 = w.alpha1, a2 = w.alpha2;
    const double R1sq = sq(w.R1);
    const double common = w.m1 * R1sq + w.I1 + kEq19I2Sign * w.I2 * w.k;
    const double num = common - 2.0 * w.m1 * R1sq * sq(std::sin(a1)) +
                       w.m2 * R1sq *
                           (2.0 + std::sin(a1) * std::cos(a1) / std::tan(a2) - sq(std::sin(a1)) * (4.0 + w.k));
    const double den = common + w.m2 * R1sq * (2.0 + std::sin(a1) * std::cos(a1) * (1.0 / std::tan(a2) + std::tan(a2)));
    return num / den;
}

double restitution_whole_mechanism(const VsswGeometry& w) {
    const double m0 = sq(w.R1) * mass_coefficient(w, w.alpha1, w.alpha2);
    return 1.0 - 2.0 * sq(w.b) * (w.m1 + w.m2 * sq(2.0 + kWholeMechanismKSign * w.k)) / m0;
}

double eq21_A(const VsswGeometry& w) {
    const double cr = std::cos(w.alpha1) / std::cos(w.alpha2);
    return w.alpha1 * (w.m1 + w.m2 * (2.0 + cr * w.alpha2 / w.alpha1)) / (w.m1 + w.m2 * (2.0 + cr * w.k));
}

double eq21_P(const VsswGeometry& w) {
    const double cr = std::cos(w.alpha1) / std::cos(w.alpha2);
    return std::sqrt(w.g * (w.m1 + w.m2 * (2.0 + cr * w.k)) / (w.R1 * mass_coefficient(w, w.alpha1, w.alpha2)));
}

double eq22_period(const VsswGeometry& w, double theta10) {
    const double A = eq21_A(w);
    require(std::isfinite(theta10) && theta10 > 0.0 && theta10 < A, "initial rotation for Eq. (22)",
            "in (0, A) rad", theta10);
    return 4.0 / eq21_P(w) * std::acosh(1.0 / (1.0 - theta10 / A));
}

double eq23_restitution_from_amplitudes(const VsswGeometry& w, double peak_before, double peak_after) {
    auto energy_ratio = [&](double peak) {
        const double q = std::abs(peak);
        const double A1 = w.alpha1 - q, A2 = w.alpha2 - w.k * q;
        const double potential = (w.m1 + 2.0 * w.m2) * (std::cos(A1) - std::cos(w.alpha1)) +
                                 w.m2 * std::sin(w.alpha1) / std::sin(w.alpha2) * (std::cos(A2) - std::cos(w.alpha2));
        return potential / mass_coefficient(w, A1, A2);
    };
    return std::sqrt(energy_ratio(peak_after) / energy_ratio(peak_before));
}

double eq24_reference_velocity(const VsswGeometry& w) {
    const double n = w.N / w.g;  // the printed 2N/W, with masses per unit depth (see header)
    const double num = 2.0 * w.g *
                       ((w.m1 + 2.0 * w.m2 + 2.0 * n) * (1.0 - std::cos(w.alpha1)) +
                        (w.m2 + 2.0 * n) * std::sin(w.alpha1) / std::sin(w.alpha2) * (1.0 - std::cos(w.alpha2)));
    return std::sqrt(num / (w.R1 * mass_coefficient(w, w.alpha1, w.alpha2)));
}

double eq25_dissipated_energy(const VsswGeometry& w, double sum_sq_velocity_before) {
    const double e = eq19_restitution(w);
    return 0.5 * sq(w.R1) * mass_coefficient(w, w.alpha1, w.alpha2) * (1.0 - e * e) * sum_sq_velocity_before;
}

std::optional<double> eq26_limit_rotation(const VsswGeometry& w) {
    const double ratio = std::sin(w.alpha1) / std::sin(w.alpha2);
    if (ratio >= 1.0) return std::nullopt;
    return std::asin(ratio) + w.alpha1;
}

double housner_restitution(double alpha) { return 1.0 - 1.5 * sq(std::sin(alpha)); }

double housner_p(double R, double g) { return std::sqrt(3.0 * g / (4.0 * R)); }

double housner_period(double alpha, double R, double g, double theta0) {
    require(std::isfinite(theta0) && theta0 > 0.0 && theta0 < alpha, "initial rotation for Housner's period",
            "in (0, alpha) rad", theta0);
    return 4.0 / housner_p(R, g) * std::acosh(1.0 / (1.0 - theta0 / alpha));
}

}  // namespace vssw

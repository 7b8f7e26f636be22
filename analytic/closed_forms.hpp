#pragma once
// Closed forms of Sorrentino, Masiani & Griffith (2008), one function each, named by equation number, and Housner's
// (1963) results for the parapet wall. theta1 >= 0 unless said otherwise: the mechanism is mirrored for theta1 < 0.
//
// Sign convention for vertical ground acceleration: this code takes a_v positive UPWARD (as records are), so the
// paper's [g - y''(t)] (its y'' points down, Fig. 1c) is written g + a_v here.
#include <optional>

#include "fast_sincos.hpp"
#include "geometry.hpp"

namespace vssw {

// Eq. (2): exact rotation of the upper body theta2(theta1) imposed by the top roller; valid for |theta1| up to the
// roller limit of Eq. (26) (std::nullopt past it, where the arcsine has no solution).
std::optional<double> eq2_theta2_exact(const VsswGeometry& w, double theta1);
// Eq. (3): the paper's linearisation theta2 = -(tan a2 / tan a1) theta1.
double eq3_theta2_linear(const VsswGeometry& w, double theta1);
// Horizontal distance of the pivot-side top corner from the roller line when theta2 follows Eq. (3) [m]: zero for
// Eq. (2) by construction, so it measures how far the paper's linearisation strays from the top restraint.
double eq3_roller_drift(const VsswGeometry& w, double theta1);
// Rotation |theta1| (rad) at which that drift first reaches `fraction` of the wall's thickness 2b, found by
// a scan and bisection up to Eq. (26)'s limit rotation (pi/2 when it has none); std::nullopt if it never does.
std::optional<double> eq3_validity_limit(const VsswGeometry& w, double fraction);
// Eq. (4): theta2_dot / theta1_dot as a function of theta1 and theta2 (a magnitude; theta2 has the sign opposite to
// theta1).
double eq4_velocity_ratio(const VsswGeometry& w, double theta1, double theta2);

// Eq. (6): potential energy of the bodies' weights for theta1 >= 0 at the given theta2 [J/m].
double eq6_potential(const VsswGeometry& w, double theta1, double theta2);
// Eq. (7): kinetic energy [J/m] at theta1 >= 0, theta2, theta1_dot.
double eq7_kinetic(const VsswGeometry& w, double theta1, double theta2, double theta1_dot);
// Eq. (8): virtual work of N per unit virtual rotation, delta Gamma_N / delta theta1 [N m/m], theta1 >= 0.
double eq8_overburden_work(const VsswGeometry& w, double theta1, double theta2);

// Eq. (11a-e): coefficients of the equation of motion (10) at |theta1|, with A1, A2 as printed (Eq. 3 inside).
struct Eq11Coefficients {
    double C_A, C_S, C_H, C_V, C_N;
};
Eq11Coefficients eq11_coefficients(const VsswGeometry& w, double abs_theta1);

// The same coefficients for one wall with its constant factors (masses over R1^2, the ratios of the constant
// angles' functions) worked out once and one division per evaluation; scaled() is the form the integrator's stages
// evaluate (no division at all). eq11_coefficients(w, q) is Eq11Evaluator(w)(q).
class Eq11Evaluator {
public:
    explicit Eq11Evaluator(const VsswGeometry& w);
    Eq11Coefficients operator()(double abs_theta1) const;
    // The terms of Eq. (10) with the wall's R1 in them (ModelTerms' M, C, X, Y, L), M and C multiplied through by
    // cos^3 A2, the coefficients' common denominator, and the levers X, Y, L as they are (they have none) with the
    // factor beside them: no division at all, what the equation of motion needs at an integrator stage.
    struct Scaled {
        double M, C;     // R1^2 C_A and R1^2 C_S, times cos^3 A2
        double X, Y, L;  // R1 C_H, R1 C_V and R1 C_N as they are (multiplied by cos3 in Eq. 10)
    double Le;       // k cos(k q): the lever of N's eccentricity per metre (model.hpp's L_e), as L
        double cos3;     // cos^3 A2
    };
    Scaled scaled(double abs_theta1) const;

private:
    double alpha1_, k_, sin_a2_, cos_a2_, m2_;
    double mass0_;     // m1 + I1 / R1^2
    double inertia2_;  // I2 / R1^2 (sin alpha2 / sin alpha1)^2: the upper body's rotary inertia term's factor
    double m12_;       // m1 + 2 m2
    double m2_cos_;    // m2 cos alpha1 / cos alpha2
    double n_cos_, n_sin_;  // C_N's factors of cos(k q) and sin(k q): tan alpha2 cos alpha1 and 2 cos alpha1
    // The same factors times R1^2 (mass terms) or R1 (levers), for scaled(): no multiplication by R1 left on a stage's
    // chain of dependent operations.
    double mass0_r_, m2_r_, inertia2_r_, m12_r_, m2_cos_r_, n_cos_r_, n_sin_r_, two_r_;
};

// Inline: the integrator's stages call it through PaperVssw::rates, which waits on its result (returned through
// memory when it was out of line).
inline Eq11Evaluator::Scaled Eq11Evaluator::scaled(double abs_theta1) const {
    const double q = abs_theta1;
    const SinCos kq = fast_sincos(k_ * q), A1 = fast_sincos(alpha1_ - q);
    const double sA1 = A1.sin, cA1 = A1.cos;
    const double s = sin_a2_ * kq.cos - cos_a2_ * kq.sin, c = cos_a2_ * kq.cos + sin_a2_ * kq.sin;  // sin, cos A2
    const double c2 = c * c, c3 = c2 * c;
    const double Lc = 2.0 * sA1 * c + s * cA1;  // cos A2 times operator()'s L
    const double ur_c2 = inertia2_r_ * cA1;     // R1^2 cos^2 A2 times operator()'s upper_rotary
    Scaled r{};
    const double cA1_2 = cA1 * cA1;
    r.M = c3 * (mass0_r_ + m2_r_ * cA1_2) + c * (m2_r_ * (Lc * Lc) + inertia2_r_ * cA1_2);
    r.C = ur_c2 * (sA1 * c - k_ * cA1 * s) +
          m2_r_ * (sA1 * cA1 * c3 - Lc * c * (2.0 * cA1 * c - s * sA1) - k_ * cA1 * Lc);
    r.X = m12_r_ * cA1 - m2_cos_r_ * c;
    r.Y = m12_r_ * sA1 + m2_cos_r_ * s;
    r.L = two_r_ * sA1 + n_cos_r_ * kq.cos - n_sin_r_ * kq.sin;
    r.Le = k_ * kq.cos;
    r.cos3 = c3;
    return r;
}

// Eq. (12): threshold horizontal ground acceleration [m/s^2] under a vertical ground acceleration a_v (up positive).
// Derived, as the paper says, from Eq. (10) at rest: N is a force and does not scale with a_v. As printed, N/g sits
// inside the bracket multiplied by [g - y''], which contradicts Eq. (10) when both N and y'' are non-zero; the two
// agree whenever a_v = 0 or N = 0.
//
// With N at the eccentricity e = eps b (geometry.hpp) the threshold depends on the direction of tipping: toward the
// side theta1 > 0 (side +1, under a_h < 0) N's lever at rest is b (2 + k) + e k, the other way b (2 + k) - e k
// (docs/model/analytic-core.md, "The overburden's position"):
//   a_c(side) = tan(alpha1) [(g + a_v)(m1 + m2 (2 + k)) + N (2 + k (1 + side eps))] / (m1 + m2).      (12e)
// Without a side, the lower of the two (the side with side eps <= 0); eps = 0 gives Eq. (12) itself.
// With the corners rounded to r = rho b (geometry.hpp) the base pivot and the hinge sit at b - r from the centreline,
// the roller still at the top corner (docs/model/analytic-core.md, "Rounded corners"):
//   a_c(side) = tan(alpha1) [(1 - rho)((g + a_v)(m1 + m2 (2 + k)) + N (2 + k)) + N k side eps] / (m1 + m2).   (12r)
// rho = 0 is Eq. (12e) bit for bit.
double eq12_threshold(const VsswGeometry& w, double a_v = 0.0);
double eq12_threshold(const VsswGeometry& w, double a_v, int side);
// Eq. (13): the same for homogeneous bodies without N: 2 (g + a_v) tan(alpha1) [m/s^2].
double eq13_threshold_no_overburden(const VsswGeometry& w, double a_v = 0.0);
// Eq. (14): |x''_t / g| from b, h, h1 and xi (a_v = 0): the static collapse load multiplier. With N at the
// eccentricity e/b = eps, Eq. (12e)'s lower side: N's extra lever k s eps tan(alpha1) is xi s eps b / (h - h1), so
//   |x''_t / g| = b xi (1 - |eps|) / (h - h1) + 2 b (1 + xi) / h1                                       (14e)
double eq14_threshold_over_g(double b, double h, double h1, double xi, double eccentricity = 0.0);
// Eq. (15): the hinge ratio h1/h that minimises Eq. (14); with N at e/b = eps, the one that minimises Eq. (14e):
//   h1 / h = 1 / (1 + sqrt(xi (1 - |eps|) / (2 (1 + xi))))                                              (15e)
// N at a corner (|eps| = 1) puts it at the very top, as xi = 0 does: its lever no longer grows as the hinge rises.
// With the corners rounded to r = rho b as well, the one that minimises Eq. (12r)'s lower side:
//   h1 / h = 1 / (1 + sqrt(xi max(0, 1 - rho - |eps|) / (2 (1 - rho)(1 + xi))))                         (15r)
// (docs/model/analytic-core.md, "Rounded corners"); rho = 0 is Eq. (15e) bit for bit, and so is eps = 0 whatever rho
// (the rounding then scales the whole threshold by 1 - rho). N at or past the flat's end (|eps| >= 1 - rho): the top.
double eq15_optimal_hinge_ratio(double xi, double eccentricity = 0.0, double corner_radius = 0.0);
// Eq. (16): the hinge ratio h1/h of first cracking, with t = f_mt / (W / 2b) the normalised mortar tensile strength.
double eq16_cracking_hinge_ratio(double xi, double t);
// Eq. (17): threshold of the parapet wall [m/s^2].
// With N at e = eps b, toward side +1 (the pivot's corner at eps = +1) its lever at rest is b - e:
//   a_c(side) = (b / h) g [1 + xi (1 - side eps)]                                                      (17e)
// so at eps = side, N over the pivot, it is Housner's g b / h whatever N. Without a side, the lower of the two.
// With the base corners rounded to r = rho b, the pivot at b - r:
//   a_c(side) = (b / h) g [(1 - rho)(1 + xi) - xi side eps]                                          (17r)
double eq17_parapet_threshold(const ParapetGeometry& p);
double eq17_parapet_threshold(const ParapetGeometry& p, int side);
// Eq. (18): VSSW/PW threshold ratio with the hinge at Eq. (15).
double eq18_threshold_ratio(double xi);
// Eq. (19): coefficient of restitution of the VSSW (angular momentum about the new base pivot).
double eq19_restitution(const VsswGeometry& w);
// Not in the paper: the fully plastic impact in which every constraint of the new mechanism acts at once (new base
// pivot, closing hinge and the roller on the new side), as a rigid-body engine resolves it: the projection of the
// pre-impact velocities onto the post-impact mechanism in the kinetic-energy metric,
//   e = 1 - 2 b^2 [m1 + m2 (2 + k)^2] / M(0),  M(0) = R1^2 C_A(0).
// Eq. (19) is the same impact with the roller's impulse left out; for a single block both are Housner's e.
double restitution_whole_mechanism(const VsswGeometry& w);

// Eq. (21a-b): A [rad] and P [1/s] of the linearised free vibration, Eq. (20), N = 0.
double eq21_A(const VsswGeometry& w);
double eq21_P(const VsswGeometry& w);
// Eq. (22): period of free vibration [s] of Eq. (20) released from rest at theta10 (0 < theta10 < A).
double eq22_period(const VsswGeometry& w, double theta10);
// Eq. (23): restitution from two successive peak amplitudes |theta1,max| before and after an impact, as printed
// (with the square root that turns the energy ratio into a velocity ratio). It evaluates C_A at the peaks although
// the velocities it compares are at theta1 = 0, so it is off by O(difference of the peaks): ~3e-4 for a slender
// wall at theta0 = 0.8 alpha1. restitution_from_peaks() in model.hpp is the consistent estimate.
double eq23_restitution_from_amplitudes(const VsswGeometry& w, double peak_before, double peak_after);
// Eq. (24): reference angular velocity [rad/s]. The printed "2N/W" beside masses is read as 2N/g (masses per unit
// depth); with N = 0 it equals sqrt(2 V_r / M(0)) exactly.
double eq24_reference_velocity(const VsswGeometry& w);
// Eq. (25): energy dissipated by impacts [J/m] given sum_i (theta1_dot_i^-)^2. The printed prefactor R1 is read as
// R1^2 (the printed one is not an energy).
double eq25_dissipated_energy(const VsswGeometry& w, double sum_sq_velocity_before);
// Eq. (26): roller limit rotation; exists only when sin(alpha1) < sin(alpha2), i.e. h1 > h2.
std::optional<double> eq26_limit_rotation(const VsswGeometry& w);

// Housner (1963): e = 1 - 3/2 sin^2(alpha), p = sqrt(3 g / (4 R)) for a rectangular block.
double housner_restitution(double alpha);
double housner_p(double R, double g);
// Housner's linearised quarter period, (1/p) arccosh(1 / (1 - theta0/alpha)), times 4.
double housner_period(double alpha, double R, double g, double theta0);

}  // namespace vssw

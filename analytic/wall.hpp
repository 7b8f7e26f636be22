#pragma once
// Wall descriptions (Sect. 2 and Table 1 of Sorrentino, Masiani & Griffith 2008).
//
// Half dimensions throughout, as in the paper: b is the half-thickness, h1 and h2 the half-heights of the lower and
// upper bodies, h = h1 + h2. Bodies are homogeneous rectangles; masses and inertias are per unit depth of wall
// (kg/m, kg m): m_i = rho * 2b * 2h_i, I_G,i = m_i R_i^2 / 3. The overburden N = xi * W is a massless force at the
// centre of the top face; W is the wall's weight per unit depth.
#include <string>

namespace vssw {

constexpr double kDefaultDensity = 1800.0;  // kg/m^3, brick masonry
constexpr double kDefaultGravity = 9.81;    // m/s^2

// Ranges the constructors below accept (InputError naming the value and the range otherwise). Each holds a real
// masonry wall or a lab specimen with a wide margin and keeps every derived quantity finite and well away from
// under- and overflow: masses ~ density * length^2 <= 1e5 * 1e6 = 1e11 kg/m, inertias ~ mass * length^2 <= 1e17,
// weights and N <= 1e3 * 1e3 * 1e11 = 1e17 N/m, angles atan(b/h) >= atan(1e-3 / 1e3) = 1e-6 rad (sin^2 = 1e-12,
// far above double's rounding); the integrator's time scale sqrt(R/g) stays in 1e-3 to 3e2 s.
constexpr double kMinLength = 1e-3;       // [m] full height or thickness: below any brick (a 1 mm lab block still fits)
constexpr double kMaxLength = 1e3;        // [m] above any wall (the tallest masonry structures are ~100 m)
constexpr double kMinDensity = 1.0;       // [kg/m^3] below any solid (foam ~20); masonry is 1500-2400
constexpr double kMaxDensity = 1e5;       // [kg/m^3] above any solid (osmium 22,600)
constexpr double kMinGravity = 1e-2;      // [m/s^2] a small asteroid's; the Moon's is 1.62
constexpr double kMaxGravity = 1e3;       // [m/s^2] a centrifuge test at 100 g
constexpr double kMaxOverburdenRatio = 1e3;  // N/W: 1000 walls' weight on the top, far past any floor load (xi ~ 0-2)

// Vertical spanning strip wall: two rigid blocks, base on the ground, top held by a roller (Fig. 1).
struct VsswGeometry {
    double b, h1, h2;        // half-thickness, half-heights of lower and upper body [m]
    double density, xi, g;   // [kg/m^3], N/W [-], gravity [m/s^2]
    // Derived once on construction (read-only afterwards).
    double alpha1, alpha2;   // atan(b/h_i) [rad]
    double R1, R2;           // half-diagonals [m]
    double m1, m2;           // masses per unit depth [kg/m]
    double I1, I2;           // centroidal polar moments of inertia per unit depth [kg m]
    double W, N;             // weight and overburden per unit depth [N/m]
    double k;                // tan(alpha2)/tan(alpha1) = h1/h2, slope of Eq. (3)
    double s;                // sin(alpha2)/sin(alpha1) = R1/R2, factor of Eq. (2)
    // Trigonometric functions of the constant angles, which the equation of motion uses at every evaluation.
    double sin_a1, cos_a1, tan_a1, sin_a2, cos_a2, tan_a2;

    double h() const { return h1 + h2; }
    double hinge_ratio() const { return h1 / h(); }
};

// Single rocking block (parapet wall, Housner 1963).
struct ParapetGeometry {
    double b, h;             // half-thickness, half-height [m]
    double density, xi, g;
    double alpha, R;         // atan(b/h), half-diagonal
    double m, I_G, I_O;      // mass, centroidal and corner polar inertia per unit depth
    double W, N;
};

// From what an engineer measures: full height 2h, full thickness 2b, hinge ratio h1/h in (0, 1). Also refused: a
// wall whose Eq. (19) restitution is <= 0 (it would not rock onto its other corner: the message gives the hinge
// ratios that rock at its thickness/height), and, for make_parapet, a block whose Housner restitution is <= 0
// (thickness/height >= sqrt(2)).
VsswGeometry make_vssw(double height, double thickness, double hinge_ratio, double xi = 0.0,
                       double density = kDefaultDensity, double g = kDefaultGravity);
// From the paper's parameter set (alpha1, alpha2, R1).
VsswGeometry make_vssw_from_angles(double alpha1, double alpha2, double R1, double xi = 0.0,
                                   double density = kDefaultDensity, double g = kDefaultGravity);
ParapetGeometry make_parapet(double height, double thickness, double xi = 0.0, double density = kDefaultDensity,
                             double g = kDefaultGravity);

}  // namespace vssw

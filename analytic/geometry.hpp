#pragma once
// Wall descriptions (Sect. 2 and Table 1 of Sorrentino, Masiani & Griffith 2008): what the closed forms
// (closed_forms.hpp) and the models read. Made by wall.hpp's constructors, which check them (and use the closed forms
// for that: this header keeps the closed forms from depending on the constructors).
//
// Half dimensions throughout, as in the paper: b is the half-thickness, h1 and h2 the half-heights of the lower and
// upper bodies, h = h1 + h2. Bodies are homogeneous rectangles; masses and inertias are per unit depth of wall
// (kg/m, kg m): m_i = rho * 2b * 2h_i, I_G,i = m_i R_i^2 / 3. The overburden N = xi * W is a massless vertical force
// on the top face of the upper body (the only body of a parapet), at the eccentricity e = eccentricity * b from its
// centre: 0 the centre (the paper's assumption), +1 the top corner on the side the wall tips toward when theta1 > 0,
// -1 the other (docs/model/analytic-core.md, "The overburden's position"). W is the wall's weight per unit depth.

namespace vssw {

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
    double eccentricity = 0.0;  // e/b of N on the upper body's top face, in [-1, 1] (with_eccentricity, wall.hpp)
    double corner_radius = 0.0;  // r/b of the rounded rocking corners, in [0, kMaxCornerRadius] (with_corner_radius)

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
    double eccentricity = 0.0;  // e/b of N on the top face, in [-1, 1] (with_eccentricity, wall.hpp)
    double corner_radius = 0.0;  // r/b of the rounded base corners, in [0, kMaxCornerRadius] (with_corner_radius)
};

}  // namespace vssw

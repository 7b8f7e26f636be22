#pragma once
// Walls from what an engineer measures, each checked against the physical ranges below and refused (InputError) when
// it would not rock: the descriptions themselves are in geometry.hpp (Sect. 2 and Table 1 of Sorrentino, Masiani &
// Griffith 2008).
#include "geometry.hpp"

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

// From what an engineer measures: full height 2h, full thickness 2b, hinge ratio h1/h in (0, 1). Also refused: a
// wall whose Eq. (19) restitution is <= 0 (it would not rock onto its other corner: the message gives the hinge
// ratios that rock at its thickness/height), and, for make_parapet, a block whose Housner restitution is <= 0
// (thickness/height >= sqrt(2)).
VsswGeometry make_vssw(double height, double thickness, double hinge_ratio, double xi = 0.0,
                       double density = kDefaultDensity, double g = kDefaultGravity);
// From the paper's parameter set (alpha1, alpha2, R1).
VsswGeometry make_vssw_from_angles(double alpha1, double alpha2, double R1, double xi = 0.0,
                                   double density = kDefaultDensity, double g = kDefaultGravity);
// The same wall with N at the eccentricity e/b = ratio of the (upper) body's top face (geometry.hpp); InputError unless
// the ratio is a number in [-1, 1] (the face's corners), and, on a wall with rounded corners, when N acts so far
// outside the rounded pivot's flat that the wall cannot stand (Eq. 12r / 17r <= 0; with_corner_radius checks the same).
VsswGeometry with_eccentricity(VsswGeometry w, double ratio);
ParapetGeometry with_eccentricity(ParapetGeometry p, double ratio);
// The largest corner radius r/b a wall takes: half the half-thickness. Past it the flat part of a face (2b - 2r) is
// shorter than the arcs; at r = b the base is a half disc and the threshold of Eq. (12r) is 0.
constexpr double kMaxCornerRadius = 0.5;
// The same wall with the blocks' corners rounded to the radius r = ratio * b (docs/model/analytic-core.md, "Rounded
// corners"): the base pivot and the hinge move inward to b - r, the threshold follows (Eq. 12r, 17r). InputError
// unless the ratio is a number in [0, kMaxCornerRadius], and when an eccentric N then acts outside the pivot's flat
// with a moment that outweighs the weights' (the threshold <= 0: the wall cannot stand), naming xi, e/b and r/b.
VsswGeometry with_corner_radius(VsswGeometry w, double ratio);
ParapetGeometry with_corner_radius(ParapetGeometry p, double ratio);
ParapetGeometry make_parapet(double height, double thickness, double xi = 0.0, double density = kDefaultDensity,
                             double g = kDefaultGravity);

}  // namespace vssw

#include "wall.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "closed_forms.hpp"
#include "error.hpp"

namespace vssw {
namespace {

// Physical ranges of the inputs (see wall.hpp for the values and why they hold every derived quantity finite).
struct Range {
    double lo, hi;
    const char* unit;
};

// The rules below are formatted only when a check fails: formatting them costs more than the check, which a study
// makes for every case it builds.
void require_in(double v, const char* what, const Range& r) {
    if (!(std::isfinite(v) && v >= r.lo && v <= r.hi))
        require(false, what, fmt::format("a number from {:g} to {:g}{}", r.lo, r.hi, r.unit), v);
}

void check_common(double xi, double density, double g) {
    if (!(std::isfinite(xi) && xi >= 0.0 && xi <= kMaxOverburdenRatio))
        require(false, "xi (N/W)", fmt::format("a number from 0 to {:g}", kMaxOverburdenRatio), xi);
    require_in(density, "density", {kMinDensity, kMaxDensity, " kg/m^3"});
    require_in(g, "gravity g", {kMinGravity, kMaxGravity, " m/s^2"});
}

void check_dimensions(double height, double thickness) {
    require_in(height, "height", {kMinLength, kMaxLength, " m"});
    require_in(thickness, "thickness", {kMinLength, kMaxLength, " m"});
}

// A restitution this close to 0 is 0 up to the rounding of Eq. (19)'s terms (t/h 0.5 at h1/h 0.5 gives 1.7e-16
// where the exact value is 0): such a wall is refused with those below 0.
constexpr double kRestitutionRoundoff = 1e-12;

bool rocks(double restitution) { return restitution > kRestitutionRoundoff; }

// Eq. (19) at full dimensions, for the refusal below.
double vssw_restitution(double height, double thickness, double hinge_ratio);

// The hinge ratios h1/h in (0, 1) at which Eq. (19) gives e > 0 for this thickness/height form an interval
// (r_min, 1): e rises monotonically with h1/h at fixed t/h (checked on a grid of t/h and h1/h in test_wall.cpp),
// from -1 as h1/h -> 0. Returns
// r_min by bisection, or nullopt when no hinge ratio gives e > 0 (e at h1/h -> 1 is already <= 0).
std::optional<double> lowest_rocking_hinge(double height, double thickness) {
    constexpr double kTopEnd = 1.0 - 1e-9;  // h1/h just below 1: the upper body vanishing
    if (!rocks(vssw_restitution(height, thickness, kTopEnd))) return std::nullopt;
    double lo = 0.0, hi = kTopEnd;  // e(lo) <= 0 (e -> -1 as h1 -> 0), e(hi) > 0
    constexpr int kBisections = 60;  // to double precision on (0, 1)
    for (int i = 0; i < kBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        (rocks(vssw_restitution(height, thickness, mid)) ? hi : lo) = mid;
    }
    return hi;
}

VsswGeometry vssw_from_half_dims(double b, double h1, double h2, double xi, double density, double g) {
    VsswGeometry w{};
    w.b = b;
    w.h1 = h1;
    w.h2 = h2;
    w.density = density;
    w.xi = xi;
    w.g = g;
    w.alpha1 = std::atan(b / h1);
    w.alpha2 = std::atan(b / h2);
    w.R1 = std::hypot(b, h1);
    w.R2 = std::hypot(b, h2);
    w.m1 = density * 2.0 * b * 2.0 * h1;
    w.m2 = density * 2.0 * b * 2.0 * h2;
    w.I1 = w.m1 * w.R1 * w.R1 / 3.0;
    w.I2 = w.m2 * w.R2 * w.R2 / 3.0;
    w.W = (w.m1 + w.m2) * g;
    w.N = xi * w.W;
    w.k = h1 / h2;
    w.s = w.R1 / w.R2;
    w.sin_a1 = b / w.R1;
    w.cos_a1 = h1 / w.R1;
    w.tan_a1 = b / h1;
    w.sin_a2 = b / w.R2;
    w.cos_a2 = h2 / w.R2;
    w.tan_a2 = b / h2;
    return w;
}

double vssw_restitution(double height, double thickness, double hinge_ratio) {
    const double h = height / 2.0;
    return eq19_restitution(vssw_from_half_dims(thickness / 2.0, hinge_ratio * h, (1.0 - hinge_ratio) * h, 0.0,
                                                kDefaultDensity, kDefaultGravity));
}

// The rocking model's impact law must give a positive restitution: with e <= 0 the wall does not rock onto its
// other corner after an impact (e < 0 would send it back the way it came, e = 0 stops it dead), so the model does not
// describe it (e.g. height 2, thickness 4, h1/h 0.7: Eq. 19 gives -0.82; h1/h 1e-12: -1).
void require_rocking_vssw(const VsswGeometry& w) {
    if (rocks(eq19_restitution(w))) return;
    const double height = 2.0 * w.h(), thickness = 2.0 * w.b;
    const std::optional<double> lowest = lowest_rocking_hinge(height, thickness);
    const std::string hinges =
        lowest ? fmt::format("at thickness/height {:g} it holds for h1/h from {:.4g} to 1", thickness / height, *lowest)
               : fmt::format("at thickness/height {:g} it holds for no hinge ratio", thickness / height);
    throw InputError(fmt::format(
        "this VSSW does not rock: thickness {:g} m, height {:g} m, hinge h1/h {:g} give an Eq. (19) restitution of "
        "{:.3g}, and the rocking model's impact law needs one > {:g} (the wall must rock onto its other corner); {}",
        thickness, height, w.hinge_ratio(), eq19_restitution(w), kRestitutionRoundoff, hinges));
}

}  // namespace

VsswGeometry make_vssw(double height, double thickness, double hinge_ratio, double xi, double density, double g) {
    check_dimensions(height, thickness);
    require(std::isfinite(hinge_ratio) && hinge_ratio > 0.0 && hinge_ratio < 1.0, "hinge ratio h1/h",
            "strictly between 0 and 1", hinge_ratio);
    check_common(xi, density, g);
    const double h = height / 2.0;
    const VsswGeometry w =
        vssw_from_half_dims(thickness / 2.0, hinge_ratio * h, (1.0 - hinge_ratio) * h, xi, density, g);
    require_rocking_vssw(w);
    return w;
}

VsswGeometry make_vssw_from_angles(double alpha1, double alpha2, double R1, double xi, double density, double g) {
    constexpr double kRightAngle = 1.5707963267948966;
    require(std::isfinite(alpha1) && alpha1 > 0.0 && alpha1 < kRightAngle, "alpha1", "in (0, pi/2) rad", alpha1);
    require(std::isfinite(alpha2) && alpha2 > 0.0 && alpha2 < kRightAngle, "alpha2", "in (0, pi/2) rad", alpha2);
    require(std::isfinite(R1) && R1 > 0.0, "R1", "a positive finite number", R1);
    check_common(xi, density, g);
    const double b = R1 * std::sin(alpha1);
    const double h1 = R1 * std::cos(alpha1), h2 = b / std::tan(alpha2);
    // The same ranges as make_vssw, on the full dimensions these angles give.
    check_dimensions(2.0 * (h1 + h2), 2.0 * b);
    const VsswGeometry w = vssw_from_half_dims(b, h1, h2, xi, density, g);
    require_rocking_vssw(w);
    return w;
}

ParapetGeometry make_parapet(double height, double thickness, double xi, double density, double g) {
    check_dimensions(height, thickness);
    check_common(xi, density, g);
    // Housner's e = 1 - 3/2 sin^2(alpha) must be > 0 for the block to rock onto its other corner: sin^2(alpha) < 2/3,
    // i.e. tan(alpha) = thickness/height < sqrt(2).
    if (!rocks(housner_restitution(std::atan(thickness / height))))
        throw InputError(fmt::format(
            "this parapet does not rock: thickness {:g} m, height {:g} m (thickness/height {:g}) give a Housner "
            "restitution of {:.3g}, and the rocking model's impact law needs one > {:g} (the block must rock onto its "
            "other corner): thickness/height must be below sqrt(2) = 1.414",
            thickness, height, thickness / height, housner_restitution(std::atan(thickness / height)),
            kRestitutionRoundoff));
    ParapetGeometry p{};
    p.b = thickness / 2.0;
    p.h = height / 2.0;
    p.density = density;
    p.xi = xi;
    p.g = g;
    p.alpha = std::atan(p.b / p.h);
    p.R = std::hypot(p.b, p.h);
    p.m = density * thickness * height;
    p.I_G = p.m * p.R * p.R / 3.0;
    p.I_O = p.I_G + p.m * p.R * p.R;
    p.W = p.m * g;
    p.N = xi * p.W;
    return p;
}

namespace {

double checked_eccentricity(double ratio) {
    require(std::isfinite(ratio) && ratio >= -1.0 && ratio <= 1.0, "overburden eccentricity e/b",
            "a number in [-1, 1] (the top face's corners)", ratio);
    return ratio;
}

double checked_corner_radius(double ratio) {
    if (!(std::isfinite(ratio) && ratio >= 0.0 && ratio <= kMaxCornerRadius))
        require(false, "corner radius r/b",
                fmt::format("a number in [0, {:g}] (0: sharp corners, the paper's blocks)", kMaxCornerRadius), ratio);
    return ratio;
}

// The largest |e/b| at which a threshold linear in |e/b| (Eq. 12r, 17r: at(0) at the centre, at(1) at a corner) is
// still > 0.
double largest_standing_eccentricity(double at_centre, double at_corner) {
    return at_centre / (at_centre - at_corner);
}

// With the corners rounded the pivot (the hinge, for the VSSW's upper body) sits at b - r from the centreline, and an
// eccentric N past it turns the wall outward at rest. When that moment outweighs the weights' (Eq. 12r or 17r <= 0 on
// the lower side) nothing holds the wall up: no threshold, no rocking, a hold time of -nan. Refused, whichever of
// with_eccentricity and with_corner_radius comes last. Sharp corners never get here: Eq. (12e) and (17e) stay > 0.
void require_standing(const char* equation, double threshold, double g, double xi, double eccentricity,
                      double corner_radius, double largest_eccentricity) {
    if (threshold > 0.0) return;
    throw InputError(fmt::format(
        "this wall cannot stand: N at e/b {:g} (xi {:g}) acts outside the flat of its rounded pivot (r/b {:g} puts "
        "the pivot at {:g} b) and turns it over at rest: Eq. ({}) gives a threshold of {:.3g} g; at this xi and r/b "
        "|e/b| must be below {:.4g}",
        eccentricity, xi, corner_radius, 1.0 - corner_radius, equation, threshold / g, largest_eccentricity));
}

template <class Wall, class Threshold>
Wall standing(Wall w, const char* equation, Threshold threshold) {
    if (w.corner_radius == 0.0 || w.eccentricity == 0.0) return w;
    Wall centred = w, corner = w;
    centred.eccentricity = 0.0;
    corner.eccentricity = 1.0;
    require_standing(equation, threshold(w), w.g, w.xi, w.eccentricity, w.corner_radius,
                     largest_standing_eccentricity(threshold(centred), threshold(corner)));
    return w;
}

VsswGeometry standing(const VsswGeometry& w) {
    return standing(w, "12r", [](const VsswGeometry& x) { return eq12_threshold(x, 0.0); });
}

ParapetGeometry standing(const ParapetGeometry& p) {
    return standing(p, "17r", [](const ParapetGeometry& x) { return eq17_parapet_threshold(x); });
}

}  // namespace

VsswGeometry with_corner_radius(VsswGeometry w, double ratio) {
    w.corner_radius = checked_corner_radius(ratio);
    // A block lower than its two arcs has no flat side for the roller and the hinge to act along.
    if (!(ratio * w.b <= std::min(w.h1, w.h2)))
        require(false, "corner radius r/b",
                fmt::format("at most {:.6g} on this wall (r no larger than the shorter block's half-height)",
                            std::min(w.h1, w.h2) / w.b),
                ratio);
    return standing(w);
}

ParapetGeometry with_corner_radius(ParapetGeometry p, double ratio) {
    p.corner_radius = checked_corner_radius(ratio);
    return standing(p);
}

VsswGeometry with_eccentricity(VsswGeometry w, double ratio) {
    w.eccentricity = checked_eccentricity(ratio);
    return standing(w);
}

ParapetGeometry with_eccentricity(ParapetGeometry p, double ratio) {
    p.eccentricity = checked_eccentricity(ratio);
    return standing(p);
}

}  // namespace vssw

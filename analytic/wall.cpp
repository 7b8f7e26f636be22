#include "wall.hpp"

#include <cmath>

#include "error.hpp"

namespace vssw {
namespace {

void require_positive(double v, const std::string& what) {
    require(std::isfinite(v) && v > 0.0, what, "a positive finite number", v);
}

void check_common(double xi, double density, double g) {
    require(std::isfinite(xi) && xi >= 0.0, "xi (N/W)", "a finite number >= 0", xi);
    require_positive(density, "density");
    require_positive(g, "gravity g");
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

}  // namespace

VsswGeometry make_vssw(double height, double thickness, double hinge_ratio, double xi, double density, double g) {
    require_positive(height, "height");
    require_positive(thickness, "thickness");
    require(std::isfinite(hinge_ratio) && hinge_ratio > 0.0 && hinge_ratio < 1.0, "hinge ratio h1/h",
            "strictly between 0 and 1", hinge_ratio);
    check_common(xi, density, g);
    const double h = height / 2.0;
    return vssw_from_half_dims(thickness / 2.0, hinge_ratio * h, (1.0 - hinge_ratio) * h, xi, density, g);
}

VsswGeometry make_vssw_from_angles(double alpha1, double alpha2, double R1, double xi, double density, double g) {
    constexpr double kRightAngle = 1.5707963267948966;
    require(std::isfinite(alpha1) && alpha1 > 0.0 && alpha1 < kRightAngle, "alpha1", "in (0, pi/2) rad", alpha1);
    require(std::isfinite(alpha2) && alpha2 > 0.0 && alpha2 < kRightAngle, "alpha2", "in (0, pi/2) rad", alpha2);
    require_positive(R1, "R1");
    check_common(xi, density, g);
    const double b = R1 * std::sin(alpha1);
    return vssw_from_half_dims(b, R1 * std::cos(alpha1), b / std::tan(alpha2), xi, density, g);
}

ParapetGeometry make_parapet(double height, double thickness, double xi, double density, double g) {
    require_positive(height, "height");
    require_positive(thickness, "thickness");
    check_common(xi, density, g);
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

}  // namespace vssw

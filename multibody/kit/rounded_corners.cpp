#include "multibody/kit/rounded_corners.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"

namespace vssw::multibody {

void require_sharp_corners(const std::string& engine, const WallScene& scene, const std::string& why) {
    if (scene.corner_radius_ratio() == 0.0) return;
    throw InputError(fmt::format("corner radius r/b {:g}: {} does not round its blocks yet ({})",
                                 scene.corner_radius_ratio(), engine, why));
}

namespace {

// Newton on the roller's condition: at most this many steps (it converges in 3-5 from Eq. 2's sharp value), to this
// residual in units of b (double's resolution of a corner's position).
constexpr int kPoseNewtonSteps = 50;
constexpr double kPoseResidual = 1e-14;
constexpr double kPoseDerivativeStep = 1e-7;  // [rad] central difference of the corner's x over theta2

struct Vec {
    double x, y;
};

// Clockwise rotation by `angle` of (x, y) (scene_geometry.cpp's turn).
Vec turn(double angle, double x, double y) {
    return {x * std::cos(angle) + y * std::sin(angle), -x * std::sin(angle) + y * std::cos(angle)};
}

}  // namespace

WallPose rounded_pose_at(const WallScene& scene, double theta1) {
    const BlockSizes s = block_sizes(scene);
    const double r = scene.corner_radius(), side = theta1 < 0.0 ? -1.0 : 1.0, inner = s.b - r;
    WallPose p{};
    // Lower block: its base arc's centre (side (b - r), -(h1 - r)) from the block's centre, rolled r theta1 along.
    const Vec base = turn(theta1, side * inner, -(s.h_lower - r));
    p.lower = {side * inner + r * theta1 - base.x, r - base.y, theta1};
    if (!scene.vssw) return p;
    const Vec top1 = turn(theta1, -side * inner, s.h_lower - r);
    const Vec c1{p.lower.x + top1.x, p.lower.y + top1.y};  // the lower block's hinge arc centre
    auto upper_at = [&](double theta2) {
        const Vec n = turn(0.5 * (theta1 + theta2), 0.0, 2.0 * r);  // c1 to the upper block's arc centre
        const Vec bottom2 = turn(theta2, -side * inner, -(s.h_upper - r));
        return BlockPose{c1.x + n.x - bottom2.x, c1.y + n.y - bottom2.y, theta2};
    };
    auto corner_gap = [&](double theta2) {  // the nominal top corner on the pivot's side, past its guide
        const BlockPose u = upper_at(theta2);
        return u.x + turn(theta2, side * s.b, s.h_upper).x - side * s.b;
    };
    double theta2 = eq2_theta2_exact(*scene.vssw, theta1).value_or(0.0);
    for (int i = 0; i < kPoseNewtonSteps && std::abs(corner_gap(theta2)) > kPoseResidual * s.b; ++i) {
        const double slope = (corner_gap(theta2 + kPoseDerivativeStep) - corner_gap(theta2 - kPoseDerivativeStep)) /
                             (2.0 * kPoseDerivativeStep);
        theta2 -= corner_gap(theta2) / slope;
    }
    p.upper = upper_at(theta2);
    return p;
}

}  // namespace vssw::multibody

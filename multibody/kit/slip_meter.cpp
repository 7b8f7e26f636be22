#include "multibody/kit/slip_meter.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace vssw::multibody {
namespace {

// A world point in a block's own frame (the inverse of point_of: clockwise rotation).
PlanePoint local_of(const BlockState& k, double x, double y) {
    const double c = std::cos(k.angle), s = std::sin(k.angle), dx = x - k.x, dy = y - k.y;
    return {dx * c - dy * s, dx * s + dy * c};
}

}  // namespace

// With rounded corners (r > 0) a rolling arc carries its nominal corner along with no slip: the slip is the drift of
// the pivot's arc centre from where rolling without slip puts it (rounded_pose_at). At the base that is side (b - r) +
// r theta1; at the hinge, in the lower block's frame, the upper arc's centre lies 2r from the lower's along the line
// turned by half the blocks' relative rotation. With r = 0 the centres are the corners, and the places +b or -b.
double base_slip(const WallState& s, const BlockSizes& z, double r) {
    const double inner = z.b - r, roll = r * s.lower.angle;
    const double below = -(z.h_lower - r);  // the base arcs' centres (the corners when r = 0), in the block's frame
    const PlanePoint right = point_of(s.lower, inner, below), left = point_of(s.lower, -inner, below);
    return right.y <= left.y ? right.x - (inner + roll) : left.x - (-inner + roll);
}

double hinge_slip(const WallState& s, const BlockSizes& z, double r) {
    if (z.h_upper <= 0.0 || std::isnan(s.upper.angle)) return 0.0;
    const double inner = z.b - r, roll = 2.0 * r * std::sin(0.5 * (s.upper.angle - s.lower.angle));
    const double below = -(z.h_upper - r);
    const PlanePoint right = point_of(s.upper, inner, below), left = point_of(s.upper, -inner, below);
    const PlanePoint right_on = local_of(s.lower, right.x, right.y), left_on = local_of(s.lower, left.x, left.y);
    return right_on.y <= left_on.y ? right_on.x - (inner + roll) : left_on.x - (-inner + roll);
}

SlipMeter::SlipMeter(const WallScene& scene, const BlockSizes& sizes)
    : sizes_(sizes), radius_(scene.corner_radius()), vssw_(scene.vssw.has_value()), alpha_(scene.alpha()) {
    m_.b = sizes.b;
}

std::optional<std::string> SlipMeter::record(double t, const WallState& s) {
    const double base = base_slip(s, sizes_, radius_);
    const double hinge = vssw_ ? hinge_slip(s, sizes_, radius_) : 0.0;
    m_.base_residual = base;
    m_.hinge_residual = hinge;
    m_.base_largest = std::max(m_.base_largest, std::abs(base));
    m_.hinge_largest = std::max(m_.hinge_largest, std::abs(hinge));
    const double most = std::max(std::abs(base), std::abs(hinge));
    if (!m_.t_first_slip && most > kSlipTolerance * sizes_.b) m_.t_first_slip = t;
    if (!m_.t_first_lift && std::abs(s.lower.angle) > kLiftTolerance * alpha_) m_.t_first_lift = t;
    if (most <= kSlidOffLimit * sizes_.b) return std::nullopt;
    const bool at_base = std::abs(base) >= std::abs(hinge);
    m_.slid_off = fmt::format("the wall slid off its support: {} m at the {} at t = {:.6g} s (past {:g} b)",
                              fmt::format("{:.3g}", at_base ? base : hinge), at_base ? "base" : "hinge", t,
                              kSlidOffLimit);
    return m_.slid_off;
}

}  // namespace vssw::multibody

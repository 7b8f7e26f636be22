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

double base_slip(const WallState& s, const BlockSizes& z) {
    const PlanePoint r = point_of(s.lower, z.b, -z.h_lower), l = point_of(s.lower, -z.b, -z.h_lower);
    return r.y <= l.y ? r.x - z.b : l.x + z.b;
}

double hinge_slip(const WallState& s, const BlockSizes& z) {
    if (z.h_upper <= 0.0 || std::isnan(s.upper.angle)) return 0.0;
    const PlanePoint r = point_of(s.upper, z.b, -z.h_upper), l = point_of(s.upper, -z.b, -z.h_upper);
    const PlanePoint r_on = local_of(s.lower, r.x, r.y), l_on = local_of(s.lower, l.x, l.y);
    return r_on.y <= l_on.y ? r_on.x - z.b : l_on.x + z.b;
}

SlipMeter::SlipMeter(const WallScene& scene, const BlockSizes& sizes)
    : sizes_(sizes), vssw_(scene.vssw.has_value()), alpha_(scene.alpha()) {
    m_.b = sizes.b;
}

std::optional<std::string> SlipMeter::record(double t, const WallState& s) {
    const double base = base_slip(s, sizes_);
    const double hinge = vssw_ ? hinge_slip(s, sizes_) : 0.0;
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

#include "multibody/kit/wall_parts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::multibody {
namespace {

using Corners = std::array<PlanePoint, 4>;

Corners corners_of(const TurnedBlock& k, double b, double h) {
    return {k.at(b, -h), k.at(-b, -h), k.at(-b, h), k.at(b, h)};
}

// How far two blocks' projections on the direction (ux, uy) overlap, negative when they are apart along it.
double axis_overlap(const Corners& a, const Corners& c, double ux, double uy) {
    auto span = [&](const Corners& k) {
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (const PlanePoint& p : k) {
            const double d = p.x * ux + p.y * uy;
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
        return std::pair{lo, hi};
    };
    const auto [alo, ahi] = span(a);
    const auto [clo, chi] = span(c);
    return std::min(ahi, chi) - std::max(alo, clo);
}

// How deep two blocks overlap: the least overlap of their projections on the four edge directions (separating axes),
// negative when they are apart. Corners alone would miss a block falling through another of its own width, edge on
// edge (the VSSW's two blocks are equally thick).
double overlap(const Corners& a, const TurnedBlock& ka, const Corners& c, const TurnedBlock& kc) {
    double least = HUGE_VAL;
    for (const TurnedBlock* block : {&ka, &kc}) {
        const double cs = block->c, sn = block->s;
        for (const auto& [ux, uy] : {std::pair{cs, -sn}, std::pair{sn, cs}})  // the block's width and height axes
            least = std::min(least, axis_overlap(a, c, ux, uy));
    }
    return least;
}

bool finite(const BlockState& k) {
    return std::isfinite(k.x) && std::isfinite(k.y) && std::isfinite(k.angle) && std::isfinite(k.vx) &&
           std::isfinite(k.vy) && std::isfinite(k.omega);
}

}  // namespace

PlanePoint point_of(const BlockState& k, double lx, double ly) { return TurnedBlock(k).at(lx, ly); }

WallState still_state_at(const WallScene& scene, double theta1, double theta1_dot, double contact_gap) {
    const WallPose p = pose_at(scene, theta1);
    const BlockState lower{p.lower.x, p.lower.y + contact_gap, p.lower.angle, 0.0, 0.0, theta1_dot};
    if (!scene.vssw) return {lower, kNoBlock};
    return {lower, {p.upper.x, p.upper.y + 2.0 * contact_gap, p.upper.angle, 0.0, 0.0, 0.0}};
}

WallParts::WallParts(std::string engine, const WallScene& scene, const Excitation& ex, double penetration,
                     double energy_gain, double contact_gap)
    : WallParts(std::move(engine), scene, mechanism_figures(scene), ex, penetration, energy_gain, contact_gap) {}

WallParts::WallParts(std::string engine, const WallScene& scene, const MechanismFigures& figures, const Excitation& ex,
                     double penetration, double energy_gain, double contact_gap)
    : engine_(std::move(engine)),
      sizes_(block_sizes(scene)),
      vssw_(scene.vssw.has_value()),
      g_(scene.gravity()),
      N_(scene.overburden()),
      load_x_(scene.overburden_offset()),
      gap_(contact_gap),
      radius_(scene.corner_radius()),
      penetration_(penetration),
      // A moving roller does work on the wall that the ground's pseudo-forces do not bound (its force is the
      // engine's): with a flexible top support under a ground motion the energy check is off and the geometric ones
      // stay. Without a ground motion the roller stays put (TopSupportMotion: u_d = 0) and the check holds.
      energy_gain_(scene.diaphragm.is_rigid() || ex.horizontal.is_zero() ? energy_gain * figures.reference_energy
                                                                          : HUGE_VAL),
      upright_range_(mechanism_theta2(scene, figures.unstable_equilibrium)),
      motion_(&ex.horizontal),
      no_motion_(ex.horizontal.is_zero()),
      rest_(still_state_at(scene, 0.0, 0.0, contact_gap)),
      last_(still_state_at(scene, ex.theta0, 0.0, contact_gap)),
      top_rest_y_(point_of(vssw_ ? rest_.upper : rest_.lower, load_x_, vssw_ ? sizes_.h_upper : sizes_.h_lower).y),
      e0_(energy(last_, TurnedBlock(vssw_ ? last_.upper : last_.lower))) {}

double WallParts::energy(const WallState& s, const TurnedBlock& top) const {
    auto block = [&](const BlockState& k, const BlockState& rest, double m, double h) {
        const double inertia = m * (sizes_.b * sizes_.b + h * h) / 3.0;  // a 2b x 2h rectangle about its centre
        return 0.5 * m * (k.vx * k.vx + k.vy * k.vy) + 0.5 * inertia * k.omega * k.omega + m * g_ * (k.y - rest.y);
    };
    double e = block(s.lower, rest_.lower, sizes_.m_lower, sizes_.h_lower);
    if (vssw_) e += block(s.upper, rest_.upper, sizes_.m_upper, sizes_.h_upper);
    // N's potential: it presses on the top face at load_x_ from its centre (analytic/geometry.hpp).
    const double h_top = vssw_ ? sizes_.h_upper : sizes_.h_lower;
    return e + N_ * (top.at(load_x_, h_top).y - top_rest_y_);
}

// The most work the ground motion can have done on the blocks since the last check: its pseudo-force -m a_h (at most
// the largest |a_h| at the interval's ends and middle) times how far each centre moved along it.
double WallParts::input_bound(double t, const WallState& s) {
    const GroundMotion& a = *motion_;
    if (no_motion_) return 0.0;  // a free vibration: no work given (three evaluations of none a step saved)
    if (std::isnan(a_last_)) a_last_ = std::abs(a(t_last_));
    const double a_now = std::abs(a(t));
    const double a_max = std::max({a_last_, std::abs(a(0.5 * (t_last_ + t))), a_now});
    a_last_ = a_now;
    double moved = sizes_.m_lower * std::abs(s.lower.x - last_.lower.x);
    if (vssw_) moved += sizes_.m_upper * std::abs(s.upper.x - last_.upper.x);
    return a_max * moved;
}

void WallParts::check_contacts(double t, const WallState& s, const TurnedBlock& lower_block,
                               const TurnedBlock* upper_turned) const {
    const BlockSizes& z = sizes_;
    // Rounded corners (rounded_corners.hpp): each corner's arc centre, r inside both faces; a block's lowest point is
    // an arc centre less r, and two blocks overlap by their cores' overlap plus 2 r. r = 0: the corners themselves.
    const double r = radius_;
    const Corners lower = corners_of(lower_block, z.b - r, z.h_lower - r);
    double lowest = HUGE_VAL;
    for (const PlanePoint& p : lower) lowest = std::min(lowest, p.y - r - gap_);
    if (-lowest > penetration_)
        throw EngineFailure(fmt::format("{}: the lower block sank {:.3g} m into the ground at t = {:.6g} s", engine_,
                                        -lowest, t));
    // The upper block is watched while it stands on the lower one (its theta2 inside the mechanism's range, as the
    // roller holds it). Past that range the wall is collapsing (RunMonitor's "upper block gone"): where the fallen
    // block goes is judged by the verdicts, and the engines' scenes do not model a fallen block's contacts (measured:
    // Bullet and MuJoCo on the Fig. 6 wall under Rinaldi at 0.7 g, theta2 -2.7 rad, the block hanging from the hinge
    // against the lower one's face). The sweep's block falling through the hinge stays inside (theta2 -0.16 to -0.53).
    if (!vssw_ || std::abs(s.upper.angle) >= upright_range_) return;
    const TurnedBlock& upper_block = *upper_turned;
    const Corners upper = corners_of(upper_block, z.b - r, z.h_upper - r);
    for (const PlanePoint& p : upper) lowest = std::min(lowest, p.y - r - gap_);
    if (-lowest > penetration_)
        throw EngineFailure(fmt::format("{}: the upper block reached {:.3g} m into the ground at t = {:.6g} s",
                                        engine_, -lowest, t));
    // The overlap along the lower block's height axis first: the least overlap is at most this one (the same sums, so
    // to the bit), and it is the hinge's own, about 0 while the upper block stands on the lower one. Only when it
    // exceeds the limit can the least one: then all four axes are projected.
    if (axis_overlap(lower, upper, lower_block.s, lower_block.c) + 2.0 * r > penetration_) {
        if (const double depth = overlap(lower, lower_block, upper, upper_block) + 2.0 * r; depth > penetration_)
            throw EngineFailure(fmt::format("{}: the upper block sank {:.3g} m into the lower block (through the "
                                            "hinge) at t = {:.6g} s",
                                            engine_, depth, t));
    }
    // The nominal top corners (the roller holds them, not the outline), between the guides at x = u_d - b and u_d + b
    // (u_d = 0: a rigid top support).
    for (const PlanePoint& p : {upper_block.at(-z.b, z.h_upper), upper_block.at(z.b, z.h_upper)})
        if (const double out = std::abs(p.x - s.top_offset) - z.b; out > penetration_)
            throw EngineFailure(fmt::format("{}: the top passed {:.3g} m through the roller at t = {:.6g} s", engine_,
                                            out, t));
}

void WallParts::check(double t, const WallState& s, const TurnedBlock& lower) {
    if (!finite(s.lower) || (vssw_ && !finite(s.upper)))
        throw EngineFailure(fmt::format("{}: the state became NaN at t = {:.6g} s", engine_, t));
    // The upper block turned once, for the contacts and N's potential alike (a parapet: none).
    const std::optional<TurnedBlock> upper = vssw_ ? std::optional<TurnedBlock>(std::in_place, s.upper) : std::nullopt;
    check_contacts(t, s, lower, upper ? &*upper : nullptr);
    if (energy_gain_ == HUGE_VAL) {  // no energy check (a moving roller): its input bound and energy are not needed
        t_last_ = t;
        last_ = s;
        return;
    }
    input_ += input_bound(t, s);
    t_last_ = t;
    last_ = s;
    if (const double gained = energy(s, upper ? *upper : lower) - e0_ - input_; gained > energy_gain_)
        throw EngineFailure(fmt::format("{}: the wall gained {:.3g} J/m of energy that the ground motion did not give "
                                        "it (at t = {:.6g} s)",
                                        engine_, gained, t));
}

}  // namespace vssw::multibody

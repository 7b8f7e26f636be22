#include "diaphragm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "error.hpp"

namespace vssw {
namespace {

constexpr double kTwoPi = 6.283185307179586;
// Nodes an analytic signal's diaphragm motion may hold: 2e7 nodes of 40 bytes are 0.8 GB, past any shaking a wall
// feels (a 60 s motion at T_d = 0.05 s takes 2.4e5); a faster or longer harmonic is refused rather than left to fill
// the memory.
constexpr double kMaxNodes = 2e7;

// The node times of an analytic signal: its breakpoints and extrema, each gap cut into equal parts no longer than
// T_d / kNodesPerPeriod and no fewer than kNodesPerSwing.
std::vector<double> analytic_nodes(const GroundMotion& ground, double period) {
    std::vector<double> marks = ground.breakpoints();
    for (double t = ground.next_extremum(0.0); t < ground.duration(); t = ground.next_extremum(t)) {
        marks.push_back(t);
        if (static_cast<double>(marks.size()) > kMaxNodes) break;
    }
    std::sort(marks.begin(), marks.end());
    marks.erase(std::unique(marks.begin(), marks.end()), marks.end());
    const double h_max = period / TopSupportMotion::kNodesPerPeriod;
    double count = 1.0;
    for (std::size_t i = 0; i + 1 < marks.size(); ++i)
        count += std::max<double>(TopSupportMotion::kNodesPerSwing, std::ceil((marks[i + 1] - marks[i]) / h_max));
    require(count <= kMaxNodes, "diaphragm nodes (the ground motion's length over T_d / 200)",
            fmt::format("at most {:g}: a shorter motion or a longer T_d", kMaxNodes), count);
    std::vector<double> nodes;
    nodes.reserve(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
        const double gap = marks[i + 1] - marks[i];
        const int parts = static_cast<int>(
            std::max<double>(TopSupportMotion::kNodesPerSwing, std::ceil(gap / h_max)));
        for (int j = 0; j < parts; ++j) nodes.push_back(marks[i] + gap * j / parts);
    }
    nodes.push_back(marks.back());
    return nodes;
}

}  // namespace

void require_diaphragm(const Diaphragm& d, const char* period_name, const char* damping_name) {
    // The ranges are formatted only for a message: every analytic model of a scene checks its diaphragm, several
    // times in each engine run's set-up (the run monitor's figures), where formatting them was 0.7 % of an ODE run.
    if (!(std::isfinite(d.period) && d.period >= 0.0 && d.period <= kMaxDiaphragmPeriod))
        require(false, period_name, fmt::format("in [0, {:g}] s (0: a rigid diaphragm)", kMaxDiaphragmPeriod),
                d.period);
    if (!(std::isfinite(d.damping) && d.damping >= 0.0 && d.damping <= kMaxDiaphragmDamping))
        require(false, damping_name, fmt::format("in [0, {:g}]", kMaxDiaphragmDamping), d.damping);
}

TopSupportMotion::TopSupportMotion(const GroundMotion& ground, const Diaphragm& d) {
    require_diaphragm(d);
    if (d.is_rigid()) return;
    omega_ = kTwoPi / d.period;
    zeta_ = d.damping;
    omega_damped_ = omega_ * std::sqrt(1.0 - zeta_ * zeta_);
    if (ground.is_zero()) {  // nothing shakes the diaphragm: u_d = 0 for ever
        nodes_.push_back({0.0, 0.0, 0.0, 0.0, 0.0});
        return;
    }
    std::vector<double> times =
        ground.sample_times().empty() ? analytic_nodes(ground, d.period) : ground.sample_times();
    // A record that starts after t = 0: a = 0 before its first sample (GroundMotion::operator()).
    if (times.front() > 0.0) times.insert(times.begin(), 0.0);
    nodes_.reserve(times.size() + 1);
    Node n{times.front(), 0.0, 0.0, 0.0, 0.0};
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
        const double t0 = times[i], t1 = times[i + 1];
        // The piece's values at its ends from inside it: a record's first sample after a quiet start and an
        // analytic signal's jumps sit at nodes, so each piece takes its own limits there.
        const bool before_record = !ground.sample_times().empty() && t1 <= ground.sample_times().front();
        const double a0 = before_record ? 0.0 : ground(t0), a1 = before_record ? 0.0 : ground(t1);
        n.t = t0;
        n.a0 = a0;
        n.slope = (a1 - a0) / (t1 - t0);
        nodes_.push_back(n);
        const TopOffset end = advance(n, t1 - t0);
        n.u = end.u;
        n.v = end.v;
        peak_u_ = std::max(peak_u_, std::abs(end.u));
    }
    n.t = times.back();  // the free ring-down
    n.a0 = 0.0;
    n.slope = 0.0;
    nodes_.push_back(n);
}

// The exact response over tau >= 0 from a node's state to a(t) = a0 + slope tau: the particular solution A + B tau
// (omega^2 B = -slope, omega^2 A = -a0 - 2 zeta omega B) plus the damped free vibration that meets the state.
TopOffset TopSupportMotion::advance(const Node& n, double tau) const {
    const double w2 = omega_ * omega_;
    const double B = -n.slope / w2;
    const double A = (-n.a0 - 2.0 * zeta_ * omega_ * B) / w2;
    const double c1 = n.u - A;
    const double c2 = (n.v - B + zeta_ * omega_ * c1) / omega_damped_;
    const double decay = std::exp(-zeta_ * omega_ * tau);
    const double c = std::cos(omega_damped_ * tau), s = std::sin(omega_damped_ * tau);
    TopOffset out;
    out.u = A + B * tau + decay * (c1 * c + c2 * s);
    const double zw = zeta_ * omega_;
    out.v = B + decay * ((omega_damped_ * c2 - zw * c1) * c - (omega_damped_ * c1 + zw * c2) * s);
    out.a = -(n.a0 + n.slope * tau) - 2.0 * zeta_ * omega_ * out.v - w2 * out.u;
    return out;
}

TopOffset TopSupportMotion::operator()(double t) const {
    if (is_rigid() || !(t >= nodes_.front().t)) return {};
    // The last node at or before t.
    const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), t, [](double x, const Node& n) { return x < n.t; });
    const Node& n = *(it - 1);
    return advance(n, t - n.t);
}

double TopSupportMotion::absolute_acceleration(double t) const {
    const TopOffset o = (*this)(t);
    return -(2.0 * zeta_ * omega_ * o.v + omega_ * omega_ * o.u);
}

}  // namespace vssw

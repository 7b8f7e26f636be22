#include "compare/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/wall_scene.hpp"
#include "multibody/host/analytic_engine.hpp"

namespace vssw::compare {
namespace {

using multibody::TrajectorySample;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int sign(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

// theta1_dot at time t by the line through samples a and b.
double extrapolate_velocity(const TrajectorySample& a, const TrajectorySample& b, double t) {
    const double slope = (b.theta1_dot - a.theta1_dot) / (b.t - a.t);
    return a.theta1_dot + slope * (t - a.t);
}

// A crossing of theta1 = 0 and the flights either side: samples [begin, before] on the old side, [after, end] on
// the new one (end is filled in once the next crossing or rest is found).
struct Crossing {
    std::size_t begin, before, after, end;
    double t;
};

std::vector<Crossing> find_crossings(const std::vector<TrajectorySample>& s, double noise_angle) {
    std::vector<Crossing> out;
    const std::size_t n = s.size();
    std::size_t flight_begin = 0;  // first sample of the current flight
    std::size_t open = 0;          // crossings whose `end` is still open
    auto close_flights = [&](std::size_t last) {
        for (; open < out.size(); ++open) out[open].end = last;
    };
    int armed = 0;              // side of the last excursion beyond noise_angle since rest (0: none yet)
    bool have_prev = false;     // a non-zero sample seen in this flight sequence
    std::size_t prev = 0;       // last sample with theta1 != 0
    bool have_change = false;   // a sign change seen since the wall was last armed
    Crossing change{};
    for (std::size_t i = 0; i < n; ++i) {
        const double th = s[i].theta1;
        if (th == 0.0) {
            if (s[i].theta1_dot == 0.0) {  // exact rest: the flight sequence ends here
                if (i > 0) close_flights(i - 1);
                armed = 0;
                have_prev = false;
                have_change = false;
                flight_begin = i + 1;
            }
            continue;  // in flight, a sample exactly on theta1 = 0 belongs to the crossing around it
        }
        if (have_prev && sign(th) != sign(s[prev].theta1)) {
            // Where the sign changed: at a sample exactly on zero in between, otherwise by linear interpolation.
            double t = s[prev].t + (s[i].t - s[prev].t) * s[prev].theta1 / (s[prev].theta1 - th);
            for (std::size_t z = prev + 1; z < i; ++z) {
                if (s[z].theta1 == 0.0) {
                    t = s[z].t;
                    break;
                }
            }
            change = {0, prev, i, n - 1, t};
            have_change = true;
        }
        if (std::abs(th) > noise_angle) {
            if (armed != 0 && sign(th) != armed && have_change) {
                change.begin = flight_begin;
                close_flights(change.before);
                out.push_back(change);
                flight_begin = change.after;
            }
            if (armed != sign(th)) have_change = false;
            armed = sign(th);
        }
        prev = i;
        have_prev = true;
    }
    if (n > 0) close_flights(n - 1);
    return out;
}

// Vertex of the parabola through three samples (Newton form), or nullopt when it is not an extremum of |theta1|
// between the outer two.
std::optional<Peak> parabola_vertex(const TrajectorySample& a, const TrajectorySample& b, const TrajectorySample& c) {
    const double d_ab = (b.theta1 - a.theta1) / (b.t - a.t);
    const double d_bc = (c.theta1 - b.theta1) / (c.t - b.t);
    const double curvature = (d_bc - d_ab) / (c.t - a.t);
    if (!(curvature * b.theta1 < 0.0)) return std::nullopt;  // a maximum of |theta1| bends towards zero
    const double t = 0.5 * (a.t + b.t) - d_ab / (2.0 * curvature);
    if (!(t >= a.t && t <= c.t)) return std::nullopt;
    return Peak{t, a.theta1 + d_ab * (t - a.t) + curvature * (t - a.t) * (t - b.t)};
}

}  // namespace

std::vector<ImpactMetric> impacts(const multibody::Trajectory& traj, int skip, double noise_angle) {
    require(skip >= 0, "impact window (samples skipped each side)", ">= 0", skip);
    require(noise_angle >= 0.0 && std::isfinite(noise_angle), "noise angle", "a finite angle >= 0 rad", noise_angle);
    const auto& s = traj.samples;
    const std::size_t k = static_cast<std::size_t>(skip);
    std::vector<ImpactMetric> out;
    for (const Crossing& c : find_crossings(s, noise_angle)) {
        ImpactMetric m{c.t, kNaN, kNaN, kNaN, false, c.before, c.after};
        // Before: samples before - skip (nearer) and before - skip - 1, both in the flight that ends here.
        const bool before_ok = c.before >= c.begin + k + 1;
        // After: samples after + skip (nearer) and after + skip + 1, both in the flight that starts here.
        const bool after_ok = c.after + k + 1 <= c.end;
        if (before_ok && after_ok) {
            const std::size_t b0 = c.before - k, a0 = c.after + k;
            m.theta_dot_before = extrapolate_velocity(s[b0], s[b0 - 1], c.t);
            m.theta_dot_after = extrapolate_velocity(s[a0], s[a0 + 1], c.t);
            m.ratio = m.theta_dot_after / m.theta_dot_before;
            m.resolved = true;
        }
        out.push_back(m);
    }
    return out;
}

std::vector<Peak> peaks(const multibody::Trajectory& traj, double noise_angle) {
    require(noise_angle >= 0.0 && std::isfinite(noise_angle), "noise angle", "a finite angle >= 0 rad", noise_angle);
    const auto& s = traj.samples;
    const std::size_t n = s.size();
    std::vector<Peak> out;
    if (n > 0 && s[0].theta1 != 0.0 && s[0].theta1_dot == 0.0) out.push_back({s[0].t, s[0].theta1});
    bool have_prev = false;
    std::size_t prev = 0;  // last sample with theta1_dot != 0 in the current flight
    for (std::size_t i = 0; i < n; ++i) {
        if (s[i].theta1 == 0.0) {  // a crossing or rest: no turning point spans it
            have_prev = false;
            continue;
        }
        if (s[i].theta1_dot == 0.0) continue;  // a sample on the turning point itself: decided by its neighbours
        const bool turns = have_prev && sign(s[i].theta1_dot) != sign(s[prev].theta1_dot) &&
                           sign(s[i].theta1) == sign(s[prev].theta1);
        if (turns) {
            std::size_t c = prev;  // the sample of largest |theta1| among those spanning the sign change
            for (std::size_t j = prev + 1; j <= i; ++j)
                if (std::abs(s[j].theta1) > std::abs(s[c].theta1)) c = j;
            if (std::abs(s[c].theta1) > noise_angle) {
                std::optional<Peak> p;
                if (c > 0 && c + 1 < n && sign(s[c - 1].theta1) == sign(s[c].theta1) &&
                    sign(s[c + 1].theta1) == sign(s[c].theta1))
                    p = parabola_vertex(s[c - 1], s[c], s[c + 1]);
                out.push_back(p.value_or(Peak{s[c].t, s[c].theta1}));
            }
        }
        prev = i;
        have_prev = true;
    }
    return out;
}

std::optional<double> quarter_period(const multibody::Trajectory& traj) {
    if (traj.samples.empty() || traj.samples.front().theta1 == 0.0) return std::nullopt;
    // Only the crossing time is used, which does not depend on the window.
    const std::vector<ImpactMetric> list = impacts(traj, 0);
    if (list.empty()) return std::nullopt;
    return list.front().t - traj.samples.front().t;
}

std::vector<double> half_cycles(const std::vector<ImpactMetric>& list) {
    std::vector<double> out;
    for (std::size_t i = 1; i < list.size(); ++i) out.push_back(list[i].t - list[i - 1].t);
    return out;
}

std::vector<double> half_cycles(const multibody::Trajectory& traj) { return half_cycles(impacts(traj, 0)); }

double max_abs_theta(const multibody::Trajectory& traj) {
    double m = 0.0;
    for (const auto& s : traj.samples) m = std::max(m, std::abs(s.theta1));
    return m;
}

bool lifted(const multibody::Trajectory& traj, double angle) { return traj.overturned || max_abs_theta(traj) >= angle; }

std::vector<AmplitudeRestitution> amplitude_restitution(const RockingModel& model, const VsswGeometry* vssw,
                                                        const std::vector<ImpactMetric>& list,
                                                        const std::vector<Peak>& turning) {
    std::vector<AmplitudeRestitution> out;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const double lo = i > 0 ? list[i - 1].t : -std::numeric_limits<double>::infinity();
        const double hi = i + 1 < list.size() ? list[i + 1].t : std::numeric_limits<double>::infinity();
        const Peak* before = nullptr;
        const Peak* after = nullptr;
        for (const Peak& p : turning) {
            if (p.t > lo && p.t < list[i].t) before = &p;                     // the last one in the flight before
            if (p.t > list[i].t && p.t < hi && after == nullptr) after = &p;  // the first one in the flight after
        }
        if (before == nullptr || after == nullptr) continue;
        const double qb = std::abs(before->theta), qa = std::abs(after->theta);
        out.push_back({i, qb, qa, restitution_from_peaks(model, qb, qa),
                       vssw != nullptr ? eq23_restitution_from_amplitudes(*vssw, qb, qa)
                                       : std::numeric_limits<double>::quiet_NaN()});
    }
    return out;
}

std::vector<AmplitudeRestitution> amplitude_restitution(const multibody::WallScene& scene,
                                                        const std::vector<ImpactMetric>& list,
                                                        const std::vector<Peak>& turning) {
    const auto model = analytic_model(scene, Kinematics::exact);
    return amplitude_restitution(*model, scene.vssw ? &*scene.vssw : nullptr, list, turning);
}

}  // namespace vssw::compare

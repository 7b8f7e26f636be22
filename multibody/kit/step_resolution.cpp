#include "multibody/kit/step_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw::multibody {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Extrema looked at from the signal's start: its shortest stretch is among the first few (the shipped signals repeat
// one shape, and a harmonic of a million cycles is not walked through).
constexpr int kExtremaLookedAt = 8;

// A limit met to rounding: a step typed as the limit (0.0005 against a record's 0.0004999999999999449) passes.
constexpr double kRoundingSlack = 1e-9;

// The mean quarter cycle of a record's content: a quarter of its span per half-cycle (sign change); its span when
// it never changes sign.
double record_time_scale(const std::vector<double>& times, const std::vector<double>& values) {
    if (times.size() < 2) return kInf;
    long sign_changes = 0;
    for (std::size_t i = 1; i < values.size(); ++i)
        if ((values[i] < 0.0) != (values[i - 1] < 0.0)) ++sign_changes;
    const double span = times.back() - times.front();
    return sign_changes == 0 ? span : 0.5 * span / static_cast<double>(sign_changes);
}

}  // namespace

double excitation_time_scale(const GroundMotion& motion) {
    if (motion.is_zero()) return kInf;
    if (!motion.sample_times().empty()) return record_time_scale(motion.sample_times(), motion.sample_values());
    std::vector<double> points = motion.breakpoints();
    points.push_back(0.0);
    points.push_back(motion.duration());
    double t = 0.0;
    for (int i = 0; i < kExtremaLookedAt; ++i) {
        t = motion.next_extremum(t);
        if (!std::isfinite(t) || t >= motion.duration()) break;
        points.push_back(t);
    }
    std::sort(points.begin(), points.end());
    double shortest = kInf;
    for (std::size_t i = 1; i < points.size(); ++i)
        if (points[i] > points[i - 1]) shortest = std::min(shortest, points[i] - points[i - 1]);
    return shortest;
}

double wall_time_scale(const WallScene& scene) { return scene.alpha() / reference_velocity(scene); }

void require_step_resolves(const std::string& engine, const WallScene& scene, const Excitation& ex, double dt,
                           bool dt_steps_the_motion) {
    if (!(ex.t_end / dt <= kMaxStepsPerRun))
        throw InputError(fmt::format("{}: dt = {:g} s would take {:.3g} steps for this run's {:g} s, more than the {:g} "
                                     "allowed: give a larger step",
                                     engine, dt, ex.t_end / dt, ex.t_end, kMaxStepsPerRun));
    const double wall = wall_time_scale(scene);
    const double motion = dt_steps_the_motion ? excitation_time_scale(ex.horizontal) : kInf;
    const double wall_limit = wall / kStepsPerWallTimeScale, motion_limit = motion / kStepsPerExcitationStretch;
    const double slack = 1.0 + kRoundingSlack;
    if (dt <= wall_limit * slack && dt <= motion_limit * slack) return;
    const std::string motion_words =
        std::isfinite(motion) ? fmt::format(", and at most {:.3g} s for the ground motion (its time scale {:.3g} s / {:g})",
                                            motion_limit, motion, kStepsPerExcitationStretch)
                              : std::string();
    throw InputError(fmt::format("{}: dt = {:g} s is too coarse for this run: a step must be at most {:.3g} s for the "
                                 "wall (its time scale alpha/theta1'_r = {:.3g} s / {:g}){}",
                                 engine, dt, wall_limit, wall, kStepsPerWallTimeScale, motion_words));
}

}  // namespace vssw::multibody

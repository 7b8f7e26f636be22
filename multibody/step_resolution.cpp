#include "multibody/step_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/scene_geometry.hpp"

namespace vssw::multibody {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Extrema looked at from the signal's start: its shortest stretch is among the first few (the shipped signals repeat
// one shape, and a harmonic of a million cycles is not walked through).
constexpr int kExtremaLookedAt = 8;

double median_interval(const std::vector<double>& times) {
    std::vector<double> gaps;
    gaps.reserve(times.size());
    for (std::size_t i = 1; i < times.size(); ++i) gaps.push_back(times[i] - times[i - 1]);
    if (gaps.empty()) return kInf;
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
    return gaps[gaps.size() / 2];
}

}  // namespace

double excitation_time_scale(const GroundMotion& motion) {
    if (motion.is_zero()) return kInf;
    if (!motion.sample_times().empty()) return 2.0 * median_interval(motion.sample_times());
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

void require_step_resolves(const std::string& engine, const WallScene& scene, const Excitation& ex, double dt) {
    const double wall = wall_time_scale(scene);
    const double motion = excitation_time_scale(ex.horizontal);
    const double wall_limit = wall / kStepsPerWallTimeScale, motion_limit = motion / kStepsPerExcitationStretch;
    if (dt <= wall_limit && dt <= motion_limit) return;
    const std::string motion_words =
        std::isfinite(motion)
            ? fmt::format(", and at most {:.3g} s for the ground motion (its shortest stretch {:.3g} s / {:g})",
                          motion_limit, motion, kStepsPerExcitationStretch)
            : std::string();
    throw InputError(fmt::format("{}: dt = {:g} s is too coarse for this run: a step must be at most {:.3g} s for the "
                                 "wall (its time scale alpha/theta1'_r = {:.3g} s / {:g}){}",
                                 engine, dt, wall_limit, wall, kStepsPerWallTimeScale, motion_words));
}

}  // namespace vssw::multibody

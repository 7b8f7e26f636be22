#include "compare/rounded_corners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace vssw::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double spread(const std::vector<double>& values) {
    std::vector<double> measured;
    for (double v : values)
        if (std::isfinite(v)) measured.push_back(v);
    if (measured.size() < 2) return kNaN;
    const auto [lo, hi] = std::minmax_element(measured.begin(), measured.end());
    return (*hi - *lo) / *lo;
}

}  // namespace

multibody::WallScene with_sharp_corners(multibody::WallScene scene) {
    if (scene.vssw) scene.vssw->corner_radius = 0.0;
    if (scene.parapet) scene.parapet->corner_radius = 0.0;
    return scene;
}

RoundedCornerComparison compare_rounded_corners(const std::vector<RoundedEngine>& engines,
                                                const multibody::WallScene& scene, double release,
                                                const ComparisonOptions& options) {
    RoundedCornerComparison out{};
    out.corner_radius_ratio = scene.corner_radius_ratio();
    out.closed_form_g = closed_form_threshold(scene) / scene.gravity();
    out.sharp_closed_form_g = closed_form_threshold(with_sharp_corners(scene)) / scene.gravity();
    out.theta0 = release * scene.alpha();
    FreeVibrationOptions free = options.free;
    free.r = release;
    if (free.t_end <= 0.0) free.t_end = free_vibration_duration(with_sharp_corners(scene), out.theta0, free.impacts);
    std::vector<double> thresholds, periods;
    for (const RoundedEngine& e : engines) {
        RoundedEngineResult res{e.engine->name(), kNaN, kNaN, kNaN, false, ""};
        try {
            res.threshold_g = find_threshold(*e.engine, e.settings, scene, options.threshold).value_g;
            res.threshold_rel_error = res.threshold_g / out.closed_form_g - 1.0;
            const FreeVibrationResult run = run_free_vibration(*e.engine, e.settings, scene, free);
            res.period = run.period.value_or(kNaN);
            res.overturned = run.trajectory.overturned;
        } catch (const multibody::EngineFailure& failure) {
            res.failure = failure.what();
        }
        thresholds.push_back(res.threshold_g);
        periods.push_back(res.period);
        out.engines.push_back(res);
    }
    out.threshold_spread = spread(thresholds);
    out.period_spread = spread(periods);
    return out;
}

}  // namespace vssw::compare

#include "multibody/kit/fold_judge.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "analytic/model.hpp"
#include "analytic/wall_scene.hpp"

namespace vssw::multibody {
namespace {

// Points of H's grid from the unstable equilibrium to the collapse angle (a few alpha1 on a VSSW: ~1e-3 alpha1
// apart). H is smooth and rises from 0 there; each point stands for the cell above it, so a wall is judged against
// the smallest H at or beyond the grid point below it (the grid errs toward going on).
constexpr int kGrid = 512;

}  // namespace

FoldJudge::FoldJudge(const WallScene& scene, const GroundMotion& motion)
    : scene_(&scene),
      motion_(&motion),
      active_(scene.diaphragm.is_rigid() && scene.corner_radius() == 0.0),
      duration_(motion.duration()) {}

void FoldJudge::build() {
    const GroundMotion& motion = *motion_;
    const std::unique_ptr<RockingModel> model = analytic_model(*scene_, Kinematics::exact);
    collapse_ = model->collapse_angle();
    for (int k = 0; k < 2; ++k) {
        const int side = k == 0 ? 1 : -1;
        unstable_[k] = model->unstable_equilibrium(side);
        std::vector<double>& h = hold_back_[k];
        h.resize(kGrid);
        for (int i = 0; i < kGrid; ++i) {
            const double q = unstable_[k] + (collapse_ - unstable_[k]) * i / (kGrid - 1);
            const double c = model->holding_acceleration(side, q);
            h[i] = std::isfinite(c) && c < 0.0 ? -c : 0.0;
        }
        for (int i = kGrid - 2; i >= 0; --i) h[i] = std::min(h[i], h[i + 1]);  // the smallest from each point on
    }
    sampled_ = !motion.sample_times().empty();
    if (sampled_) {
        times_ = motion.sample_times();
        largest_after_.resize(times_.size());
        double largest = 0.0;
        for (std::size_t i = times_.size(); i-- > 0;) {
            largest = std::max(largest, std::abs(motion.sample_values()[i]));
            largest_after_[i] = largest;
        }
    } else {
        analytic_peak_ = motion.pga();
    }
    built_ = true;  // last: a build that threw is tried again, never read half made
}

double FoldJudge::hold_back(int side, double q) {
    if (!active_) return 0.0;
    if (!built_) build();
    const int k = side > 0 ? 0 : 1;
    if (!(q > unstable_[k])) return 0.0;
    const double at = (q - unstable_[k]) / (collapse_ - unstable_[k]) * (kGrid - 1);
    const int i = std::min(kGrid - 1, static_cast<int>(std::floor(at)));
    return hold_back_[k][static_cast<std::size_t>(i)];
}

double FoldJudge::largest_left(double t) {
    if (!active_ || t >= duration_) return 0.0;  // zero after the motion's end (and a still ground's throughout)
    if (!built_) build();
    if (!sampled_) return analytic_peak_;
    while (cursor_ + 1 < times_.size() && times_[cursor_ + 1] <= t) ++cursor_;
    return largest_after_[cursor_];  // from the sample before t (a(t) lies between it and the next)
}

bool FoldJudge::cannot_come_back(double t, double theta1, double theta1_dot) {
    if (!active_) return false;
    const int side = theta1 < 0.0 ? -1 : 1;
    if (side * theta1_dot < 0.0) return false;  // moving inward
    const double h = hold_back(side, std::abs(theta1));
    return h > 0.0 && largest_left(t) < h;
}

}  // namespace vssw::multibody

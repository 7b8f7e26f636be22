#pragma once
// Sliding as a measured response (WallScene::slip_measured): after each step, the base's and the hinge's slip from
// the blocks' state, their largest and last values, the first slip and the first lift-off, and whether the wall has
// left its support (a slip past kSlidOffLimit b, which ends the run with that reason). Engine-free: RunMonitor holds
// one per run and every adapter's state feeds it, so that all engines' slips mean the same thing.
#include <optional>
#include <string>

#include "multibody/engine.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/wall_parts.hpp"

namespace vssw::multibody {

// A slip counts once it passes this share of b: above the contacts' drift at rest before anything moves (measured
// below 1e-5 b on the Fig. 6 wall in every engine) and far below the 5e-2 b of the default friction's failure.
constexpr double kSlipTolerance = 1e-3;
// The wall has lifted once |theta1| passes this share of alpha: the rest criterion's (RunMonitor), above the
// contacts' jitter at rest (~3e-5 rad on the Fig. 6 wall).
constexpr double kLiftTolerance = 1e-3;
// A slip of one b ends the run: at the hinge the upper block's corner has then reached the middle of the lower
// block's top face (its weight over the lower block's edge); at the base the pivot corner has left its place by the
// wall's half-thickness. Past it the wall has left its support and the blocks' rocking is no longer the question.
constexpr double kSlidOffLimit = 1.0;

// The base's slip: the drift from its place (+b or -b on the ground) of the lower of the lower block's two base
// corners, along +x [m]: the pivot while it rocks (the other corner is lifted), either while it rests (both drift
// alike). With corners rounded to `radius` [m], the drift of that corner's arc centre from where rolling puts it.
double base_slip(const WallState& s, const BlockSizes& sizes, double radius = 0.0);
// The hinge's slip: the drift of the upper block's bottom corner nearer the lower block's top face (the hinge's pivot)
// from its place on that face (+b or -b), along the face [m]; 0 for a parapet. Rounded: as base_slip.
double hinge_slip(const WallState& s, const BlockSizes& sizes, double radius = 0.0);

class SlipMeter {
public:
    SlipMeter(const WallScene& scene, const BlockSizes& sizes);
    // Records the step's slips; returns the reason the wall left its support when a slip passed kSlidOffLimit b.
    std::optional<std::string> record(double t, const WallState& s);
    const SlipMeasures& measures() const { return m_; }

private:
    BlockSizes sizes_;
    double radius_;  // the corners' [m] (WallScene::corner_radius)
    bool vssw_;
    double alpha_;
    SlipMeasures m_;
};

}  // namespace vssw::multibody

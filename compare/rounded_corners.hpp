#pragma once
// Rounded corners, where the analytic model stops (docs/model/analytic-core.md, "Rounded corners"): its threshold is a
// closed form (Eq. 12r / 17r), its motion is not built (the pivots roll along the arcs), so each engine's threshold and
// period on the rounded wall are measured and set side by side; their spread over engines of independent contact
// schemes is the uncertainty of the answer.
#include <string>
#include <vector>

#include "compare/experiments.hpp"
#include "multibody/engine.hpp"

namespace vssw::compare {

struct RoundedEngine {
    const multibody::Engine* engine;
    multibody::EngineSettings settings;
};

struct RoundedEngineResult {
    std::string engine;
    double threshold_g = 0.0;  // find_threshold on the rounded wall [g] (NaN when the engine failed)
    double threshold_rel_error = 0.0;  // against Eq. (12r) / (17r)
    double period = 0.0;       // 4 x release to the first impact [s] (NaN when none was resolved)
    bool overturned = false;   // the free vibration overturned (released past the equilibrium, or N off-centre)
    std::string failure;       // the engine's failure, "" when both were measured
};

struct RoundedCornerComparison {
    double corner_radius_ratio;  // r/b
    double closed_form_g;        // Eq. (12r) / (17r), the easier side [g]
    double sharp_closed_form_g;  // Eq. (12) / (17) of the same wall with sharp corners [g]
    double theta0;               // the free vibration's release [rad]
    std::vector<RoundedEngineResult> engines;
    // (largest - smallest) / smallest over the engines that measured it (NaN with fewer than two).
    double threshold_spread, period_spread;
};

// Each engine's threshold (its trials tipping the wall the easier way) and free-vibration period from release * alpha
// (the release angle's share of alpha; r is the corner radius everywhere else), on the
// scene as given (its corner radius and all). The run's length is the sharp wall's automatic one (the analytic model
// cannot run the rounded wall). An engine's EngineFailure is recorded, the others still run.
RoundedCornerComparison compare_rounded_corners(const std::vector<RoundedEngine>& engines,
                                                const multibody::WallScene& scene, double release,
                                                const ComparisonOptions& options = {});

// The scene with sharp corners: the same wall, corner radius 0.
multibody::WallScene with_sharp_corners(multibody::WallScene scene);

}  // namespace vssw::compare

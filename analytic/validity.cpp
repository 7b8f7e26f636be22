#include "validity.hpp"

#include <utility>

#include <fmt/format.h>

#include "closed_forms.hpp"

namespace vssw {

std::vector<std::string> validity_warnings(const RockingModel& model, std::optional<Kinematics> kinematics,
                                           const SimulationResult& result) {
    std::vector<std::string> out;
    const double alpha = model.reference_angle();
    const VsswGeometry* w = model.vssw_geometry();
    if (w && kinematics == Kinematics::paper) {
        // Eq. (3) strays from the roller as theta1 grows (docs/model/paper.md "Where each kinematics stops being
        // valid").
        const auto limit = eq3_validity_limit(*w, kEq3DriftFraction);
        if (limit && result.max_abs_theta > *limit)
            out.push_back(fmt::format(
                "paper kinematics past their validity: the run reached |theta1| = {:.3g} alpha1, and Eq. (3) moves "
                "the top {:g} % of the thickness off the roller from {:.3g} alpha1 on; use --kinematics exact",
                result.max_abs_theta / alpha, 100.0 * kEq3DriftFraction, *limit / alpha));
    }
    // The whole mechanism's impact projects to a negative ratio on a squat wall and is held at 0 (with_impact_law):
    // the model's landing stops the wall, where an engine's contacts were seen to rebound (docs/model/assumptions.md).
    if (w && !result.impacts.empty() && model.restitution() == 0.0) {
        const double projected = restitution_whole_mechanism(*w);
        if (projected < 0.0)
            out.push_back(fmt::format(
                "the whole mechanism's plastic impact projects to a negative ratio ({:.3g}) on this squat wall: the "
                "model's landing leaves it at rest, where a rigid-body engine's contacts may rebound",
                projected));
    }
    if (result.weightless_at)
        out.push_back(fmt::format("the vertical ground acceleration cancels gravity at t = {:.6g} s (g + a_v <= 0): "
                                  "the wall would leave the ground there, which the rocking model does not allow",
                                  *result.weightless_at));
    const SupportDemand& d = result.supports;
    if (!d.computed) return out;
    if (d.roller_tension_at && d.roller_departures == 0)  // a unilateral roller let the top go: modelled, no warning
        out.push_back(fmt::format(
            "the roller would have to pull (from t = {:.6g} s; least reaction {:.4g} N/m at t = {:.6g} s): the "
            "paper's bilateral roller is an assumption that fails here, and a roller that can only push (as the "
            "engines') lets the top leave it",
            *d.roller_tension_at, d.min_roller_reaction, d.t_min_roller_reaction));
    if (d.base_pulls_at)
        out.push_back(fmt::format("the base pivot would have to pull at t = {:.6g} s: the wall would lift off the "
                                  "ground there, which the rocking model does not allow",
                                  *d.base_pulls_at));
    if (d.hinge_pulls_at)
        out.push_back(fmt::format("the hinge would have to pull at t = {:.6g} s: the blocks would separate there, "
                                  "which the rocking model does not allow",
                                  *d.hinge_pulls_at));
    for (const auto& [where, mu] : {std::pair{"base", d.base_friction}, std::pair{"hinge", d.hinge_friction}})
        if (mu > kMasonryFriction)
            out.push_back(fmt::format("the {} needs a friction coefficient of {:.3g} not to slide, above {:g} (a "
                                      "common design value for masonry joints): the no-sliding assumption may fail",
                                      where, mu, kMasonryFriction));
    return out;
}

}  // namespace vssw

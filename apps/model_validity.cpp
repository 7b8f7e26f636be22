#include "apps/model_validity.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"

namespace vssw::cli {

std::vector<std::string> validity_warnings(const WallOptions& wall, const ChosenModel& chosen,
                                           const SimulationResult& result) {
    std::vector<std::string> out;
    const double alpha = chosen.model->reference_angle();
    if (chosen.kinematics == Kinematics::paper) {
        // Eq. (3) strays from the roller as theta1 grows (README, "Where each kinematics stops being valid").
        const auto limit = eq3_validity_limit(vssw_geometry(wall), kEq3DriftFraction);
        if (limit && result.max_abs_theta > *limit)
            out.push_back(fmt::format(
                "paper kinematics past their validity: the run reached |theta1| = {:.3g} alpha1, and Eq. (3) moves "
                "the top {:g} % of the thickness off the roller from {:.3g} alpha1 on; use --kinematics exact",
                result.max_abs_theta / alpha, 100.0 * kEq3DriftFraction, *limit / alpha));
    }
    const SupportDemand& d = result.supports;
    if (!d.computed) return out;
    if (d.roller_tension_at)
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

Json impact_json(const ChosenModel& chosen) {
    return {{"law", to_string(chosen.impact)}, {"restitution", chosen.model->restitution()}};
}

void add_support_json(Json& j, const SimulationResult& result) {
    const SupportDemand& d = result.supports;
    if (!d.computed) {
        j["roller"] = nullptr;
        j["friction_needed"] = nullptr;
        j["contacts_pull"] = nullptr;
        return;
    }
    j["roller"] = {{"model", "bilateral"},
                   {"min_reaction", finite_or_null(d.min_roller_reaction)},
                   {"t_min_reaction", d.t_min_roller_reaction},
                   {"tension_at", or_null(d.roller_tension_at)}};
    j["friction_needed"] = {{"base", finite_or_null(d.base_friction)}, {"hinge", finite_or_null(d.hinge_friction)}};
    j["contacts_pull"] = {{"base_at", or_null(d.base_pulls_at)}, {"hinge_at", or_null(d.hinge_pulls_at)}};
}

void add_support_rows(Table& table, const SimulationResult& result) {
    const SupportDemand& d = result.supports;
    if (!d.computed) return;
    table.add("least roller reaction", num(d.min_roller_reaction), "N/m",
              d.roller_tension_at ? fmt::format("pulls from t = {} s", num(*d.roller_tension_at)) : "pushes throughout")
        .add("friction needed, base / hinge", fmt::format("{} / {}", num(d.base_friction), num(d.hinge_friction)), "",
             "largest |T|/N");
}

}  // namespace vssw::cli

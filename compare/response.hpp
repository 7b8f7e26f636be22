#pragma once
// One run from rest (or released), measured: the response measures that the report's history rows, `vssw check`,
// studies, `vssw compare --record` and Python read under one name each (docs/model/engines-and-metrics.md, "One
// measure per name"). The analytic model's located events when the backend gives them (analytic/response.hpp made
// them), the samples otherwise; an overturned run's peak is the collapse angle at which its backend counts the wall
// overturned, its peak time the overturning.
#include <optional>

#include "multibody/engine.hpp"

namespace vssw::compare {

struct Response {
    double peak = 0.0, peak_time = 0.0;  // |theta1| [rad], [s]; NaN time for a run without samples
    bool overturned = false;
    std::optional<double> t_overturn;    // [s]
    std::optional<double> energy_error;  // the analytic model's energy balance (located events only)
    std::optional<double> tension_at;    // first time the bilateral roller would pull [s] (located events only)
    // Finite friction (multibody::WallScene::slip_measured): an engine's slips, and the friction the analytic model
    // needed at the base and the hinge (located events only, its supports computed).
    std::optional<multibody::SlipMeasures> slip;
    std::optional<double> base_friction_needed, hinge_friction_needed;
};

Response response_of(const multibody::Trajectory& run, const multibody::WallScene& scene);

}  // namespace vssw::compare

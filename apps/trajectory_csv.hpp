#pragma once
// The trajectory CSV of `vssw history --csv` and `vssw free --csv`: one row per sample, in the model's reference units.
#include <iosfwd>

#include "analytic/model.hpp"
#include "analytic/simulate.hpp"

namespace vssw::cli {

// Header "t,theta_over_alpha,theta_dot_over_ref,E_over_Vr,ED_over_Vr,ag_g", then the samples (10 significant digits).
void write_trajectory_csv(std::ostream& out, const RockingModel& model, const SimulationResult& result);

}  // namespace vssw::cli

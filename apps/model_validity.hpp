#pragma once
// What an analytic run's own assumptions say about it, for every command that runs the model (free, history): the
// impact law used, the supports' demand (the roller's reaction, the friction the no-sliding assumption needs, a base
// or hinge contact that would have to pull) and warnings in words where an assumption fails along the run (Eq. 3
// past its validity, a roller that would have to pull, more friction than masonry offers, a contact that pulls).
#include <string>
#include <vector>

#include "analytic/simulate.hpp"
#include "apps/json.hpp"
#include "apps/table.hpp"
#include "apps/wall_options.hpp"

namespace vssw::cli {

// A friction coefficient needed above this is flagged: 0.6 is a common design value for masonry bed joints (0.6-0.8
// are usual; dry or wet joints can be lower), so a run that needs more may slide where the model only rocks.
constexpr double kMasonryFriction = 0.6;
// The paper's kinematics are flagged once Eq. (3) moves the top this fraction of the thickness off the roller.
constexpr double kEq3DriftFraction = 0.01;

std::vector<std::string> validity_warnings(const WallOptions& wall, const ChosenModel& chosen,
                                           const SimulationResult& result);
// {law, restitution}: the impact law and the ratio it gives.
Json impact_json(const ChosenModel& chosen);
// roller {model, min_reaction, t_min_reaction, tension_at}, friction_needed {base, hinge}, contacts_pull
// {base_at, hinge_at}; nulls for a parapet (no roller, not computed).
void add_support_json(Json& j, const SimulationResult& result);
// The same as table rows (nothing for a parapet).
void add_support_rows(Table& table, const SimulationResult& result);

}  // namespace vssw::cli

#pragma once
// What an analytic run's own assumptions say about it, for every command that runs the model (free, history): the
// impact law used, the supports' demand (the roller's reaction, the friction the no-sliding assumption needs, a base
// or hinge contact that would have to pull) and warnings in words where an assumption fails along the run (Eq. 3
// past its validity, a roller that would have to pull, more friction than masonry offers, a contact that pulls).
#include <string>
#include <vector>

#include "analytic/simulate.hpp"
#include "analytic/validity.hpp"
#include "io/json.hpp"
#include "cli/table.hpp"
#include "cli/wall_options.hpp"

namespace vssw::cli {

// analytic/validity.hpp's warnings for the model chosen on the command line.
std::vector<std::string> validity_warnings(const ChosenModel& chosen, const SimulationResult& result);
// `--strict` (free, history, compare): a run whose own assumptions failed is not an answer to build on. Throws
// SimulationFailure (exit 3) naming how many warnings there were and the first; called once the outputs are written.
void refuse_warnings(const std::vector<std::string>& warnings);
// The --strict flag of `free` and `history` (one help text for both).
void add_strict_flag(CLI::App& cmd, bool& strict);
// {law, restitution}: the impact law and the ratio it gives.
io::Json impact_json(const ChosenModel& chosen);
// roller {model, min_reaction, t_min_reaction, tension_at, departures, time_off}, friction_needed {base, hinge},
// contacts_pull {base_at, hinge_at}; nulls for a parapet (no roller, not computed).
void add_support_json(io::Json& j, const SimulationResult& result, Roller roller);
// The same as table rows (nothing for a parapet).
void add_support_rows(Table& table, const SimulationResult& result);

}  // namespace vssw::cli

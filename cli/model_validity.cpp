#include "cli/model_validity.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/simulation_failure.hpp"


namespace vssw::cli {

std::vector<std::string> validity_warnings(const ChosenModel& chosen, const SimulationResult& result) {
    return vssw::validity_warnings(*chosen.model, chosen.kinematics(), result);
}

io::Json impact_json(const ChosenModel& chosen) {
    return {{"law", to_string(chosen.impact())}, {"restitution", chosen.model->restitution()}};
}

void add_support_json(io::Json& j, const SimulationResult& result, Roller roller) {
    const SupportDemand& d = result.supports;
    if (!d.computed) {
        j["roller"] = nullptr;
        j["friction_needed"] = nullptr;
        j["contacts_pull"] = nullptr;
        return;
    }
    j["roller"] = {{"model", to_string(roller)},
                   {"min_reaction", io::finite_or_null(d.min_roller_reaction)},
                   {"t_min_reaction", d.t_min_roller_reaction},
                   {"tension_at", io::or_null(d.roller_tension_at)},
                   {"departures", d.roller_departures},
                   {"time_off", d.time_off_roller}};
    j["friction_needed"] = {{"base", io::finite_or_null(d.base_friction)}, {"hinge", io::finite_or_null(d.hinge_friction)}};
    j["contacts_pull"] = {{"base_at", io::or_null(d.base_pulls_at)}, {"hinge_at", io::or_null(d.hinge_pulls_at)}};
}

void add_support_rows(Table& table, const SimulationResult& result) {
    const SupportDemand& d = result.supports;
    if (!d.computed) return;
    // Under a unilateral roller the reaction is the bilateral one's until the top leaves: where it turns tensile the
    // roller lets go instead of pulling.
    const std::string tension =
        !d.roller_tension_at         ? "pushes throughout"
        : d.roller_departures > 0    ? fmt::format("would pull from t = {} s: the top left the roller there",
                                                   io::num(*d.roller_tension_at))
                                     : fmt::format("pulls from t = {} s", io::num(*d.roller_tension_at));
    table.add("least roller reaction", io::num(d.min_roller_reaction), "N/m", tension)
        .add("top off the roller", fmt::format("{} time{}", d.roller_departures, d.roller_departures == 1 ? "" : "s"),
             "", d.roller_departures > 0 ? fmt::format("{} s in all (unilateral roller)", io::num(d.time_off_roller)) : "")
        .add("friction needed, base / hinge", fmt::format("{} / {}", io::num(d.base_friction), io::num(d.hinge_friction)), "",
             "largest |T|/N");
}

void add_strict_flag(CLI::App& cmd, bool& strict) {
    cmd.add_flag("--strict", strict,
                 "exit 3 when the model's own assumptions fail along the run (its warnings), after writing the outputs "
                 "(for CI)");
}

void refuse_warnings(const std::vector<std::string>& warnings) {
    if (warnings.empty()) return;
    throw SimulationFailure(fmt::format("--strict: the model's assumptions failed along the run ({} warning{}): {}",
                                        warnings.size(), warnings.size() == 1 ? "" : "s", warnings.front()));
}

}  // namespace vssw::cli

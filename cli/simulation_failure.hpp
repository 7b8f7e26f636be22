#pragma once
// The integrator reports a run it cannot finish (step size underflow, step limit) with std::runtime_error, and bad
// input with InputError (also a std::runtime_error). The program tells them apart by exit code, so the commands
// run every simulation through run_simulation(), which renames the former to SimulationFailure and also refuses a
// result that is not finite (a NaN state must not pass as "nothing happened").
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "analytic/error.hpp"
#include "analytic/simulate.hpp"

namespace vssw::cli {

struct SimulationFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <class Simulation>
SimulationResult run_simulation(Simulation&& simulation) {
    SimulationResult result;
    try {
        result = std::forward<Simulation>(simulation)();
    } catch (const InputError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw SimulationFailure(e.what());
    }
    if (!std::isfinite(result.t_final) || !std::isfinite(result.max_abs_theta) ||
        !std::isfinite(result.energy_balance_error))
        throw SimulationFailure("the integrator returned a non-finite result (end time " +
                                std::to_string(result.t_final) + " s, max |theta| " +
                                std::to_string(result.max_abs_theta) + " rad)");
    return result;
}

}  // namespace vssw::cli

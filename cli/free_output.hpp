#pragma once
// Free vibration from rest at theta0 = r * alpha (alpha1 for a VSSW, alpha for a parapet): what `vssw free` prints,
// and the second part of `vssw summary`.
#include <cstddef>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analytic/simulate.hpp"
#include "io/json.hpp"
#include "cli/wall_options.hpp"

namespace vssw::cli {

struct FreeRequest {
    double theta0_over_alpha = 0.0;  // r: finite, nonzero; its sign picks the side
    double rtol = SimulationOptions{}.step.rtol;
    bool keep_trajectory = false;  // --csv: samples kept
    double output_dt = 1e-3;       // [s] their spacing (--output-dt)
};

struct FreeRun {
    WallOptions wall;
    WallKind kind;
    std::optional<Kinematics> kinematics;
    double theta0_over_alpha, alpha;
    SimulationResult result;  // events, and samples when the request keeps the trajectory
    std::vector<std::string> warnings;  // the model's assumptions failing along the run (cli/model_validity.hpp)
    ImpactLaw impact;
    double restitution = 0.0;           // the impact ratio that law gives
    Roller roller = Roller::bilateral;
    std::string set_name;  // the assumptions' set: "paper", "mechanism" or "custom"
    std::shared_ptr<const RockingModel> model;  // for the trajectory's reference units

    std::optional<double> stop_time() const;     // the last rest time; none if the wall overturned
    std::optional<double> first_impact() const;  // the time to the first impact: a quarter period
};

// InputError on a bad wall, a bad r (zero, not finite, r * alpha past the collapse angle) or a bad rtol;
// SimulationFailure when the integrator gives up.
FreeRun run_free(const WallOptions& wall, const ModelOptions& model, const FreeRequest& request);
io::Json to_json(const FreeRun& run);
// The key figures (impacts, quarter period, stop time, overturning, energy balance).
void print_free_summary(std::ostream& out, const FreeRun& run, const std::string& title);
// One row per impact with the peak before it; at most max_rows rows, then a line saying how many were left out.
void print_free_impacts(std::ostream& out, const FreeRun& run, std::size_t max_rows);

}  // namespace vssw::cli

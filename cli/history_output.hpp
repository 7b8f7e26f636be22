#pragma once
// Response of a wall to a ground motion from rest: what `vssw history` prints, and the third part of
// `vssw summary`.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "analytic/simulate.hpp"
#include "cli/ground_motion_options.hpp"
#include "io/json.hpp"
#include "cli/wall_options.hpp"
#include "compare/experiments.hpp"

namespace vssw::cli {

struct HistoryRequest {
    std::optional<double> output_dt;  // trajectory sample spacing [s]; default: the motion's sample_dt
    std::optional<double> t_end;      // [s]; default: the motion's duration + kDefaultExtraTime
    bool keep_trajectory = false;     // samples are needed only for a CSV file
};

// How long a run continues after the ground motion ends by default (compare/experiments.hpp: a study's runs too).
constexpr double kDefaultExtraTime = compare::kResponseTail;  // [s]

struct HistoryRun {
    WallOptions wall;
    std::optional<std::string> record;  // path, when the input is a record
    std::optional<std::string> vertical_record;  // path of the vertical component, when given
    LoadedMotion input;
    ChosenModel chosen;
    SimulationOptions options;
    SimulationResult result;  // empty until simulate_history()
    std::vector<std::string> warnings;  // the model's assumptions failing along the run (cli/model_validity.hpp)
};

// Builds the model and the ground motion and checks every option (InputError on a bad one), without simulating:
// the caller can still refuse (e.g. an unwritable output file) before the run.
HistoryRun prepare_history(const WallOptions& wall, const ModelOptions& model, const GroundMotionOptions& motion,
                           const HistoryRequest& request);
// Fills run.result; SimulationFailure when the integrator gives up.
void simulate_history(HistoryRun& run);
io::Json to_json(const HistoryRun& run);
void print_history_summary(std::ostream& out, const HistoryRun& run, const std::string& title);

}  // namespace vssw::cli

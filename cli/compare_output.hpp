#pragma once
// The output of `vssw compare`: one engine's comparison with the analytic model as a JSON object and as a table, the
// same whether it is the only engine or one of several, and the analytic reference they are all measured against.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "io/json.hpp"
#include "cli/wall_options.hpp"
#include "compare/experiments.hpp"

namespace vssw::cli {

// What every engine of one `vssw compare` is measured against, and on what.
struct CompareReference {
    WallOptions wall;
    WallKind kind;
    std::optional<Kinematics> kinematics;  // the analytic model's; none for a parapet
    ImpactLaw impact;
    std::optional<Roller> roller;          // none for a parapet (it has no roller)
    std::string set_name;                  // "paper", "mechanism" or "custom" (ChosenModel::set_name)
    double theta0;                         // release for the period and restitution, a fraction r of alpha
    double restitution_whole_mechanism;    // what an engine's impact should give (docs/measurements/findings.md)
};

// One engine's comparison. `failure` holds the message of an engine that failed outright (EngineFailure) instead.
struct EngineCompareRun {
    std::string engine, version;
    multibody::EngineSettings settings;
    compare::EngineComparison comparison;
    double seconds = 0.0;
    std::string failure;
};

// {kinematics, impact, roller}: "exact" | "paper" (null for a parapet), the impact law as --impact takes it,
// "bilateral" | "unilateral" (null for a parapet).
io::Json analytic_model_json(const CompareReference& reference);
// The JSON object of one engine (EngineCompareRun::failure empty).
io::Json to_json(const EngineCompareRun& run, const CompareReference& reference);
// Several engines: {comparisons [the object above per engine that ran], engine_failures [{engine, version, message}],
// wall_time_s}.
io::Json to_json(const std::vector<EngineCompareRun>& runs, const CompareReference& reference, double seconds);
// The table of one engine: its metrics, or the failure.
void print_compare(std::ostream& out, const EngineCompareRun& run, const CompareReference& reference);
// Why the run is not a complete result ("" when it is): the failure, or the metrics not measured and why.
std::string incomplete(const EngineCompareRun& run);

}  // namespace vssw::cli

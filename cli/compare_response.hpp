#pragma once
// The output of `vssw compare` with --record or --pulse (study/response_comparison.hpp runs it): the engines and the
// analytic model from rest under one ground motion, each run's peak rotation, its time and overturning side by side,
// as a table or JSON.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/ground_motion_options.hpp"
#include "cli/wall_options.hpp"
#include "study/response_comparison.hpp"

namespace vssw::cli {

// The ground motion of a comparison, from its options as `vssw history` reads them (`loaded`: what
// load_ground_motion read from them), with a study's rules besides (a record with its own times and one that shakes,
// a pulse of positive amplitude): InputError naming the option otherwise. Also the Python module's (vssw.compare).
study::ResponseMotion response_motion(const GroundMotionOptions& m, LoadedMotion loaded);

// The engines and the analytic model (the chosen model's assumptions) from rest under the motion the options give
// (study::compare_response): the Python module's vssw.compare(record=...). InputError as response_motion and
// compare_response say.
study::ResponseComparison compare_under_motion(const ChosenModel& chosen, const GroundMotionOptions& motion,
                                               const std::vector<study::ResponseEngine>& engines,
                                               const std::optional<std::string>& friction = std::nullopt);

// Prints the comparison (table or JSON); `options` names the reference's assumptions as given. SimulationFailure
// (exit 3) when any run failed, or with `strict` when the analytic run warns (after printing).
void print_response_comparison(const study::ResponseComparison& result, const ChosenModel& chosen, double seconds,
                               bool json, bool strict, std::ostream& out);

}  // namespace vssw::cli

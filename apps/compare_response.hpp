#pragma once
// `vssw compare` with --record or --pulse: the engines and the analytic model from rest under one ground motion, each
// run's peak rotation, its time and overturning side by side. It is a one-case study (study/): the options become a
// study document, every run is measured by the study's code, so `vssw compare --record ...` and a study file with the
// same keys give the same numbers.
#include <iosfwd>
#include <string>
#include <vector>

#include "apps/ground_motion_options.hpp"
#include "apps/wall_options.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {

struct ResponseCompareRequest {
    WallOptions wall;
    ModelOptions model;  // the analytic reference's kinematics, impact and roller
    GroundMotionOptions motion;
    std::vector<std::string> engines;                  // checked names, in order
    std::vector<multibody::EngineSettings> settings;   // per engine (the options' dt, iterations, knobs applied)
    bool json = false;
    bool strict = false;  // exit 3 when the analytic run's own assumptions fail (after printing)
};

// Prints the comparison (table or JSON). SimulationFailure (exit 3) when any run failed, or with `strict` when the
// analytic run warns (after printing); InputError on bad input before anything runs.
void compare_response(const ResponseCompareRequest& request, std::ostream& out);

}  // namespace vssw::cli

#pragma once
// What a run of the analytic model says about its own assumptions, in words, for every place the model is used
// (free, history, compare, the report): Eq. (3) past its validity, a roller that would have to pull, a base or hinge
// contact that would have to pull, more friction than masonry joints offer.
#include <optional>
#include <string>
#include <vector>

#include "model.hpp"
#include "simulate.hpp"

namespace vssw {

// A friction coefficient needed above this is flagged: 0.6 is a common design value for masonry bed joints (0.6-0.8
// are usual; dry or wet joints can be lower), so a run that needs more may slide where the model only rocks.
constexpr double kMasonryFriction = 0.6;
// The paper's kinematics are flagged once Eq. (3) moves the top this fraction of the thickness off the roller.
constexpr double kEq3DriftFraction = 0.01;

// `kinematics` is the model's (none for a parapet).
std::vector<std::string> validity_warnings(const RockingModel& model, std::optional<Kinematics> kinematics,
                                           const SimulationResult& result);

}  // namespace vssw

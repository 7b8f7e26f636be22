#pragma once
// The Simbody adapter's default route (engine "simbody"): Hunt-Crossley compliant contact through
// CompliantContactSubsystem, integrated by an error-controlled integrator. Simbody's headers stay in the .cpp.
#include "multibody/engine.hpp"

namespace vssw::multibody {

Trajectory simulate_compliant(const WallScene& scene, const Excitation& excitation, const EngineSettings& settings);

}  // namespace vssw::multibody

#pragma once
// The Simbody adapter's default route (engine "simbody"): Hunt-Crossley compliant contact through
// CompliantContactSubsystem, integrated by an error-controlled integrator. Simbody's headers stay in the .cpp.
#include "multibody/engine.hpp"

namespace vssw::multibody {

Trajectory simulate_compliant(const WallScene& scene, const Excitation& excitation, const EngineSettings& settings);
// Throws InputError on a knob the compliant route does not know or refuses (Engine::check_settings).
void check_compliant_settings(const EngineSettings& settings);
// The compliant route's settings (Engine::setting_descriptions()).
const std::vector<SettingDescription>& compliant_setting_descriptions();

}  // namespace vssw::multibody

#pragma once
// Whether an engine's step can see what it is asked to simulate (issue 27: ODE at --dt 0.5 under a 0.5 s sine pulse
// sampled the pulse only where it is zero and reported "ok, peak 0"; at --dt 1000 every engine did). A step is
// refused, as bad input naming both time scales, when it is longer than
//  - a tenth of the wall's own time scale alpha / theta1'_r (1 / p for a parapet, p = sqrt(3 g / 4 R): about 0.5 s
//    for the Fig. 6 wall, 26 ms for a 1 cm specimen), so that a rocking half-cycle spans tens of steps; or
//  - half the excitation's shortest time scale: a record's typical (median) sample interval times two, so that no
//    sample is stepped over (a step of one sample interval sees every sample); an analytic signal's shortest
//    stretch between its breakpoints and extrema (a quarter period of a sine), so that each rise and fall of the
//    ground acceleration is seen by at least two steps.
// The engines' defaults (0.5 to 2 ms) are 25 or more times finer than either on every wall the program accepts.
#include <string>

#include "multibody/engine.hpp"

namespace vssw::multibody {

constexpr double kStepsPerWallTimeScale = 10.0;
constexpr double kStepsPerExcitationStretch = 2.0;

// The excitation's shortest time scale [s] as above; +infinity for no ground motion.
double excitation_time_scale(const GroundMotion& motion);
// alpha / theta1'_r of the scene [s].
double wall_time_scale(const WallScene& scene);

// Throws InputError naming the step, the limit and what sets it when dt is longer than either limit allows.
void require_step_resolves(const std::string& engine, const WallScene& scene, const Excitation& ex, double dt);

}  // namespace vssw::multibody

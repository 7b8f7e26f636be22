#pragma once
// Whether an engine's step can see what it is asked to simulate (docs/contributing/engines.md "Isolation": ODE at --dt
// 0.5 under a 0.5 s sine pulse sampled the pulse only where it is zero and reported "ok, peak 0"; at --dt 1000 every
// engine did). A step is refused, as bad input naming both time scales, when it is longer than
//  - a tenth of the wall's own time scale alpha / theta1'_r (1 / p for a parapet, p = sqrt(3 g / 4 R): 0.325 s for
//    the Fig. 6 VSSW, 26 ms for a 1 cm specimen), so that a rocking half-cycle spans tens of steps; or
//  - half the ground motion's time scale T_g, so that each rise and fall of the ground acceleration is seen by at
//    least two steps. T_g of an analytic signal is its shortest stretch between breakpoints and extrema (a quarter
//    period of a sine); of a record, the mean quarter cycle of its content, a quarter of its span over the number of
//    sign changes in half-cycles (33 ms for the shipped Rinaldi and El Centro records): its content, not its
//    sampling, so that a smooth record sampled at 2 kHz is no harder than the same at 100 Hz.
// The second applies only where dt is the engine's step; where it is a reporting interval (Simbody's compliant
// route: the integrator picks its steps and sees the motion between reports) the wall's rule alone holds.
// The engines' defaults (0.5 to 2 ms) are 15 or more times finer than either on the shipped records and Table 1's
// walls.
#include <string>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// Steps (or reports) one engine run may take: a step so small that a run would take more is refused as bad input, not
// left to run for hours (ODE costs 2.3 ms per simulated second at its 1 ms step, docs/measurements/speed.md: about 2 us
// a step, so 1e8 steps are minutes; --dt 1e-9 asked for 3e9 per threshold trial).
constexpr double kMaxStepsPerRun = 1e8;

constexpr double kStepsPerWallTimeScale = 10.0;
constexpr double kStepsPerExcitationStretch = 2.0;

// The ground motion's time scale T_g [s] as above; +infinity for no ground motion.
double excitation_time_scale(const GroundMotion& motion);
// alpha / theta1'_r of the scene [s].
double wall_time_scale(const WallScene& scene);

// The one check of an engine step every entry point makes before anything runs (compare, study, report suites,
// Python; RunMonitor and IsolatedEngine again for a caller that did not): InputError naming dt when the run of
// ex.t_end seconds would take more than kMaxStepsPerRun steps, or naming the step, the limit and what sets it when dt
// is longer than either limit above allows (the ground motion's only when `dt_steps_the_motion`).
void require_step_resolves(const std::string& engine, const WallScene& scene, const Excitation& ex, double dt,
                           bool dt_steps_the_motion = true);

}  // namespace vssw::multibody

#pragma once
// Event-driven simulation of a rocking model (a hybrid system: smooth flight on one side, an impact map at
// theta1 = 0, a rest state).
//
//  - At rest the wall stays put until the tipping moment of the ground acceleration beats the restoring one at
//    theta1 = 0 (the equation of motion at rest; Eq. (12) for the VSSW). It lifts off towards -sgn(a_h).
//  - Rocking on side s is integrated with Dormand-Prince 8(5,3), stepping onto the ground motion's breakpoints (and
//    the last 1e-4 s to a predicted landing with classical Runge-Kutta steps).
//  - theta1 reaching 0 is an impact: located on the integrator's own step, then theta1'+ = e theta1'-. Most landings
//    are predicted (a free flight's symmetry; in other flights the parabola through theta1, theta1', theta1'')
//    and the step aimed there; the rest are found on the continuous extension and reached by a re-step.
//    SimulationOptions::predict_landings.
//  - After an impact whose next flight would rise less than rest_amplitude * alpha while the ground cannot tip the
//    wall, the remaining impacts (a geometric series) are summed in closed form: the wall stops at a finite time.
//  - |theta1| reaching the model's collapse angle is overturning; the run ends there.
// These events are one table of guards with their resets (simulate.cpp), located by one routine (bracket.hpp).
// Energy bookkeeping: kinetic + weights' potential - work(N) - work(ground) + dissipated stays at its initial value;
// its largest relative drift (over V_r) is reported.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dop853.hpp"
#include "ground_motion.hpp"
#include "model.hpp"
#include "result_parts.hpp"

namespace vssw {

// The VSSW's top roller: bilateral holds the top corner on its line whatever force that takes (the paper's
// assumption); unilateral can only push, so where the bilateral reaction would turn tensile the top leaves the line
// (analytic/off_roller.hpp). Unilateral needs the exact kinematics (Eq. 3 does not keep the corner on the line).
enum class Roller { bilateral, unilateral };
Roller parse_roller(const std::string& text);  // "bilateral" | "unilateral", InputError otherwise
const char* to_string(Roller roller);

struct SimulationOptions {
    double t_end = 60.0;        // [s]
    StepControl step{};         // rtol 1e-10 by default
    double output_dt = 0.0;     // > 0: samples every output_dt (dense output); 0: at every step and event
    bool keep_samples = true;   // false: no trajectory, only events and summaries (fast path)
    // false: the samples carry the motion (t, theta, theta_dot, work_ground, dissipated, a_h) and NaN for the
    // kinetic energy, the weights' potential and the work of N: for a caller that reads the motion alone, the energies
    // at every output time were most of a sampled run's cost. The energy balance is still checked at every step (the
    // run's energy_balance_error means the same either way; steps are far fewer than samples).
    bool sample_energies = true;
    // Flight amplitude (in units of alpha) below which the remaining impacts are summed to rest in closed form; the
    // closed form treats the restoring acceleration as constant, an error of the order of this amplitude.
    double rest_amplitude = 1e-6;
    bool stop_at_rest = true;   // end the run once at rest after the ground motion has ended
    double event_time_tol = 1e-13;  // [s] root tolerance for impacts and overturning
    // A run whose energy balance error (below) exceeds this is not a result: simulate() throws EnergyBalanceFailure
    // naming the time and the error. 1e-6 of the largest energy in play is 100 to 10,000 times what the integrator
    // leaves at its default tolerance (1e-10 to 1e-8), so only a broken run or a very loose --rtol meets it.
    double energy_ceiling = 1e-6;
    // Compute the supports' forces along a VSSW run (SupportDemand below): what tells whether the roller would have
    // to pull or a contact slide. Off only where the motion alone is wanted and its cost matters.
    bool monitor_supports = true;
    // Aim steps at predicted landings (a free flight's symmetry, or in other flights the parabola through the state)
    // and place the impact without a search when they land close: the same impacts to the accuracy goal with 13 %
    // fewer right-hand sides under a record. false: every impact is found by the search on the continuous extension
    // and a re-step (the tests' reference for the predictions).
    bool predict_landings = true;
    Roller roller = Roller::bilateral;  // a parapet has none: ignored
};

struct InitialState {
    double theta = 0.0;      // [rad]
    double theta_dot = 0.0;  // [rad/s]
};

struct Sample {
    double t, theta, theta_dot;
    double kinetic, weight_potential, work_overburden, work_ground, dissipated;  // [J/m]
    double a_h;  // horizontal ground acceleration [m/s^2]
};

struct Impact {
    double t, theta_dot_before, theta_dot_after;
};

struct SimulationResult {
    std::vector<Sample> samples;
    std::vector<Impact> impacts;
    std::vector<TurningPoint> peaks;
    std::vector<double> lift_offs;   // times the wall left rest
    std::vector<double> rest_times;  // times the wall came to rest (after a finite sequence of impacts)
    bool overturned = false;
    double t_overturn = 0.0;          // valid when overturned
    double t_final = 0.0;             // where the run ended
    bool at_rest_at_end = false;
    double max_abs_theta = 0.0;
    double initial_abs_theta = 0.0;  // |theta1| where the run started (a turning point only when started from rest)
    // Largest |balance residual| divided by the largest energy in play: V_r, or the largest sum of the magnitudes of
    // the balance's terms (kinetic, potential, works, dissipated) met during the run, whichever is larger.
    double energy_balance_error = 0.0;
    long steps = 0, rejected_steps = 0;
    // Events (impacts, overturning) located by the search on the continuous extension and a re-step; the others
    // were placed from a step aimed at a predicted landing (SimulationOptions::predict_landings).
    long searched_events = 0;
    SupportDemand supports;
    // The first time within the run the vertical ground acceleration cancels gravity (g + a_v <= 0): the wall would
    // leave the ground, at rest or rocking, which the model does not describe. Empty when it never does.
    std::optional<double> weightless_at;
};

// The run's largest |theta1| and when it was reached: the overturning's, else the largest of the start and the
// turning points, else (a run cut off mid-swing past them all) the run's end. The outputs read a run's peak through
// analytic/response.hpp, which gives an overturned run the collapse angle instead of this |theta1|.
struct LargestRotation {
    double abs_theta, t;
};
LargestRotation largest_rotation(const SimulationResult& result);

// Output samples a run may keep at most (SimulationOptions::output_dt): more is refused as bad input rather than left to
// run for hours.
constexpr double kMaxOutputSamples = 1e8;

// A run needing more integration steps than this is reported as a failure, not left to spin (every phase counts).
constexpr long kMaxIntegrationSteps = 50'000'000;

// The energy balance failed its ceiling: the trajectory cannot be trusted (a std::runtime_error, like every failed run).
struct EnergyBalanceFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What the message of an EnergyBalanceFailure suggests: a tighter relative tolerance only where the integrator's own
// error can reach the ceiling (up to 100 rtol, measured under records); below that a tighter tolerance gives the same
// failure (the model's events are at fault, as they were in the unilateral roller's micro-rocking failures).
std::string energy_failure_remedy(const SimulationOptions& options);

// Throws InputError naming the first bad option (end time, tolerance, output interval); simulate() calls it first.
void validate(const SimulationOptions& options);

SimulationResult simulate(const RockingModel& model, const GroundMotion& horizontal, const GroundMotion& vertical,
                          InitialState initial, const SimulationOptions& options);

// Free vibration from rest at theta0 (no ground motion), run until the wall stops or overturns. An options.t_end left
// at its default is raised to 1e4 s (the wall stops or falls long before); any other value is kept. A release at
// an equilibrium (where theta1'' = 0, e.g. theta0 = alpha1 with exact kinematics and N = 0) is bad input: the wall
// would neither rock nor fall.
SimulationResult free_vibration(const RockingModel& model, double theta0, SimulationOptions options = {});

}  // namespace vssw

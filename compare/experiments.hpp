#pragma once
// Experiments run through any Engine (the analytic model included, as multibody::AnalyticEngine), measured with
// compare/metrics.hpp only: the threshold acceleration by bisection on simulations, the free vibration from rest, and
// the comparison of an engine with the analytic model on threshold, period and restitution
// (docs/model/engines-and-metrics.md).
#include <optional>
#include <string>
#include <vector>

#include "compare/metrics.hpp"
#include "multibody/engine.hpp"

namespace vssw::compare {


// Threshold ----------------------------------------------------------------------------------------------------
//
// Each trial ramps a horizontal ground acceleration smoothly from 0 to the trial value A (the ramp
// s(x) = x - sin(2 pi x)/(2 pi), x = t/ramp_time, has zero first and second derivatives at both ends: no step that
// would make a compliant engine bounce), then holds A for hold_time. The wall has lifted when |theta1| reaches
// lift_angle * alpha (or it overturned).
//
// Why the hold is long enough: just above the threshold A_c, at A = A_c (1 + eps), the equation of motion linearised
// at theta1 = 0 is theta1'' = eps k + q^2 theta1, with k = A_c X(0)/M(0) (the net tipping acceleration per unit
// excess) and q^2 = d theta1''/d theta1 > 0 (the restoring moment falls as the wall tips). From rest,
// theta1 = (eps k / q^2)(cosh(q t) - 1): the excess eps reaches the lift angle after
//     t(eps) = acosh(1 + lift_angle alpha q^2 / (eps k)) / q,
// which grows only like ln(1/eps). The hold is hold_margin * t(detectable_excess * rel_tol), k and q taken from the
// analytic model of the scene (exact kinematics): any excess of at least a tenth of the tolerance lifts the wall
// within the hold, so the bisection's answer is biased by at most that tenth on top of its bracket. The lift
// criterion of 1e-2 alpha is far above an engine's elastic rotation on its contacts at rest (~1e-6 rad) and far
// below any angle at which the linearisation fails. Measured on the analytic backend (rel_tol 1e-4): the hold is
// 2.7 s for a 4 m x 0.4 m VSSW (h1/h = 0.7, xi = 0.1), 2.2 s for 3.05 m x 0.143 m (0.6, 0.1), 5.0 s for a 4 m x 0.4 m
// parapet, 2.4 s for 0.9 m x 0.11 m; an excess of 1e-5 lifts each at 0.80 of it (the 1/1.25 margin: the estimate is
// accurate), 1e-6 does not lift at all.
//
// Where to look: the analytic model's rest threshold E (Eq. 12 / Eq. 17, exact kinematics, the scene the engines build)
// is already known, and every engine that meets the threshold target (0.5 %) lies within it by construction; measured
// at their defaults they are within 0.15 % (docs/model/engines-and-metrics.md). The search therefore starts from the
// bracket [E / bracket, E * bracket] and tries its upper end (it must lift). Only when an end does not hold (an engine
// more than 1 % off, a knob that moves the threshold) is that end moved out geometrically (the bracket factor squared
// each time: 1 %, 2 %, 4 %, 8 %, ... in log), the end that failed becoming the other end of the bracket.
//
// Where to look next (guided): a trial that lifted says when, and the time it took points at the threshold: the one
// under which the analytic wall, linearised as above and driven through the ramp, reaches the lift angle at that time.
// The next trials go a quarter of rel_tol below and above that point; if it is right, the bracket is closed (a lower
// end that did not lift, an upper one that did) after 3 trials where bisecting the first bracket took 2 + 8 = 10. An
// engine whose wall leaves rest unlike the analytic one points off, and the trials widen around the point; after 6
// guided trials bisection finishes. The answer is the same bracket logic either way: only where trials go changes.
// Measured on the 11 walls of the default suite: the analytic model 3 trials each; ODE and Siconos 3-5; Bullet 4-8;
// Simbody's compliant contacts 3-9 (none above bisection's 10).
struct ThresholdOptions {
    double rel_tol = 1e-4;          // relative width of the final bracket
    double ramp_time = 0.2;         // [s]
    double lift_angle = 1e-2;       // lift criterion, in units of alpha
    double detectable_excess = 0.1; // hold long enough to lift an excess of this fraction of rel_tol
    double hold_margin = 1.25;      // on the linearised estimate (the ramp's end, the nonlinearity)
    double hold_time = 0.0;         // [s] > 0 overrides the estimate above
    // First bracket around the estimate E: [E / bracket, E * bracket]. 1 % is twice the threshold target, so every
    // engine within its target (and one twice as far off) is bracketed at once, and the bracket is narrow: its
    // bisection to rel_tol takes log2(0.02 / rel_tol) = 8 trials.
    double bracket = 1.01;
    // Give up (EngineFailure) when the wall has not lifted under this multiple of the analytic model's rest threshold
    // (Eq. 12 / 17, exact kinematics): the widening upper end stops at it (a trial at exactly this multiple is run).
    // The bracket follows the wall, so an engine that needs up to four times the analytic threshold is still
    // measured, whatever the overburden (a fixed cap of 20 g left a wall with xi 25, 15.8 g by Eq. 12, unmeasurable).
    // Below E / max_over_estimate the lower end is 0 (a wall at rest under no acceleration does not lift).
    double max_over_estimate = 4.0;
    // Trajectory sampling of a trial [s]: only max |theta1| is needed, and past the threshold theta1 grows
    // monotonically, so coarse samples suffice (settings.sample_dt is raised to this, never lowered).
    double sample_dt = 1e-3;
    // Place each trial where the last lift points (the lift time, inverted through the analytic model's departure
    // from rest) rather than at the bracket's middle: the bracket closes in about 2 trials instead of 8, and the
    // answer is the same bracket logic (a lower end that did not lift, an upper end that did). false: bisection only.
    bool guided = true;
    // Which way the trials tip the wall: +1 toward theta1 > 0 (a_h < 0), -1 the other way (a_h > 0), 0 the way its
    // rest threshold is lower (-1 on a tie, as on every wall with N at the centre). The two differ only when N is
    // eccentric (docs/model/analytic-core.md, "The overburden's position"); the answer is the chosen side's.
    int side = 0;
};

struct ThresholdResult {
    double value_g;           // mid-point of the final bracket, in units of the wall's g
    double lower_g, upper_g;  // the final bracket: lower did not lift the wall, upper did
    int trials;               // simulations run (bracket, its widening, and bisection)
    double hold_time;         // [s] hold used by each trial
};

// Ground motion of one trial: the smooth ramp to `amplitude` [m/s^2] over ramp_time, then held for hold_time.
GroundMotion ramp_and_hold(double amplitude, double ramp_time, double hold_time);
// The side the trials tip the wall: options.side, or when 0 the scene's easier side (RockingModel::easier_side).
int trial_side(const multibody::WallScene& scene, const ThresholdOptions& options = {});
// The hold of the reasoning above, for a scene.
double threshold_hold_time(const multibody::WallScene& scene, const ThresholdOptions& options = {});
// Smallest constant horizontal ground acceleration that lifts the wall off rest, by bisection on trials. An
// EngineFailure from a trial propagates.
ThresholdResult find_threshold(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                               const ThresholdOptions& options = {});

// Free vibration -----------------------------------------------------------------------------------------------

// How long a run from rest goes on after its pulse or record ends (it stops earlier at rest or when the wall
// overturns) [s]: the wall may keep rocking after the shaking. One question with two answers, kept apart on purpose:
// each is the one its outputs were measured with, and changing either changes those runs. A case carries the one it
// runs with (study::CaseSpec::response_tail, validation::SuiteCase::response_tail); a study or suite file's
// [excitation] response_tail (pulse, record, scale-to-collapse) replaces these defaults for its part:
//  - kResponseTail: studies, `vssw compare --record/--pulse` and `vssw history` (its default end), so that a study's
//    peaks are `vssw history`'s;
//  - kSuiteResponseTail: the validation suite's history cases, whose Fig. 6 walls come to rest within a few seconds
//    of the shipped records' end at the shipped scales, so a shorter run buys suite time.
constexpr double kResponseTail = 10.0;
constexpr double kSuiteResponseTail = 5.0;

// Smallest release, in units of alpha, that an engine's free vibration is measured from (vssw compare, studies): the
// threshold's lift criterion (ThresholdOptions::lift_angle). Below it an engine's elastic rotation on its contacts
// (~1e-6 rad) and its step are no longer small against the motion (at 1e-4 alpha the Fig. 6 wall's whole period is
// 18 ms), and at 1e-6 alpha the analytic model comes to rest without an impact to measure.
constexpr double kMinRelease = 0.01;

struct FreeVibrationOptions {
    double r = 0.5;          // release from rest at theta1,0 = r alpha
    double t_end = 0.0;      // [s]; 0: long enough for `impacts` impacts of the analytic model (see duration below)
    int impacts = 8;         // impacts the automatic t_end is meant to show (the run stops earlier at rest)
    int skip = kDefaultImpactSkip;  // metrics.hpp
    double noise_angle = 0.0;       // metrics.hpp
};

struct FreeVibrationResult {
    double theta0;  // [rad]
    multibody::Trajectory trajectory;
    std::vector<ImpactMetric> impacts;
    std::vector<Peak> peaks;
    std::optional<double> quarter_period;  // release to first impact [s]
    std::optional<double> period;          // 4 x quarter_period [s]
    std::vector<double> half_cycles;       // between successive impacts [s]
    // theta1_dot ratio of the first impact, when resolved and in (0, 1]: an impact that reverses the wall's motion
    // (ratio <= 0) or gains energy (ratio > 1) is not a restitution of the rocking model but a failure of the run,
    // reported in restitution_note instead of a value.
    std::optional<double> restitution;
    std::string restitution_note;          // why a resolved first impact has no restitution (empty otherwise)
    std::vector<AmplitudeRestitution> amplitude;  // per impact with peaks either side (exact-kinematics model)
};

// Duration that shows `impacts` impacts of the analytic model (exact kinematics) released at theta0: 1.25 times
// the time of that impact (a quarter of the last half-cycle and more, so the peak after it is in the run), or 1.25
// times the time the wall comes to rest if it stops before.
double free_vibration_duration(const multibody::WallScene& scene, double theta0, int impacts);
// A run that needs its first impact only (the period and the first impact's theta1_dot ratio: all that the validation
// suite's free and step cases read) ends at kFirstImpactMargin times the analytic model's first impact (exact
// kinematics, sharp corners), or at free_vibration_duration's end when that model reaches no impact (rest or
// overturning before it). Why 1.5: an impact is measured from kDefaultImpactSkip samples either side of its crossing
// (metrics.hpp), a few ms at any engine's step, and half the time to the impact is left after it, so an engine whose
// first impact comes up to 50 % late (a hundred times the period target of 0.5 %) is still measured; one later has no
// impact in its run and its period is not measured (NaN), never a wrong value. Measured: the suite's 15 free cases x 7
// engines and its step cases give the same period and restitution, bit for bit, as runs to the 8th impact
// (docs/measurements/speed.md, "Runs that end when their measures are known").
constexpr double kFirstImpactMargin = 1.5;
double first_impact_duration(const multibody::WallScene& scene, double theta0);
FreeVibrationResult run_free_vibration(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                                       const FreeVibrationOptions& options = {});

// Whether the engine's step can serve find_threshold's trials and run_free_vibration's run as they will be run
// (multibody::require_step_resolves: at most kMaxStepsPerRun steps, fine enough for the wall and a trial's ramp):
// InputError naming dt otherwise. Callers check it for every engine before the first runs; the analytic model, whose
// dt is its sampling only, passes.
void require_threshold_steps(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                             const ThresholdOptions& options = {});
void require_free_vibration_steps(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                                  const FreeVibrationOptions& options = {});

// Comparison with the analytic model ---------------------------------------------------------------------------

struct MetricComparison {
    double analytic, engine;
    double rel_error;  // engine / analytic - 1 (NaN when either is missing)
};
MetricComparison compare_metric(double analytic, double engine);

// The analytic side of a comparison with an engine run at `settings`: AnalyticEngine's defaults (exact kinematics,
// output every 1e-4 s) whatever the engine's step, so that the reference is the model's own value and the sampling
// error of a coarse engine step is charged to the engine. At 1e-4 s the sampled metrics are within 5.4e-6
// (restitution, Fig. 6 VSSW) of the model's events, 400 times below the tightest target; they are the values of the
// analytic model's own rows in the validation suite. The same for every engine: it does not depend on the engine's
// step or settings.
multibody::EngineSettings analytic_reference_settings();

struct ComparisonOptions {
    ThresholdOptions threshold;
    FreeVibrationOptions free;  // its r is replaced by the r given to compare_with_analytic
    // The analytic reference's settings (independent of the engine's step): its model's knobs (kinematics, impact
    // law, roller: multibody::analytic_settings) and output interval. Default: exact kinematics, Eq. (19), the
    // bilateral roller, every 1e-4 s.
    multibody::EngineSettings reference = analytic_reference_settings();
};

struct EngineComparison {
    MetricComparison threshold_g;      // find_threshold, in g
    MetricComparison period;           // 4 x time to the first impact [s]
    MetricComparison restitution;      // theta1_dot ratio of the first impact
    MetricComparison restitution_amplitude;  // restitution_from_peaks around the first impact
    // Closed forms beside the measured values: Eq. (12) / Eq. (17) [g]; Eq. (19) / Housner's e; the linearised
    // period, Eq. (22) / Housner's (NaN where it does not apply: N > 0, or theta0 beyond its A).
    double threshold_closed_form_g;
    double restitution_closed_form;
    double period_linearised;
    ThresholdResult analytic_threshold, engine_threshold;
    int analytic_impacts, engine_impacts;  // impacts in the free vibration runs
    // Why a metric above is NaN on either side, one line each (empty when all were measured): a comparison with any
    // is not a complete result (vssw compare exits 3).
    std::vector<std::string> failures;
    // The analytic model's own assumptions failing along its free vibration (analytic/validity.hpp): its numbers
    // above are the model's, but the model may not hold there (e.g. a roller that would have to pull).
    std::vector<std::string> analytic_warnings;
    // The engine's slips along its free vibration when the scene's friction was given (WallScene::slip_measured).
    std::optional<multibody::SlipMeasures> free_vibration_slip;
};

// The free vibrations of a comparison: the analytic model at `reference` (AnalyticEngine's settings, e.g.
// analytic_reference_settings) and the engine, released at options.r alpha, both run for the same time
// (options.t_end, or free_vibration_duration when 0).
struct FreeVibrationComparison {
    FreeVibrationResult analytic, engine;
};
FreeVibrationComparison free_vibration_with_analytic(const multibody::Engine& engine, const multibody::EngineSettings& settings,
                                                     const multibody::WallScene& scene, const FreeVibrationOptions& options,
                                                     const multibody::EngineSettings& reference);

// The engine against AnalyticEngine at options.reference (exact kinematics unless it says otherwise), both measured
// by the code above, both free vibrations run for the same time. require_comparison_steps first.
EngineComparison compare_with_analytic(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                                       double r, const ComparisonOptions& options = {});
// require_threshold_steps and require_free_vibration_steps for compare_with_analytic's runs.
void require_comparison_steps(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene, double r,
                              const ComparisonOptions& options = {});

}  // namespace vssw::compare

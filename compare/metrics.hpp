#pragma once
// Metrics of a sampled trajectory, one code path for every backend (docs/model/engines-and-metrics.md: the metrics are
// defined once for every backend): the analytic integrator and each engine are measured by these functions only, from
// the samples of a multibody::Trajectory, never from a backend's own event list.
//
// Impacts are where theta1 changes sign; turning points (peaks) are where theta1_dot changes sign away from
// theta1 = 0. A sample with theta1 == 0 and theta1_dot == 0 exactly is the wall at rest (the analytic model writes
// exact zeros there): rest ends a flight, and the next excursion, on either side, starts a new one (no impact).
//
// Sampling errors, for a trajectory sampled every dt (used to set the tests' tolerances):
//  - impact time: theta1 is linear on each side near the crossing but its slope jumps by the factor e, so the linear
//    interpolation between the two samples either side misplaces the crossing by at most dt (1 - sqrt e)/(1 + sqrt e)
//    (about 0.05 dt for e = 0.8), plus a curvature term of order |theta1''| dt^2 / |theta1_dot|;
//  - impact velocities: linear extrapolation of theta1_dot from two samples whose nearer one is (skip + 1) dt from the
//    crossing errs by at most (1/2) |theta1'''| (skip + 1)(skip + 2) dt^2, where near theta1 = 0
//    theta1''' ~ p^2 theta1_dot (p^2 = d theta1''/d theta1): relative error ~ p^2 (skip + 1)(skip + 2) dt^2 / 2;
//    evaluated at the misplaced crossing time it also picks up |theta1''| delta t on each side, relative
//    (1 + e) |theta1''| delta t / |theta1_dot| on the ratio;
//  - peaks: a parabola through the three samples around a turning point is exact for a parabolic flight and errs by
//    O(dt^4) in theta and O(dt^3) in time for a smooth one (the cubic term vanishes at a turning point of rocking).
#include <cstddef>
#include <optional>
#include <vector>

#include "analytic/model.hpp"
#include "analytic/wall.hpp"
#include "multibody/engine.hpp"

namespace vssw::compare {


// Samples left out on each side of a crossing when reading the velocities either side of an impact. An engine
// spreads an impact over a few steps (a compliant contact over its contact time, an LCP solver over its iterations),
// so the samples nearest the crossing carry a velocity in transition; two samples cover the engines' impact
// duration at their usual steps and cost nothing on a smooth trajectory (the extrapolation error grows as skip^2 dt^2).
constexpr int kDefaultImpactSkip = 2;

struct ImpactMetric {
    double t;                  // crossing time: theta1 interpolated linearly between the two samples either side
    double theta_dot_before;   // theta1_dot before the impact, extrapolated to t (NaN when not resolved)
    double theta_dot_after;    // theta1_dot after the impact, extrapolated to t (NaN when not resolved)
    double ratio;              // theta_dot_after / theta_dot_before (NaN when not resolved)
    bool resolved;             // each side's flight had the skip samples plus the two extrapolated from
    std::size_t index_before;  // last sample on the old side
    std::size_t index_after;   // first sample on the new side
};

// Each sign change of theta1 (samples with theta1 == 0 in flight are skipped; exact rest breaks the sequence).
// theta_dot_before / after: a window of `skip` samples on each side of the crossing is left out, and theta1_dot is
// extrapolated linearly to the crossing time from the two samples nearest the window on that side (both within the
// same flight; otherwise the impact is kept, its velocities NaN and resolved = false).
// noise_angle (>= 0, rad): hysteresis for an engine's jitter at rest. A crossing counts only once |theta1| has
// exceeded noise_angle on the new side, after exceeding it on the old one; it is placed at the last sign change
// before that. 0 (the default) counts every sign change.
std::vector<ImpactMetric> impacts(const multibody::Trajectory& traj, int skip = kDefaultImpactSkip, double noise_angle = 0.0);

struct Peak {
    double t, theta;  // time [s] and theta1 [rad] (signed) of a turning point
};

// Turning points: theta1_dot changes sign between two samples of theta1 of one sign, |theta1| > noise_angle. Time
// and theta are the vertex of the parabola through the sample of largest |theta1| and its two neighbours (the
// sample itself where the neighbours are not all in the same flight). A run starting with theta1 != 0 and
// theta1_dot == 0 (a release from rest) has the release as its first peak.
std::vector<Peak> peaks(const multibody::Trajectory& traj, double noise_angle = 0.0);

// Time from the release (the first sample, theta1 != 0) to the first impact: a quarter period in free vibration.
// nullopt when the run does not start away from theta1 = 0 or has no impact.
std::optional<double> quarter_period(const multibody::Trajectory& traj);
// Times between successive impacts (half-cycles of the rocking), from the impact list or from the trajectory.
std::vector<double> half_cycles(const std::vector<ImpactMetric>& impacts);
std::vector<double> half_cycles(const multibody::Trajectory& traj);

// Largest |theta1| sampled; lifted(): it reached `angle` [rad] (or the run reports the wall overturned).
double max_abs_theta(const multibody::Trajectory& traj);
bool lifted(const multibody::Trajectory& traj, double angle);

// Restitution from the turning points either side of an impact (free vibration only: it assumes energy is conserved
// in flight).
struct AmplitudeRestitution {
    std::size_t impact;      // index in the impact list
    double peak_before;      // |theta1| of the last turning point before the impact [rad]
    double peak_after;       // |theta1| of the first turning point after it [rad]
    double energy;           // restitution_from_peaks(): sqrt(V(after)/V(before)), consistent with M(0) at impact
    double eq23;             // Eq. (23) as printed (VSSW only; NaN for a parapet wall)
};
// One entry per impact that has a turning point in the flights on both sides. `vssw` may be null (no Eq. 23).
std::vector<AmplitudeRestitution> amplitude_restitution(const RockingModel& model, const VsswGeometry* vssw,
                                                        const std::vector<ImpactMetric>& impacts,
                                                        const std::vector<Peak>& peaks);
// The same with the scene's model in the exact kinematics (an engine realises Eq. 2, not Eq. 3).
std::vector<AmplitudeRestitution> amplitude_restitution(const multibody::WallScene& scene,
                                                        const std::vector<ImpactMetric>& impacts,
                                                        const std::vector<Peak>& peaks);

}  // namespace vssw::compare

#include "multibody/kit/run_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/step_resolution.hpp"

namespace vssw::multibody {

FailureLimits FailureLimits::read(const SettingsReader& r) {
    const FailureLimits defaults;
    return {r.positive("slide_limit", defaults.slide), r.positive("penetration_limit", defaults.penetration)};
}

std::vector<SettingDescription> FailureLimits::described_after(std::vector<SettingDescription> adapter_settings) {
    const FailureLimits defaults;
    // These are this program's own checks, never given to an engine library: any positive limit is safe. From
    // 1e-12 b (far below the contacts' jitter: every run fails at once, which the tests use to make a run fail) to
    // 10 b (past it the wall has left its base and nothing is left to watch).
    constexpr double kLowest = 1e-12, kHighest = 10.0;
    adapter_settings.push_back({"slide_limit", fmt::format("{:g}", defaults.slide), "b",
                                "the run fails when the pivot corner has slid this far (in half-thicknesses b)",
                                kLowest, kHighest});
    adapter_settings.push_back({"penetration_limit", fmt::format("{:g}", defaults.penetration), "b",
                                "the run fails when a corner sinks this far below the ground (in b)", kLowest,
                                kHighest});
    return adapter_settings;
}

long sample_every(const EngineSettings& settings, double dt) {
    return settings.sample_dt > 0.0 ? std::max(1L, std::lround(settings.sample_dt / dt)) : 1L;
}

RunMonitor::RunMonitor(std::string engine, const WallScene& scene, const Excitation& ex, double dt,
                       FailureLimits limits, bool dt_steps_the_motion, double contact_gap)
    : figures_(mechanism_figures(scene)),
      engine_(std::move(engine)),
      b_(block_sizes(scene).b),
      h_lower_(block_sizes(scene).h_lower),
      friction_(scene.friction),
      collapse_(figures_.collapse_angle),
      // A free vibration too can pass it: released past it (a heavy N lowers it) or, with N off-centre, landing on the
      // side whose equilibrium is lower. Not when its friction was given: its blocks may slide, the rigid mechanism's
      // argument (FoldJudge) does not hold, and its slide is measured to the end
      // (StudyMeasure.AWallThatSlidOffFailsItsCollapseSearchAndRockingMetrics).
      unstable_(ex.horizontal.duration() > 0.0 || !scene.slip_measured ? figures_.unstable_equilibrium : HUGE_VAL),
      unstable2_(std::isfinite(unstable_) ? mechanism_theta2(scene, unstable_) : HUGE_VAL),
      v_ref_(figures_.reference_velocity),
      alpha_(scene.alpha()),
      motion_end_(ex.horizontal.duration()),
      // From here on no acceleration can lift a wall at rest (kRestCannotLiftShare): rest ends the run.
      // A flexible top support rings on after the ground stops and can still turn the upper block: its runs go to
      // their end.
      quiet_from_(!scene.diaphragm.is_rigid() ? HUGE_VAL
                  : ex.horizontal.is_zero()
                      ? 0.0
                      : ex.horizontal.quiet_after(kRestCannotLiftShare * figures_.rest_threshold)),
      stop_angle_(ex.stop_angle),
      stop_at_rest_(ex.stop_at_rest),
      limits_(limits),
      parts_(engine_, scene, figures_, ex, limits.penetration * b_, limits.energy_gain, contact_gap),
      slip_(scene.slip_measured ? std::optional<SlipMeter>(std::in_place, scene, block_sizes(scene)) : std::nullopt),
      // Asked only past the unstable equilibrium, which most runs never reach (a threshold trial stops short of it):
      // the judge builds its grid then.
      fold_(scene, ex.horizontal),
      // At rest: rotation and rate below 1e-3 of alpha and of theta1'_r for a tenth of a second after the shaking
      // ended (an engine's contacts jitter: measured |theta1| ~ 3e-5 rad on the Fig. 6 wall long after it stopped).
      quiet_needed_(std::max(1, static_cast<int>(std::lround(0.1 / dt)))),
      folded_needed_(std::max(1, static_cast<int>(std::lround(kFoldedFor / dt)))) {
    require_step_resolves(engine_, scene, ex, dt, dt_steps_the_motion);
}

double RunMonitor::default_drift(const TurnedBlock& lower) const {
    const double right_dx = lower.at(b_, -h_lower_).x - b_, left_dx = lower.at(-b_, -h_lower_).x + b_;
    return std::abs(right_dx) < std::abs(left_dx) ? right_dx : left_dx;
}

RunMonitor::Verdict RunMonitor::check(double t, const WallState& s) {
    const double theta = s.lower.angle, rate = s.lower.omega, theta2 = s.upper.angle;
    if (!std::isfinite(theta) || !std::isfinite(rate))
        throw EngineFailure(fmt::format("{}: the state became NaN at t = {:.6g} s", engine_, t));
    // A rocking wall never turns a hundred times faster than the rate that carries it from rest to alpha.
    if (std::abs(rate) > 100.0 * v_ref_)
        throw EngineFailure(fmt::format("{}: blow-up, theta1' = {:.3g} rad/s at t = {:.6g} s", engine_, rate, t));
    // No sliding: while rocking the pivot corner stays put, at rest both do; the smaller drift of the two base
    // corners from their places (+b and -b) covers both cases.
    // The upper block past the mechanism's range (NaN compares false: not given).
    const bool upper_gone = std::abs(theta2) > unstable2_;
    const TurnedBlock lower(s.lower);  // once a step, for the base's drift and every part's check
    if (slip_) {  // the user's friction: sliding is measured (SlipMeter), and ends the run only off the support
        // Only while the wall stands in its mechanism: past the unstable equilibrium the blocks fold, and the drift of
        // their corners is the collapse, not a slide (measured: a hinge "slip" of 4.9 b as an upper block fell).
        if (std::abs(theta) <= unstable_ && !upper_gone && slip_->record(t, s)) return Verdict::slid_off;
    } else if (const double drift = default_drift(lower); std::abs(drift) > limits_.slide * b_)
        throw EngineFailure(fmt::format("{}: the wall slid {:.3g} m at its base at t = {:.6g} s (friction {})",
                                        engine_, drift, t, friction_));
    parts_.check(t, s, lower);
    if (stop_angle_ > 0.0 && std::abs(theta) >= stop_angle_) return Verdict::stop;
    if (std::abs(theta) >= collapse_) return Verdict::overturned;
    if (std::abs(theta) > unstable_ && fold_.cannot_come_back(t, theta, rate)) return Verdict::overturned;
    if (t > motion_end_) {  // folded: past the unstable equilibrium, the shaking over (or none: a free vibration)
        folded_steps_ = std::abs(theta) > unstable_ || upper_gone ? folded_steps_ + 1 : 0;
        if (folded_steps_ >= folded_needed_) return Verdict::overturned;
    }
    if (stop_at_rest_ && t > quiet_from_) {
        const bool quiet = std::abs(theta) < 1e-3 * alpha_ && std::abs(rate) < 1e-3 * v_ref_ && !upper_gone;
        quiet_steps_ = quiet ? quiet_steps_ + 1 : 0;
        if (quiet_steps_ >= quiet_needed_) return Verdict::at_rest;
    }
    return Verdict::go_on;
}

bool RunMonitor::ends_run(Verdict verdict, Trajectory& out) {
    if (verdict == Verdict::go_on) return false;
    out.overturned = verdict == Verdict::overturned;
    out.at_rest_at_end = verdict == Verdict::at_rest;
    return true;
}

}  // namespace vssw::multibody

#pragma once
// What every engine adapter checks after each step, in one place: failures (NaN, blow-up, sliding, and every part of
// the wall that wall_parts.hpp watches: corners in the ground, through the hinge or the roller, energy not given),
// each an EngineFailure naming the engine, the reason and the time; and reasons to stop (a threshold trial's stop angle,
// overturning at the scene's collapse angle, rest once the ground motion is over). Engine-free.
// Overturning is also a wall that has folded: the two blocks can pass the roller's lock short of the collapse angle
// and stay there, the upper block against the far guide, swinging between about 3.7 and 4.0 alpha1 (measured on the
// Fig. 6 wall under Rinaldi at 0.55 g: MuJoCo, Siconos and Simbody alike, never still). No standing wall can stay past
// the unstable equilibrium (RockingModel::unstable_equilibrium) once the ground is still: there gravity turns it
// outward, and only an inward speed brings it back, at once. Past it for kFoldedFor after the shaking (in a free
// vibration, from the start): overturned.
// During the shaking a wall is judged overturned as soon as it cannot come back (FoldJudge: past the equilibrium that
// the largest acceleration left in the record could hold, its rate not inward), which ends a folded wall's run
// seconds to tens of seconds before the record's end; on a still ground (a free vibration, which an off-centre N can
// overturn; its friction not given) as soon as it is past the unstable equilibrium and not moving inward.
// With N off-centre the two sides' equilibria differ; the larger is taken, so a wall standing on the side of the
// larger one is never called overturned.
// The same holds for the upper block (theta2, where the adapter gives it): a wall whose upper block fell off the roller
// and turned past the mechanism's theta2 at that equilibrium has collapsed even with its lower block upright again
// (Simbody's Fig. 6 wall under LA Dam at 0.7 g: theta2 2.2 rad, the top 2.4 m down, theta1 back near 0). Such a wall is
// never at rest either.
// Rest ends a run once the shaking can no longer lift the wall: past the record's last acceleration above
// kRestCannotLiftShare of the rest threshold, not only past its end (the quiet tail of a record is most of it).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "multibody/engine.hpp"
#include "multibody/kit/fold_judge.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/slip_meter.hpp"
#include "multibody/kit/step_resolution.hpp"  // kMaxStepsPerRun, require_step_resolves
#include "multibody/kit/wall_parts.hpp"

namespace vssw::multibody {

// When a run counts as failed, in units of b (the engine settings slide_limit and penetration_limit, every adapter's):
// sliding past `slide` of the pivot corner (measured: the wall "walks" ~1e-2 b over many small impacts in Bullet) or
// any corner sinking past `penetration` into the ground, the other block or a roller guide. energy_gain: the energy
// a run may gain beyond what the ground motion gave (kEnergyGainShare; not a setting: +infinity only in tests that
// feed motions no mechanics gave).
struct FailureLimits {
    double slide = 5e-2;
    double penetration = 5e-2;
    double energy_gain = kEnergyGainShare;
    // The two settings, read by an adapter whose known names include "slide_limit" and "penetration_limit".
    static FailureLimits read(const SettingsReader& r);
    // An adapter's own settings followed by these two (Engine::setting_descriptions()).
    static std::vector<SettingDescription> described_after(std::vector<SettingDescription> adapter_settings);
};

// Record every this many steps for settings.sample_dt (every step when it is 0).
long sample_every(const EngineSettings& settings, double dt);


// A wall at rest stays at rest while |a_h| is below its rest threshold (Eq. 12 / 17: no rocking solution leaves
// rest). Half of the analytic model's threshold, so that an engine whose threshold is off by up to half (every
// engine's target is 0.5 %) is held to the same: shaking below it cannot lift that engine's wall either.
constexpr double kRestCannotLiftShare = 0.5;

// How long a wall must stay past the unstable equilibrium after the shaking (in a free vibration, from the release)
// to count as folded [s]: five times the stillness asked for rest, longer than a wall coming back inward takes to
// cross it (it would be crossing at speed).
constexpr double kFoldedFor = 0.5;

class RunMonitor {
public:
    // slid_off: the wall left its support (SlipMeter, a scene whose friction was given): the run ends there.
    enum class Verdict { go_on, stop, overturned, at_rest, slid_off };

    // InputError when dt is not usable for the run (require_step_resolves: too many steps, or too coarse), naming dt.
    // dt_steps_the_motion false: dt is a reporting interval (the integrator picks its own steps).
    // contact_gap: WallParts's (Simbody's corner spheres keep the bodies their radius apart).
    RunMonitor(std::string engine, const WallScene& scene, const Excitation& ex, double dt, FailureLimits limits,
               bool dt_steps_the_motion = true, double contact_gap = 0.0);

    // Throws EngineFailure on a failure; otherwise says whether the run goes on. Call once per step, in time order,
    // with the blocks relative to the ground (the upper block ignored for a parapet).
    Verdict check(double t, const WallState& state);
    // True when the verdict ends the run, having marked the trajectory overturned or at rest as it says.
    static bool ends_run(Verdict verdict, Trajectory& out);
    // The run's slips when the scene's friction was given (WallScene::slip_measured), else none: Trajectory::slip.
    std::optional<SlipMeasures> slip() const {
        return slip_ ? std::optional(slip_->measures()) : std::nullopt;
    }
    // Whether step i of n is recorded: every `every` steps, the last, and the one that ends the run.
    static bool records(long i, long n, long every, Verdict verdict) {
        return i % every == 0 || i == n || verdict != Verdict::go_on;
    }

private:
    // The default friction's slide: the smaller drift of the two base corners from their places.
    double default_drift(const TurnedBlock& lower) const;

    MechanismFigures figures_;  // first: the members after it read it
    std::string engine_;
    double b_, h_lower_, friction_, collapse_, unstable_, unstable2_, v_ref_, alpha_, motion_end_, quiet_from_,
        stop_angle_;
    bool stop_at_rest_;
    FailureLimits limits_;
    WallParts parts_;
    std::optional<SlipMeter> slip_;  // a scene whose friction was given: sliding measured, not a failure
    FoldJudge fold_;
    int quiet_steps_ = 0, folded_steps_ = 0, quiet_needed_, folded_needed_;
};

}  // namespace vssw::multibody

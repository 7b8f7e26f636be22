#pragma once
// The analytic model (analytic/) behind the Engine interface, so that a comparison measures the analytic trajectory
// and an engine's with the same metric code (compare/metrics.hpp) and the same sampling.
//
// Settings:
//  - dt: the output interval of the trajectory [s] (the integrator's steps are its own, set by rtol); sample_dt, when
//    > 0, takes precedence, as for an engine. Default 1e-4 s, the engines' default step, so that both sides of a
//    comparison are sampled alike unless the caller says otherwise.
//  - knobs: the assumptions, defaulting to the set `mechanism` (analytic/assumption_sets.hpp), as every comparison
//    with an engine uses: "paper_kinematics" (0: exact kinematics of Eq. 2, the default; 1: the paper's Eq. 3),
//    "whole_mechanism_impact" (1, the default: the whole mechanism's plastic impact; 0: Eq. 19 / Housner's),
//    "restitution" (given: this impact ratio in [0, 1] instead, 0 included), "unilateral_roller" (1, the default: a
//    roller that can only push, exact kinematics only; 0: bilateral); "rtol" (DOP853's relative tolerance, default
//    1e-10), "restitution_error" (a stand-in
//    engine's error: every impact's velocity ratio times 1 + this, in [-0.5, 0.5]; 0, the default, leaves the model
//    untouched). Any other knob is
//    an InputError: a misspelt knob must not be ignored silently.
//  - iterations: unused.
// The integrator's own failures (step size underflow, step limit, a non-finite state) are reported as EngineFailure;
// bad input stays InputError.
#include <memory>
#include <string>
#include <vector>

#include "analytic/assumption_sets.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"      // Roller
#include "analytic/wall_scene.hpp"    // analytic_model
#include "multibody/engine.hpp"

namespace vssw::multibody {

class AnalyticEngine final : public Engine {
public:
    std::string name() const override { return "analytic"; }
    double cost_per_simulated_second() const override { return 0.26e-3; }  // Fig. 6 VSSW, docs/measurements/speed.md
    bool dt_is_a_reporting_interval() const override { return true; }  // DOP853 picks its steps
    std::string version() const override { return "vssw analytic (DOP853, event-driven)"; }
    EngineSettings default_settings() const override;
    std::vector<SettingDescription> setting_descriptions() const override;
    Trajectory simulate(const WallScene& scene, const Excitation& excitation,
                        const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override;
};

// The analytic model's assumptions, which the backend takes as knobs: the one encoder (set_assumptions) and decoder
// (read_assumptions) of them, and the one list of their knobs' names, for every caller that runs the model through the
// Engine interface (vssw compare's reference, a study's analytic runs).
// Default-constructed: the set `mechanism`.
using AnalyticAssumptions = Assumptions;
// The knobs that stand for them (a study gives these in [assumptions], not as settings). In the header, so that a
// reader of study files needs no engine to know them.
inline constexpr const char* kPaperKinematicsKnob = "paper_kinematics";  // 1: Eq. (3); 0: Eq. (2)
inline constexpr const char* kRestitutionKnob = "restitution";  // when given: this impact ratio in [0, 1]
inline constexpr const char* kWholeMechanismKnob = "whole_mechanism_impact";  // 1: the whole mechanism's plastic impact
inline constexpr const char* kUnilateralRollerKnob = "unilateral_roller";  // 1: a roller that can only push
// Not an assumption: a stand-in engine's error, every impact's velocity ratio times (1 + this) (validation/earthquake).
inline constexpr const char* kRestitutionErrorKnob = "restitution_error";
inline const std::vector<std::string>& assumption_knobs() {
    static const std::vector<std::string> names = {kPaperKinematicsKnob, kRestitutionKnob, kWholeMechanismKnob,
                                                   kUnilateralRollerKnob};
    return names;
}
// Writes the knobs that stand for `assumptions` into `settings`, replacing any it held.
void set_assumptions(EngineSettings& settings, const AnalyticAssumptions& assumptions);
// The assumptions the knobs stand for (the set `mechanism`'s where none is given); InputError on a value out of
// range, on two impact laws at once, or on assumptions that are not a model (require_a_model).
AnalyticAssumptions read_assumptions(const EngineSettings& settings);

// The settings that run the model under `assumptions` (vssw compare's reference): default_settings() with the
// assumptions' knobs set.
EngineSettings analytic_settings(const Assumptions& assumptions);

// The contacts at which the analytic model's run needed more friction than the scene's given one (WallScene::
// slip_measured): "base", "hinge", in that order; none when its supports were not computed (a parapet, a threshold
// trial). The model cannot slide: it runs as before and says that it would have (docs/model/analytic-core.md).
std::vector<std::string> would_slide_at(const LocatedEvents& located, const WallScene& scene);

}  // namespace vssw::multibody

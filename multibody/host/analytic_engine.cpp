#include "multibody/host/analytic_engine.hpp"

#include "multibody/kit/settings_reader.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/simulate.hpp"
#include "analytic/response.hpp"
#include "analytic/validity.hpp"

namespace vssw::multibody {
namespace {

constexpr const char* kRtol = "rtol";
constexpr double kDefaultRtol = 1e-10;
constexpr double kDefaultOutputDt = 1e-4;  // [s] the engines' default step (EngineSettings::dt)
// A stand-in engine's error (the report's detection limit, validation/earthquake.hpp): every impact's velocity ratio
// times (1 + this), the law's own ratio (Eq. 19, the whole mechanism's, a given one) changed alike; the off-roller
// landings are plastic and stay so. Up to +-0.5: a ratio changed by half is far past any target, and the result
// must stay an impact ratio in [0, 1].
constexpr double kMaxRestitutionError = 0.5;

struct Knobs {
    double rtol = kDefaultRtol;
    double restitution_error = 0.0;
    AnalyticAssumptions assumptions;
};

std::vector<SettingDescription> setting_table() {
    return {
        {"dt", fmt::format("{:g}", kDefaultOutputDt), "s",
         "the sampling interval of the trajectory (the integrator's steps are its own)"},
        {"iterations", "none", "", "not used"},
        {kPaperKinematicsKnob, "0", "0/1", "1: the paper's linearised kinematics (Eq. 3); 0: the exact ones (Eq. 2)", 0.0, 1.0},
        {kRtol, fmt::format("{:g}", kDefaultRtol), "", "DOP853's relative tolerance (impact times within 1e-8 s)"},
        {kRestitutionKnob, "none", "", "when given: this impact ratio in [0, 1] instead of the impact law", 0.0, 1.0},
        {kWholeMechanismKnob, "1", "0/1",
         "1: the whole mechanism's plastic impact (the roller's impulse kept); 0: Eq. (19) / Housner's", 0.0, 1.0},
        {kUnilateralRollerKnob, "1", "0/1", "1: a roller that can only push (exact kinematics); 0: bilateral", 0.0, 1.0},
        {kRestitutionErrorKnob, "0", "",
         "a stand-in engine's error: every impact's velocity ratio times (1 + this); 0 is the model itself",
         -kMaxRestitutionError, kMaxRestitutionError},
    };
}

Knobs read_knobs(const EngineSettings& settings) {
    Knobs k;
    k.assumptions = read_assumptions(settings);  // first, as the unknown knobs are refused there
    const SettingsReader r("analytic", settings, setting_table());
    k.rtol = r.number(kRtol, kDefaultRtol);  // range: simulate()
    k.restitution_error = r.number(kRestitutionErrorKnob, 0.0);
    require(std::abs(k.restitution_error) <= kMaxRestitutionError, "analytic setting restitution_error",
            fmt::format("a number in [-{0:g}, {0:g}]", kMaxRestitutionError), k.restitution_error);
    return k;
}

// theta2 of the sample: Eq. (2) for the exact kinematics (NaN past Eq. 26, where no configuration exists; the run
// ends just before it), Eq. (3) for the paper's, 0 for the single block.
double upper_rotation(const WallScene& scene, Kinematics kinematics, double theta1) {
    if (!scene.vssw) return 0.0;
    if (kinematics == Kinematics::paper) return eq3_theta2_linear(*scene.vssw, theta1);
    return eq2_theta2_exact(*scene.vssw, theta1).value_or(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

EngineSettings AnalyticEngine::default_settings() const {
    EngineSettings s;
    s.dt = kDefaultOutputDt;
    // The assumptions are the set `mechanism` when no knob says otherwise (read_assumptions): none is written here,
    // so that a restitution given alone is not two impact laws.
    s.knobs = {{kRtol, kDefaultRtol}};
    return s;
}

std::vector<SettingDescription> AnalyticEngine::setting_descriptions() const { return setting_table(); }

void AnalyticEngine::check_settings(const EngineSettings& settings) const {
    SimulationOptions options;
    options.step.rtol = read_knobs(settings).rtol;
    validate(options);  // the tolerance's range is the integrator's
}

Trajectory AnalyticEngine::simulate(const WallScene& scene, const Excitation& excitation,
                                    const EngineSettings& settings) const {
    const Knobs knobs = read_knobs(settings);
    // A flexible top under a ground motion is no input error but a run this backend cannot make: the run fails with
    // the reason, and the engines beside it in a comparison or a study still run.
    try {
        require_model_follows_top(scene, excitation.horizontal);
    } catch (const InputError& e) {
        throw EngineFailure(e.what());
    }
    std::unique_ptr<RockingModel> model =
        with_impact_law(analytic_model(scene, knobs.assumptions.kinematics), knobs.assumptions.impact);
    if (knobs.restitution_error != 0.0) {  // 0: the model itself, untouched (the same numbers to the bit)
        const double e = model->restitution() * (1.0 + knobs.restitution_error);
        require(e <= 1.0, "analytic impact ratio with restitution_error", "at most 1 (no impact that creates energy)",
                e);
        model = with_restitution(std::move(model), e);
    }
    // A stop angle (a threshold trial) ends the run there, as it ends an engine's (RunMonitor): the trial's question is
    // answered, and the rest of its hold, with the wall flying towards its collapse, is not integrated (with the
    // unilateral roller such a flight may fail the energy ceiling it has no need to meet).
    const bool stops = excitation.stop_angle > 0.0 && excitation.stop_angle < model->collapse_angle();
    if (stops) model = with_stop_angle(std::move(model), excitation.stop_angle);
    const double output_dt = settings.sample_dt > 0.0 ? settings.sample_dt : settings.dt;
    require(std::isfinite(output_dt) && output_dt > 0.0, "analytic output interval (sample_dt, else dt)",
            "a positive finite time in s", output_dt);

    SimulationOptions options;
    options.t_end = excitation.t_end;
    options.stop_at_rest = excitation.stop_at_rest;
    options.output_dt = output_dt;
    options.step.rtol = knobs.rtol;
    options.roller = knobs.assumptions.roller;
    // A threshold trial (a stop angle) needs only whether the wall lifted: the supports' forces are not computed.
    options.monitor_supports = !(excitation.stop_angle > 0.0);
    options.sample_energies = !excitation.motion_only;

    // The integrator's sign convention is engine.hpp's: a positive a_h tips the wall towards theta1 < 0.
    SimulationResult r;
    try {
        r = vssw::simulate(*model, excitation.horizontal, GroundMotion::none(), {excitation.theta0, 0.0}, options);
    } catch (const InputError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw EngineFailure(fmt::format("analytic integration failed: {}", e.what()));
    }

    const bool stopped = stops && r.overturned;  // at the stop angle, not the collapse angle
    Trajectory out;
    out.overturned = r.overturned && !stopped;
    out.at_rest_at_end = r.at_rest_at_end;
    out.warnings = validity_warnings(*model, scene.vssw ? std::optional(knobs.assumptions.kinematics) : std::nullopt, r);
    out.steps = r.steps;
    LocatedEvents located;
    const AnalyticResponse response = response_of(r, *model);  // stopped: the stop angle, when it was reached
    located.max_abs_theta1 = response.peak;
    located.t_max_abs_theta1 = response.peak_time;
    if (r.overturned && !stopped) located.t_overturn = r.t_overturn;
    located.energy_balance_error = r.energy_balance_error;
    located.supports_computed = r.supports.computed;
    located.roller_tension_at = r.supports.roller_tension_at;
    if (r.supports.computed) {
        located.base_friction_needed = r.supports.base_friction;
        located.hinge_friction_needed = r.supports.hinge_friction;
    }
    // The user's friction: the model cannot slide, so it says where it would (docs/model/analytic-core.md "Finite
    // friction").
    if (scene.slip_measured)
        for (const std::string& where : would_slide_at(located, scene)) {
            const bool base = where == "base";
            out.warnings.push_back(fmt::format(
                "the model would slide: the {} needs a friction coefficient of {:.3g}, above the given {:g}", where,
                base ? located.base_friction_needed : located.hinge_friction_needed,
                base ? scene.base_mu() : scene.hinge_mu()));
        }
    out.located = located;
    out.samples.reserve(r.samples.size());
    const double top_at_rest = model->load_height(0.0);
    for (const Sample& s : r.samples) {
        if (excitation.motion_only) {
            out.samples.push_back(motion_sample(s.t, s.theta, s.theta_dot));
            continue;
        }
        TrajectorySample t{};
        t.t = s.t;
        t.theta1 = s.theta;
        t.theta1_dot = s.theta_dot;
        t.theta2 = upper_rotation(scene, knobs.assumptions.kinematics, s.theta);
        t.top_dy = model->load_height(std::abs(s.theta)) - top_at_rest;
        t.kinetic = s.kinetic;
        t.potential = s.weight_potential - s.work_overburden;
        t.contacts = 0;
        out.samples.push_back(t);
    }
    // The stop angle reached between two output times: its own last sample, so that the samples show it too.
    if (stopped && (out.samples.empty() || std::abs(out.samples.back().theta1) < excitation.stop_angle)) {
        // Built like the others: under motion_only its fields not computed are NaN, as every other sample's.
        TrajectorySample t = !out.samples.empty()     ? out.samples.back()
                             : excitation.motion_only ? motion_sample(0.0, 0.0, 0.0)
                                                      : TrajectorySample{};
        const double side = !out.samples.empty() && out.samples.back().theta1 < 0.0 ? -1.0 : 1.0;
        t.t = r.t_overturn;
        t.theta1 = side * excitation.stop_angle;
        if (!excitation.motion_only) t.theta2 = upper_rotation(scene, knobs.assumptions.kinematics, t.theta1);
        out.samples.push_back(t);
    }
    return out;
}

void set_assumptions(EngineSettings& settings, const AnalyticAssumptions& a) {
    std::map<std::string, double>& knobs = settings.knobs;
    knobs[kPaperKinematicsKnob] = a.kinematics == Kinematics::paper ? 1.0 : 0.0;
    knobs[kUnilateralRollerKnob] = a.roller == Roller::unilateral ? 1.0 : 0.0;
    // A restitution present is used, 0 included; absent, whole_mechanism_impact chooses the law.
    knobs.erase(kRestitutionKnob);
    knobs.erase(kWholeMechanismKnob);
    if (a.impact.kind == ImpactLaw::Kind::ratio) knobs[kRestitutionKnob] = a.impact.ratio;
    else knobs[kWholeMechanismKnob] = a.impact.kind == ImpactLaw::Kind::whole_mechanism ? 1.0 : 0.0;
}

AnalyticAssumptions read_assumptions(const EngineSettings& settings) {
    const SettingsReader r("analytic", settings, setting_table());
    const auto given = [&](const char* knob) { return settings.knobs.count(knob) > 0; };
    AnalyticAssumptions a;  // the set `mechanism` where no knob says otherwise
    if (given(kPaperKinematicsKnob)) a.kinematics = r.flag(kPaperKinematicsKnob) ? Kinematics::paper : Kinematics::exact;
    if (given(kRestitutionKnob)) {  // given means used: 0 is a plastic impact
        if (given(kWholeMechanismKnob) && r.flag(kWholeMechanismKnob))
            throw InputError("analytic settings restitution and whole_mechanism_impact=1 are two impact laws: give one");
        const double e = r.non_negative(kRestitutionKnob, 0.0);
        require(e <= 1.0, "analytic setting restitution", "a number in [0, 1]", e);
        a.impact = {ImpactLaw::Kind::ratio, e};
    } else if (given(kWholeMechanismKnob) && !r.flag(kWholeMechanismKnob)) {
        a.impact = {};  // Eq. (19) / Housner's
    }
    if (given(kUnilateralRollerKnob)) a.roller = r.flag(kUnilateralRollerKnob) ? Roller::unilateral : Roller::bilateral;
    require_a_model(a, a.roller == Roller::unilateral && !given(kUnilateralRollerKnob)
                           ? "analytic setting paper_kinematics=1 with the default unilateral roller (the set "
                             "'mechanism') needs unilateral_roller=0"
                           : "analytic setting unilateral_roller=1 needs paper_kinematics=0");
    return a;
}

EngineSettings analytic_settings(const AnalyticAssumptions& assumptions) {
    EngineSettings s = AnalyticEngine().default_settings();
    set_assumptions(s, assumptions);
    return s;
}

std::vector<std::string> would_slide_at(const LocatedEvents& located, const WallScene& scene) {
    std::vector<std::string> at;
    if (!located.supports_computed) return at;
    if (located.base_friction_needed > scene.base_mu()) at.emplace_back("base");
    if (scene.vssw && located.hinge_friction_needed > scene.hinge_mu()) at.emplace_back("hinge");
    return at;
}

}  // namespace vssw::multibody

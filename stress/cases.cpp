// The stress cases (docs/measurements/stress.md). Each names the input that makes it hard and what is held of the
// result; the tolerances are stability criteria, not the accuracy targets of the validation suite (an engine that meets
// those on ordinary walls is asked here only not to break, and to agree with the analytic model where the answer is
// known).
#include <cmath>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "compare/experiments.hpp"
#include "stress/case.hpp"
#include "vssw_engine_facts.hpp"  // each engine's contact ends (generated: cmake/engines.cmake)

namespace vssw::stress {
namespace {

using multibody::EngineSettings;
using multibody::Excitation;
using multibody::WallScene;

// A stress run's first impact must come within 2 % of the analytic model's: four times the suite's 0.5 % period
// target, so an engine that is merely less accurate on an extreme wall passes and one that has gone unstable (a
// blown-up step, a wall that sticks or bounces) does not.
constexpr double kPeriodTol = 0.02;
// Rotation that counts as lifting off [alpha]: the threshold's lift criterion (compare::ThresholdOptions::lift_angle),
// far above an engine's elastic rotation at rest (~1e-6 rad) and far below any rocking excursion.
constexpr double kLiftAngle = 1e-2;
// Release of the free-vibration cases [alpha]: the suite's middle release.
constexpr double kRelease = 0.5;
// Impacts a free-vibration case shows: 3 in full, 1 in quick (the first impact is what is checked).
constexpr int kImpactsFull = 3;
constexpr int kImpactsQuick = 1;
// Trajectory sampling of a stress run [s]: 1 ms resolves a first impact of the walls here to well under kPeriodTol
// (their quarter periods are >= 0.1 s) and keeps a 600 s run's trajectory small.
constexpr double kSampleDt = 1e-3;

WallScene fig6_vssw(double xi = 0.0) { return WallScene::of(make_vssw(4.0, 0.4, 0.7, xi)); }
WallScene fig6_pw() { return WallScene::of(make_parapet(4.0, 0.4)); }

EngineSettings sampled(EngineSettings s) {
    s.sample_dt = std::max(kSampleDt, s.dt);
    return s;
}

// A run of `scene` at `settings`, from rest, nothing checked yet.
Setup start(WallScene scene, EngineSettings settings) {
    Setup s;
    s.scene = std::move(scene);
    s.settings = std::move(settings);
    return s;
}

// A free vibration from rest at r alpha, judged on overturning and the first impact's time.
Setup free_vibration(WallScene scene, const EngineSettings& defaults, bool quick, double r = kRelease) {
    Setup s = start(std::move(scene), sampled(defaults));
    s.excitation.theta0 = r * s.scene.alpha();
    s.excitation.t_end =
        compare::free_vibration_duration(s.scene, s.excitation.theta0, quick ? kImpactsQuick : kImpactsFull);
    s.overturn_as_analytic = true;
    s.period_tol = kPeriodTol;
    return s;
}

// The contact knobs at the soft and the stiff end of their range: each engine's CONTACT_SOFT and CONTACT_STIFF facts
// (its multibody/<engine>/engine.cmake, checked there as knob=number words; docs/guide/stress.md: which knob).
EngineSettings contact_end(const std::string& engine, EngineSettings s, bool stiff) {
    const EngineFacts* facts = nullptr;
    for (const EngineFacts& e : kEngineFacts)
        if (engine == e.name) facts = &e;
    const std::string words = facts ? (stiff ? facts->contact_stiff : facts->contact_soft) : "";
    if (words.empty())
        throw InputError(fmt::format("{} has no contact stiffness knob (rigid contact or no contact at all)", engine));
    std::istringstream in(words);
    for (std::string word; in >> word;) {
        const std::size_t eq = word.find('=');
        s.knobs[word.substr(0, eq)] = std::stod(word.substr(eq + 1));
    }
    return s;
}

// The step at `factor` times the default; the analytic model's step is its own (set by rtol), so rtol is scaled.
EngineSettings step_scaled(const std::string& engine, EngineSettings s, double factor) {
    if (engine == "analytic") s.knobs["rtol"] *= factor;
    else s.dt *= factor;
    return s;
}

std::vector<Case> make_cases() {
    std::vector<Case> c;
    c.push_back({"slender-t/h0.01", "VSSW 4 x 0.04 m (t/h 0.01), h1/h 0.7, free vibration from 0.5 alpha: overturn as "
                 "analytic, first impact within 2 %", true,
                 [](const std::string&, const EngineSettings& d, bool q) {
                     return free_vibration(WallScene::of(make_vssw(4.0, 0.04, 0.7)), d, q);
                 }});
    c.push_back({"squat-t/h0.5", "VSSW 4 x 2 m (t/h 0.5), h1/h 0.7, free vibration from 0.5 alpha: as above", true,
                 [](const std::string&, const EngineSettings& d, bool q) {
                     return free_vibration(WallScene::of(make_vssw(4.0, 2.0, 0.7)), d, q);
                 }});
    for (double hinge : {0.05, 0.95})
        c.push_back({fmt::format("hinge-{}", hinge),
                     fmt::format("VSSW 4 x 0.4 m, h1/h {}, free vibration from 0.5 alpha: as above", hinge), hinge < 0.5,
                     [hinge](const std::string&, const EngineSettings& d, bool q) {
                         return free_vibration(WallScene::of(make_vssw(4.0, 0.4, hinge)), d, q);
                     }});
    for (double xi : {0.0, 50.0})
        c.push_back({fmt::format("xi-{}", xi),
                     fmt::format("Fig. 6 VSSW with xi {}, free vibration from 0.5 alpha: as above", xi), xi > 0.0,
                     [xi](const std::string&, const EngineSettings& d, bool q) { return free_vibration(fig6_vssw(xi), d, q); }});
    c.push_back({"release-0.999-collapse", "Fig. 6 parapet released at 0.999 alpha (its static collapse angle): "
                 "slow fall back, no overturning (as analytic), first impact within 2 %", true,
                 [](const std::string&, const EngineSettings& d, bool q) { return free_vibration(fig6_pw(), d, q, 0.999); }});
    c.push_back({"release-1e-6-alpha", "Fig. 6 VSSW released at 1e-6 alpha for 2 s: never lifts past 1e-2 alpha, "
                 "no overturning", true,
                 [](const std::string&, const EngineSettings& d, bool) {
                     Setup s = start(fig6_vssw(), sampled(d));
                     s.excitation.theta0 = 1e-6 * s.scene.alpha();
                     s.excitation.t_end = 2.0;
                     s.overturn_as_analytic = true;
                     s.max_theta = kLiftAngle * s.scene.alpha();
                     return s;
                 }});
    for (int sign : {-1, +1})
        c.push_back({sign < 0 ? "pulse-threshold-1e-9" : "pulse-threshold+1e-9",
                     sign < 0 ? "Fig. 6 VSSW, ramp and hold at Eq. (12) x (1 - 1e-9): the analytic model must not lift "
                                "(1e-2 alpha); engines (own threshold within 0.15 % of it) only no failure"
                              : "Fig. 6 VSSW, ramp and hold at Eq. (12) x (1 + 1e-9), ending once lifted: no failure, no NaN",
                     sign < 0,
                     [sign](const std::string& engine, const EngineSettings& d, bool) {
                         Setup s = start(fig6_vssw(), sampled(d));
                         const double a = closed_form_threshold(s.scene) * (1.0 + sign * 1e-9);
                         const double hold = compare::threshold_hold_time(s.scene);
                         s.excitation.horizontal = compare::ramp_and_hold(a, 0.2, hold);
                         s.excitation.t_end = 0.2 + hold;
                         s.excitation.stop_angle = kLiftAngle * s.scene.alpha();
                         if (sign < 0 && engine == "analytic") s.max_theta = kLiftAngle * s.scene.alpha();
                         return s;
                     }});
    c.push_back({"chattering-e0.05", "Fig. 6 VSSW, analytic model with impact ratio 0.05 (Zeno: impacts accumulate) "
                 "from 0.5 alpha: comes to rest at a finite time, no overturning; engines refuse (their landing's ratio "
                 "is what their contacts make of it, not a setting)",
                 true,
                 [](const std::string& engine, const EngineSettings& d, bool) {
                     if (engine != "analytic")
                         throw InputError(engine + " has no setting for the whole landing's impact ratio: its "
                                                   "contacts make it (Siconos's per-contact coefficients included, "
                                                   "docs/engines.md \"Siconos\")");
                     Setup s = start(fig6_vssw(), sampled(d));
                     s.settings.knobs["restitution"] = 0.05;
                     s.excitation.theta0 = kRelease * s.scene.alpha();
                     s.excitation.t_end = 5.0;
                     s.overturn_as_analytic = true;
                     s.must_rest = true;
                     return s;
                 }});
    c.push_back({"chattering-squat-block", "block 1 x 1.2 m (Housner e 0.12: a low-restitution landing, many quick "
                 "impacts) from 0.5 alpha for 3 s: no overturning, back within 1e-2 alpha of rest at the end", true,
                 [](const std::string&, const EngineSettings& d, bool) {
                     Setup s = start(WallScene::of(make_parapet(1.0, 1.2)), sampled(d));
                     s.excitation.theta0 = kRelease * s.scene.alpha();
                     s.excitation.t_end = 3.0;
                     s.overturn_as_analytic = true;
                     s.final_theta = kLiftAngle * s.scene.alpha();
                     return s;
                 }});
    c.push_back({"harmonic-600s", "Fig. 6 VSSW under a 600 s harmonic, 0.5 x Eq. (12), period 0.3 s: never lifts "
                 "past 1e-2 alpha (below its threshold), no failure over 3e6 steps", false,
                 [](const std::string&, const EngineSettings& d, bool) {
                     Setup s = start(fig6_vssw(), sampled(d));
                     s.excitation.horizontal = harmonic(0.5 * closed_form_threshold(s.scene), 0.3, 600.0);
                     s.excitation.t_end = 600.0;
                     s.max_theta = kLiftAngle * s.scene.alpha();
                     return s;
                 }});
    c.push_back({"huge-pga", "Fig. 6 VSSW under a 0.5 s sine pulse of 50 g: overturns, as the analytic model does",
                 true,
                 [](const std::string&, const EngineSettings& d, bool) {
                     Setup s = start(fig6_vssw(), sampled(d));
                     s.excitation.horizontal = sine_pulse(50.0 * s.scene.gravity(), 0.5);
                     s.excitation.t_end = 3.0;
                     s.overturn_as_analytic = true;
                     return s;
                 }});
    for (double factor : {10.0, 0.01})
        c.push_back({fmt::format("step-{}x", factor),
                     fmt::format("Fig. 6 VSSW free vibration from 0.5 alpha at {} x the backend's default step (the "
                                 "analytic model: rtol): overturn as analytic, first impact within 2 %",
                                 factor),
                     factor > 1.0,
                     [factor](const std::string& engine, const EngineSettings& d, bool q) {
                         Setup s = free_vibration(fig6_vssw(), step_scaled(engine, d, factor), q);
                         s.settings.sample_dt = std::max(kSampleDt, s.settings.dt);
                         return s;
                     }});
    for (bool stiff : {false, true})
        c.push_back({stiff ? "contact-stiff" : "contact-soft",
                     fmt::format("Fig. 6 VSSW free vibration from 0.5 alpha, contact at the {} end (simbody stiffness "
                                 "{} Pa, ode erp {} cfm {}, bullet erp {}; analytic and simbody-rigid refuse): as above",
                                 stiff ? "stiff" : "soft", stiff ? "1e18" : "1e12", stiff ? "1" : "0.2",
                                 stiff ? "0" : "1e-5", stiff ? "1" : "0"),
                     false,  // Simbody at 1e18 Pa runs past a minute (docs/measurements/stress.md)
                     [stiff](const std::string& engine, const EngineSettings& d, bool q) {
                         return free_vibration(fig6_vssw(), contact_end(engine, d, stiff), q);
                     }});
    return c;
}

}  // namespace

const std::vector<Case>& all_cases() {
    static const std::vector<Case> cases = make_cases();
    return cases;
}

const Case* find_case(const std::string& name) {
    for (const Case& c : all_cases())
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace vssw::stress

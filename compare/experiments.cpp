#include "compare/experiments.hpp"
#include "compare/rounded_corners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall_scene.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/kit/step_resolution.hpp"

namespace vssw::compare {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Step of the one-sided finite difference for q^2 = d theta1''/d theta1 at theta1 = 0, in units of alpha: small
// enough that the curvature of theta1''(theta1) does not matter (relative error ~1e-6), large enough that the
// cancellation at the threshold does not (the terms are O(g), the difference O(1e-6 alpha q^2): ~1e-8 relative).
constexpr double kGrowthStep = 1e-6;
// RK4 steps over a trial's ramp in DepartureFromRest::angle_at: its error (h^4 q^4 ~ 1e-10 at the 0.2 s ramp) far
// below the pointing's own error (the engine's wall is not the analytic one).
constexpr int kRampSteps = 200;
// Where a lift points, to this fraction of the trial's acceleration: a hundredth of the search's rel_tol (1e-4).
constexpr double kPointedTolerance = 1e-6;
// Guided trials of one threshold search before bisection takes over (find_threshold): 3 when the pointing is right
// (measured: the analytic model), up to ~8 for an engine whose wall leaves rest unlike the analytic one; bisection
// of the 2 % first bracket takes 8.
constexpr int kGuidedTrials = 6;

// Before anything reads scene.alpha() or scene.gravity(), which assume one description is set.
void require_scene(const multibody::WallScene& scene) {
    if (scene.vssw.has_value() == scene.parapet.has_value())
        throw InputError("a wall scene must hold exactly one description (a VSSW or a parapet wall)");
}

}  // namespace

GroundMotion ramp_and_hold(double amplitude, double ramp_time, double hold_time) {
    require(std::isfinite(amplitude), "trial ground acceleration", "finite", amplitude);
    require(std::isfinite(ramp_time) && ramp_time > 0.0, "ramp time", "a positive finite time in s", ramp_time);
    require(std::isfinite(hold_time) && hold_time >= 0.0, "hold time", "a finite time >= 0 s", hold_time);
    return GroundMotion::analytic(
        [amplitude, ramp_time](double t) {
            if (t >= ramp_time) return amplitude;
            const double x = t / ramp_time;
            return amplitude * (x - std::sin(2.0 * kPi * x) / (2.0 * kPi));
        },
        // x - sin(2 pi x) / (2 pi) rises monotonically from 0 to 1: the hold is the peak.
        ramp_time + hold_time, {ramp_time}, {std::abs(amplitude), {}},
        fmt::format("ramp to {} m/s^2 over {} s, held {} s", amplitude, ramp_time, hold_time));
}

namespace {

// The wall's departure from rest under a held acceleration just above its threshold, linearised about rest (the
// analytic model, exact kinematics): theta1'' = q2 theta1 + eps k, eps the relative excess over the threshold.
// From rest: theta1(t) = eps k / q2 (cosh(sqrt(q2) t) - 1) (q2 > 0: every rocking wall), else eps k t^2 / 2.
struct DepartureFromRest {
    double q2, k;

    // Toward `side` (+1: theta1 > 0), the side the trials tip it.
    static DepartureFromRest of(const multibody::WallScene& scene, int side) {
        const auto model = analytic_model(scene, Kinematics::exact);
        const double alpha = model->reference_angle();
        const double a_c = model->rest_threshold(0.0, side);
        const ModelTerms rest = model->terms(0.0);
        // Side +1 tips under a_h < 0 (engine.hpp's sign convention); side -1 is its mirror image, the angle and its
        // acceleration negated (exactly, so that a centred N gives side +1's numbers bit for bit).
        const double step = kGrowthStep * alpha, s = side;
        const double q2 = s * (model->acceleration(side, s * step, 0.0, -s * a_c, 0.0) -
                               model->acceleration(side, 0.0, 0.0, -s * a_c, 0.0)) / step;
        return {q2, a_c * rest.X / rest.M};  // k: theta1'' at rest per unit relative excess
    }
    // Time for an excess eps to turn the wall to `angle` [rad].
    double time_to(double angle, double eps) const {
        return q2 > 0.0 ? std::acosh(1.0 + angle * q2 / (eps * k)) / std::sqrt(q2) : std::sqrt(2.0 * angle / (eps * k));
    }
    // theta1 at time t of a trial (ramp_and_hold to `held` over `ramp`), were the threshold `threshold` (same unit):
    // at rest until the ramp passes the threshold, then driven by the excess; the ramp integrated (RK4 at
    // kRampSteps steps: its excess is smooth), the hold in closed form.
    double angle_at(double t, double held, double ramp, double threshold) const {
        auto excess = [&](double time) {
            const double x = std::min(time / ramp, 1.0);
            return std::max(0.0, held * (x - std::sin(2.0 * kPi * x) / (2.0 * kPi)) / threshold - 1.0);
        };
        auto accel = [&](double time, double th) { return excess(time) > 0.0 ? q2 * th + k * excess(time) : 0.0; };
        double th = 0.0, w = 0.0, time = 0.0;
        const double h = std::min(t, ramp) / kRampSteps;
        for (int i = 0; i < kRampSteps; ++i, time += h) {
            const double k1 = accel(time, th), v1 = w;
            const double k2 = accel(time + 0.5 * h, th + 0.5 * h * v1), v2 = w + 0.5 * h * k1;
            const double k3 = accel(time + 0.5 * h, th + 0.5 * h * v2), v3 = w + 0.5 * h * k2;
            const double k4 = accel(time + h, th + h * v3), v4 = w + h * k3;
            th += h / 6.0 * (v1 + 2.0 * v2 + 2.0 * v3 + v4);
            w += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        if (t <= ramp) return th;
        const double e = excess(ramp), tau = t - ramp;
        if (q2 <= 0.0) return th + w * tau + 0.5 * k * e * tau * tau;
        const double om = std::sqrt(q2), shift = k * e / q2;  // theta1 + shift grows as cosh / sinh
        return (th + shift) * std::cosh(om * tau) + w / om * std::sinh(om * tau) - shift;
    }
    // The threshold under which the wall of angle_at turns to `angle` at time t of a trial held at `held`: angle_at
    // inverted (it falls as the threshold rises), by bisection in (0, held) to kPointedTolerance.
    double threshold_for(double angle, double t, double held, double ramp) const {
        double below = 0.0, above = held;  // angle_at(threshold = above) = 0: no excess at all
        while (above - below > kPointedTolerance * held)
            (angle_at(t, held, ramp, 0.5 * (below + above)) > angle ? below : above) = 0.5 * (below + above);
        return 0.5 * (below + above);
    }
};

}  // namespace

int trial_side(const multibody::WallScene& scene, const ThresholdOptions& o) {
    require(o.side == 0 || o.side == 1 || o.side == -1, "threshold trials' side", "-1, 0 or +1", o.side);
    return o.side != 0 ? o.side : analytic_model(scene, Kinematics::exact)->easier_side();
}

double threshold_hold_time(const multibody::WallScene& scene, const ThresholdOptions& o) {
    require(o.rel_tol > 0.0 && o.rel_tol < 0.1, "threshold relative tolerance", "in (0, 0.1)", o.rel_tol);
    require(o.lift_angle > 0.0 && o.lift_angle < 1.0, "lift angle (units of alpha)", "in (0, 1)", o.lift_angle);
    require(o.detectable_excess > 0.0 && o.detectable_excess <= 1.0, "detectable excess (fraction of rel_tol)",
            "in (0, 1]", o.detectable_excess);
    require(o.hold_margin >= 1.0 && std::isfinite(o.hold_margin), "hold margin", ">= 1", o.hold_margin);
    if (o.hold_time > 0.0) return o.hold_time;
    const DepartureFromRest departure = DepartureFromRest::of(scene, trial_side(scene, o));
    return o.hold_margin * departure.time_to(o.lift_angle * scene.alpha(), o.detectable_excess * o.rel_tol);
}

ThresholdResult find_threshold(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                               const ThresholdOptions& o) {
    require_scene(scene);
    require(std::isfinite(o.ramp_time) && o.ramp_time > 0.0, "ramp time", "a positive finite time in s", o.ramp_time);
    require(std::isfinite(o.bracket) && o.bracket > 1.0, "threshold search bracket (factor around the analytic "
            "threshold)", "a finite number > 1", o.bracket);
    require(std::isfinite(o.max_over_estimate) && o.max_over_estimate >= 2.0,
            "threshold search cap (multiple of the analytic threshold)", ">= 2", o.max_over_estimate);
    require(std::isfinite(o.sample_dt) && o.sample_dt >= 0.0, "trial sampling interval", ">= 0 s", o.sample_dt);
    const double hold = threshold_hold_time(scene, o);
    const double g = scene.gravity();
    const double lift = o.lift_angle * scene.alpha();
    const int side = trial_side(scene, o);
    const double estimate_g = analytic_model(scene, Kinematics::exact)->rest_threshold(0.0, side) / g;
    const double push = -side;  // a_h > 0 tips the wall toward theta1 < 0
    const double cap_g = o.max_over_estimate * estimate_g;

    multibody::EngineSettings trial_settings = settings;
    trial_settings.sample_dt = std::max(settings.sample_dt, o.sample_dt);
    ThresholdResult result{kNaN, 0.0, kNaN, 0, hold};
    const DepartureFromRest departure = DepartureFromRest::of(scene, side);
    // The threshold the last trial that lifted points at: the one under which the analytic wall's departure from
    // rest (DepartureFromRest) reaches the lift angle when the engine's wall did.
    double pointed_g = kNaN;
    auto lifts = [&](double a_g) {
        multibody::Excitation ex;
        ex.horizontal = ramp_and_hold(push * a_g * g, o.ramp_time, hold);
        ex.theta0 = 0.0;
        ex.t_end = o.ramp_time + hold;
        ex.stop_at_rest = false;
        ex.stop_angle = lift;  // the trial's question is answered once the wall has lifted
        ex.motion_only = true;  // whether it lifted is read from theta1 alone
        ++result.trials;
        const multibody::Trajectory traj = engine.simulate(scene, ex, trial_settings);
        if (!lifted(traj, lift)) return false;
        pointed_g = traj.samples.empty() ? kNaN
                                         : departure.threshold_for(lift, traj.samples.back().t, a_g, o.ramp_time);
        return true;
    };

    // Bracket around the estimate (ThresholdOptions: why it holds for an engine within its target). The upper end
    // first: when it does not lift, the lower end would not either, and that trial is saved.
    double factor = o.bracket;
    double lo = estimate_g / factor, hi = estimate_g * factor;
    bool lower_known = false;  // lo is a trial that did not lift
    while (!lifts(hi)) {
        lo = hi;
        lower_known = true;  // did not lift: a lower end, the upper end moves out
        if (hi >= cap_g)
            throw multibody::EngineFailure(
                fmt::format("{}: the wall did not lift under a constant ground acceleration of {} g ({:.3g} times the "
                            "analytic model's threshold, {:.4g} g)",
                            engine.name(), lo, lo / estimate_g, estimate_g));
        factor *= factor;
        hi = std::min(estimate_g * factor, cap_g);
    }
    // Narrow [lo, hi] to rel_tol (ThresholdOptions::guided). With a pointed threshold p, the next trial is p (1 - s)
    // until one does not lift (a lower end close below the truth), then p (1 + s) (an upper end close above it), s a
    // quarter of rel_tol: a right p closes the bracket with those two. A trial on either side that fails to close
    // it says p was off that way: s grows fourfold for the next (a lift also moves p nearer, from a smaller excess).
    // Trials stay a quarter of rel_tol inside the bracket; past kGuidedTrials the rest is bisection.
    double spread = 0.25 * o.rel_tol;
    bool below_found = false;  // a guided trial below p did not lift: aim above it now
    int guided_trials = 0;
    auto narrow = [&] {
        while (hi - lo > o.rel_tol * hi) {
            const double margin = 0.25 * o.rel_tol * hi;
            const bool aim = o.guided && std::isfinite(pointed_g) && guided_trials < kGuidedTrials;
            const double trial = aim ? std::clamp(pointed_g * (below_found ? 1.0 + spread : 1.0 - spread),
                                                  lo + margin, hi - margin)
                                     : 0.5 * (lo + hi);
            guided_trials += aim;
            if (lifts(trial)) {
                hi = trial;
                if (aim && !below_found) spread *= 4.0;  // p was too high
                if (aim && below_found) {  // both ends found near p: start again from the lift's new p
                    spread = 0.25 * o.rel_tol;
                    below_found = false;
                }
            } else {
                lo = trial;
                lower_known = true;
                if (aim && below_found) spread *= 4.0;  // p was too low
                below_found = true;
            }
        }
    };
    narrow();
    if (!lower_known) {  // every trial lifted: now the first lower end must not
        factor = o.bracket;
        while (lo > 0.0 && lifts(lo)) {
            hi = lo;  // lifted: an upper end, the lower end moves out
            factor *= factor;
            lo = factor > o.max_over_estimate ? 0.0 : estimate_g / factor;
        }
        narrow();
    }
    result.lower_g = lo;
    result.upper_g = hi;
    result.value_g = 0.5 * (lo + hi);
    return result;
}

namespace {

// The analytic model's free vibration from theta0, impacts and end only. Rounded corners: the sharp wall's (the
// analytic model does not run a rounded wall; a length is all that is read from it).
SimulationResult timing_run(const multibody::WallScene& scene, double theta0) {
    const auto model = analytic_model(with_sharp_corners(scene), Kinematics::exact);
    SimulationOptions opt;
    opt.keep_samples = false;
    return free_vibration(*model, theta0, opt);
}

}  // namespace

double free_vibration_duration(const multibody::WallScene& scene, double theta0, int impacts) {
    require(impacts >= 1, "impacts to show", ">= 1", impacts);
    const SimulationResult r = timing_run(scene, theta0);
    const std::size_t n = static_cast<std::size_t>(impacts);
    if (r.impacts.size() >= n) return 1.25 * r.impacts[n - 1].t;
    return 1.25 * r.t_final;
}

double first_impact_duration(const multibody::WallScene& scene, double theta0) {
    const SimulationResult r = timing_run(scene, theta0);
    if (!r.impacts.empty()) return kFirstImpactMargin * r.impacts.front().t;
    return 1.25 * r.t_final;
}

FreeVibrationResult run_free_vibration(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                                       const FreeVibrationOptions& o) {
    require_scene(scene);
    require(std::isfinite(o.r) && o.r > 0.0, "release angle r (units of alpha)", "a positive finite number", o.r);
    require(std::isfinite(o.t_end) && o.t_end >= 0.0, "free vibration end time", ">= 0 s (0: automatic)", o.t_end);
    FreeVibrationResult out;
    out.theta0 = o.r * scene.alpha();
    multibody::Excitation ex;
    ex.theta0 = out.theta0;
    ex.t_end = o.t_end > 0.0 ? o.t_end : free_vibration_duration(scene, out.theta0, o.impacts);
    ex.stop_at_rest = true;
    ex.motion_only = true;  // the impacts and peaks are read from theta1 and theta1' alone
    out.trajectory = engine.simulate(scene, ex, settings);

    out.impacts = impacts(out.trajectory, o.skip, o.noise_angle);
    out.peaks = peaks(out.trajectory, o.noise_angle);
    if (!out.impacts.empty()) {
        out.quarter_period = out.impacts.front().t - out.trajectory.samples.front().t;
        out.period = 4.0 * *out.quarter_period;
        const ImpactMetric& first = out.impacts.front();
        if (first.resolved && first.ratio > 0.0 && first.ratio <= 1.0) out.restitution = first.ratio;
        else if (first.resolved)
            out.restitution_note = fmt::format(
                "{}: first impact at t = {:.4g} s gives a theta1_dot ratio of {:.10g}, {}, outside (0, 1]: the wall {} "
                "(not a restitution of the rocking model)",
                engine.name(), first.t, first.ratio, first.ratio <= 0.0 ? "at or below 0" : "above 1",
                first.ratio <= 0.0 ? "did not rock onto its other corner" : "gained energy at the impact");
    }
    out.half_cycles = half_cycles(out.impacts);
    out.amplitude = amplitude_restitution(scene, out.impacts, out.peaks);
    return out;
}

void require_threshold_steps(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                             const ThresholdOptions& o) {
    if (engine.name() == "analytic") return;
    multibody::Excitation ex;  // a trial (find_threshold): its amplitude sets no time scale
    const double hold = threshold_hold_time(scene, o);
    ex.horizontal = ramp_and_hold(scene.gravity(), o.ramp_time, hold);
    ex.t_end = o.ramp_time + hold;
    multibody::require_step_resolves(engine.display_name(), scene, ex, settings.dt,
                                     !engine.dt_is_a_reporting_interval());
}

void require_free_vibration_steps(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                                  const FreeVibrationOptions& o) {
    require(std::isfinite(o.r) && o.r > 0.0, "release angle r (units of alpha)", "a positive finite number", o.r);
    if (engine.name() == "analytic") return;
    multibody::Excitation ex;  // run_free_vibration's run
    ex.theta0 = o.r * scene.alpha();
    ex.t_end = o.t_end > 0.0 ? o.t_end : free_vibration_duration(scene, ex.theta0, o.impacts);
    multibody::require_step_resolves(engine.display_name(), scene, ex, settings.dt,
                                     !engine.dt_is_a_reporting_interval());
}

void require_comparison_steps(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene, double r,
                              const ComparisonOptions& options) {
    FreeVibrationOptions free = options.free;
    free.r = r;
    require_free_vibration_steps(engine, settings, scene, free);
    require_threshold_steps(engine, settings, scene, options.threshold);
}

MetricComparison compare_metric(double analytic, double engine) { return {analytic, engine, engine / analytic - 1.0}; }

multibody::EngineSettings analytic_reference_settings() {
    return multibody::AnalyticEngine().default_settings();  // exact kinematics, output every 1e-4 s
}

FreeVibrationComparison free_vibration_with_analytic(const multibody::Engine& engine, const multibody::EngineSettings& settings,
                                                     const multibody::WallScene& scene, const FreeVibrationOptions& options,
                                                     const multibody::EngineSettings& reference) {
    require_scene(scene);
    const multibody::AnalyticEngine analytic;
    FreeVibrationOptions free = options;
    require(std::isfinite(free.r) && free.r > 0.0, "release angle r (units of alpha)", "a positive finite number",
            free.r);
    if (free.t_end <= 0.0) free.t_end = free_vibration_duration(scene, free.r * scene.alpha(), free.impacts);
    return {run_free_vibration(analytic, reference, scene, free),
            run_free_vibration(engine, settings, scene, free)};
}

namespace {

// The amplitude restitution of the first impact, NaN when there is none or it lies outside (0, 1] (see
// FreeVibrationResult::restitution: not a restitution of the rocking model).
double first_amplitude(const FreeVibrationResult& f) {
    if (f.amplitude.empty() || f.amplitude.front().impact != 0) return kNaN;
    const double e = f.amplitude.front().energy;
    return e > 0.0 && e <= 1.0 ? e : kNaN;
}

}  // namespace

EngineComparison compare_with_analytic(const multibody::Engine& engine, const multibody::EngineSettings& settings, const multibody::WallScene& scene,
                                       double r, const ComparisonOptions& options) {
    require_scene(scene);
    require_comparison_steps(engine, settings, scene, r, options);
    const multibody::AnalyticEngine analytic;

    EngineComparison c{};
    c.analytic_threshold = find_threshold(analytic, options.reference, scene, options.threshold);
    c.engine_threshold = find_threshold(engine, settings, scene, options.threshold);
    c.threshold_g = compare_metric(c.analytic_threshold.value_g, c.engine_threshold.value_g);

    FreeVibrationOptions free = options.free;
    free.r = r;
    const double theta0 = r * scene.alpha();
    const FreeVibrationComparison runs = free_vibration_with_analytic(engine, settings, scene, free, options.reference);
    const FreeVibrationResult& a = runs.analytic;
    const FreeVibrationResult& e = runs.engine;
    c.period = compare_metric(a.period.value_or(kNaN), e.period.value_or(kNaN));
    c.restitution = compare_metric(a.restitution.value_or(kNaN), e.restitution.value_or(kNaN));
    c.restitution_amplitude = compare_metric(first_amplitude(a), first_amplitude(e));
    for (const auto* side : {&a, &e}) {
        const std::string who = side == &a ? "analytic model" : engine.name();
        if (!side->period)
            c.failures.push_back(fmt::format("period: the {} reached no impact in the free vibration from {} alpha",
                                             who, r));
        if (!side->restitution_note.empty()) c.failures.push_back("restitution: " + side->restitution_note);
        else if (side->period && !side->restitution)
            c.failures.push_back(fmt::format("restitution: the {}'s first impact is not resolved", who));
        const double amplitude = first_amplitude(*side);
        if (side->period && !std::isfinite(amplitude))
            c.failures.push_back(fmt::format("restitution from peaks: the {} has no peak either side of its first "
                                             "impact, or a ratio outside (0, 1]", who));
    }
    c.analytic_warnings = a.trajectory.warnings;
    c.free_vibration_slip = e.trajectory.slip;
    c.analytic_impacts = static_cast<int>(a.impacts.size());
    c.engine_impacts = static_cast<int>(e.impacts.size());

    if (scene.vssw) {
        const VsswGeometry& w = *scene.vssw;
        c.threshold_closed_form_g = eq12_threshold(w) / w.g;
        c.restitution_closed_form = eq19_restitution(w);
        c.period_linearised = w.N == 0.0 && theta0 < eq21_A(w) ? eq22_period(w, theta0) : kNaN;
    } else {
        const ParapetGeometry& p = *scene.parapet;
        c.threshold_closed_form_g = eq17_parapet_threshold(p) / p.g;
        c.restitution_closed_form = housner_restitution(p.alpha);
        c.period_linearised = p.N == 0.0 && theta0 < p.alpha ? housner_period(p.alpha, p.R, p.g, theta0) : kNaN;
    }
    return c;
}

}  // namespace vssw::compare

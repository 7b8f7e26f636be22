#include "study/measure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "io/text.hpp"
#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/intensity_measures.hpp"
#include "analytic/same_size_parapet.hpp"
#include "analytic/wall_scene.hpp"
#include "compare/experiments.hpp"
#include "compare/case_runner.hpp"
#include "compare/response.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_resolution.hpp"
#include "study/metric_catalog.hpp"

namespace vssw::study {
namespace {

using multibody::EngineFailure;
using multibody::Trajectory;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kOk = "ok";

// The analytic model's trajectory in a pulse or record run is read only for what its located events do not give: a
// sample every 10 ms costs little and keeps the run's energy check at every step.
constexpr double kAnalyticResponseSampleDt = 1e-2;  // [s]

// scale-to-collapse: the scale rises from the one at which the record's PGA equals the wall's rest threshold (below
// it the wall does not even lift) by a relative step per run, as incremental dynamic analysis steps up its intensity;
// the first overturning scale is then bisected against the last standing one. The response is not monotonic in the
// scale (the Fig. 6 VSSW under Rinaldi, exact kinematics: 0.52 overturns it, 0.53 does not, 0.54 does, 0.559 does
// not), so a window of overturning narrower than a step can be stepped over: 2 % steps find Fig. 6's at ~20 runs
// (10 % steps answered 0.576); the study file's `step` trades runs for resolution.
constexpr double kDefaultCollapseStep = 0.02;
constexpr double kDefaultCollapseTolerance = 1e-3;  // relative width of the final bracket on the scale
// Default ceiling of the search: a PGA of this many times the wall's rest threshold (Eq. 12 / 17). Real walls that
// stand up to it do not fall to that record at any credible intensity; the study file's max_pga raises it.
constexpr double kDefaultMaxPgaOverThreshold = 20.0;

std::string failed(const std::string& reason) { return "failed: " + io::one_line(reason); }

// The impact ratio of an analytic run's law on this wall (Fig. 8 follows the run's impact assumption).
double law_restitution(const RunSpec& run, const multibody::WallScene& scene) {
    switch (run.impact.kind) {
        case ImpactLaw::Kind::ratio: return run.impact.ratio;
        case ImpactLaw::Kind::whole_mechanism:
            return scene.vssw ? restitution_whole_mechanism(*scene.vssw) : housner_restitution(scene.parapet->alpha);
        case ImpactLaw::Kind::eq19: break;
    }
    return scene.vssw ? eq19_restitution(*scene.vssw) : housner_restitution(scene.parapet->alpha);
}

// The parapet of the same height, thickness, xi, density and g as the case's VSSW (the paper's comparisons), with
// sharp corners and N at the centre: what the forms that ignore N's position and the corners (Housner's e and period)
// read.
ParapetGeometry same_size_parapet(const VsswGeometry& w) {
    return make_parapet(2.0 * w.h(), 2.0 * w.b, w.xi, w.density, w.g);
}

// The same parapet with N at the VSSW's e/b and its corners rounded to the same r/b, as `vssw wall`'s
// (cli/wall_output.cpp): whose threshold (Eq. 17r / 17e) the VSSW's is compared with. nullopt when that parapet cannot
// stand (N outside its rounded pivot's flat: with_corner_radius refuses it, the r/b itself accepted for the VSSW).
std::optional<ParapetGeometry> same_parapet_with_n_and_corners(const VsswGeometry& w) {
    return parapet_with_n_and_corners(same_size_parapet(w), w.eccentricity, w.corner_radius);
}

// A closed form's value, or a reason it has none here.
struct ClosedForm {
    double value = kNaN;
    std::string why_not;
};

ClosedForm closed_form(const std::string& metric, const CaseSpec& c, const RunSpec& run) {
    const multibody::WallScene& s = c.scene;
    const VsswGeometry* w = s.vssw ? &*s.vssw : nullptr;
    const ParapetGeometry* p = s.parapet ? &*s.parapet : nullptr;
    const auto vssw_only = [&]() -> std::optional<ClosedForm> {
        if (w) return std::nullopt;
        return ClosedForm{kNaN, "a VSSW's comparison with the parapet of its size (this case is a parapet)"};
    };
    const auto needs_theta0 = [&]() -> std::optional<ClosedForm> {
        if (c.theta0 > 0.0) return std::nullopt;
        return ClosedForm{kNaN, "needs theta0 in [excitation]"};
    };
    const auto needs_no_overburden = [&]() -> std::optional<ClosedForm> {
        if (c.xi == 0.0) return std::nullopt;
        return ClosedForm{kNaN, fmt::format("Eq. (20)-(22) are for N = 0 (xi {} here)", c.xi)};
    };
    if (metric == "threshold_closed_form_g") return {closed_form_threshold(s) / s.gravity(), ""};
    if (metric == "restitution_closed_form") return {w ? eq19_restitution(*w) : housner_restitution(p->alpha), ""};
    if (metric == "restitution_whole_mechanism")
        return {w ? restitution_whole_mechanism(*w) : housner_restitution(p->alpha), ""};
    if (metric == "threshold_ratio_to_parapet") {
        if (auto no = vssw_only()) return *no;
        const std::optional<ParapetGeometry> parapet = same_parapet_with_n_and_corners(*w);
        if (!parapet) return {kNaN, "the parapet of this wall's size, xi, e/b and r/b cannot stand"};
        return {eq12_threshold(*w) / eq17_parapet_threshold(*parapet), ""};
    }
    if (metric == "restitution_ratio_to_parapet") {
        if (auto no = vssw_only()) return *no;
        return {eq19_restitution(*w) / housner_restitution(same_size_parapet(*w).alpha), ""};
    }
    if (auto no = needs_theta0()) return *no;
    if (auto no = needs_no_overburden()) return *no;
    // Amplitude-dependent forms, at theta0 as a fraction of A (VSSW, Eq. 21a) or alpha (parapet).
    const double A = w ? eq21_A(*w) : p->alpha;
    if (metric == "period_linearised") {
        if (w) {
            const double theta = c.theta0 * w->alpha1;
            if (!(theta < A)) return {kNaN, fmt::format("theta0 {} alpha1 is beyond Eq. (21a)'s A", c.theta0)};
            return {eq22_period(*w, theta), ""};
        }
        return {housner_period(p->alpha, p->R, p->g, c.theta0 * p->alpha), ""};
    }
    if (metric == "period_ratio_to_parapet") {
        if (auto no = vssw_only()) return *no;
        if (!(c.theta0 < 1.0)) return {kNaN, fmt::format("theta0 {} is not below A and alpha (Eq. 22 and Housner's period)", c.theta0)};
        const ParapetGeometry pw = same_size_parapet(*w);
        return {eq22_period(*w, c.theta0 * A) / housner_period(pw.alpha, pw.R, pw.g, c.theta0 * pw.alpha), ""};
    }
    if (metric == "peak_ratio_half_cycle") {
        // Eq. (20) conserves (1/2) theta1'^2 + P^2 (A theta1 - theta1^2 / 2) in flight; the impact multiplies the
        // velocity by e. With u = theta_peak / A: u_next (2 - u_next) = e^2 u (2 - u), so
        // u_next = 1 - sqrt(1 - e^2 u (2 - u)), and the ratio of the peaks is u_next / u.
        const double u = c.theta0 * (w ? w->alpha1 : p->alpha) / A;
        if (!(u < 1.0)) return {kNaN, fmt::format("theta0 {} alpha is beyond Eq. (21a)'s A", c.theta0)};
        const double e = law_restitution(run, s);
        return {(1.0 - std::sqrt(1.0 - e * e * u * (2.0 - u))) / u, ""};
    }
    throw InputError(fmt::format("'{}' is not a closed form", metric));
}

using compare::Response;
using compare::response_of;

GroundMotion case_motion(const Grid& grid, const CaseSpec& c, double scale) {
    switch (grid.spec().parts[c.part].kind) {
        case ExcitationKind::pulse: return pulse_motion(c);
        case ExcitationKind::record:
        case ExcitationKind::scale_to_collapse: return grid.record(c).scaled(scale);
        default: return GroundMotion::none();
    }
}

// The finite-friction metrics (compare/metric_catalog.cpp) of a run: NaN (empty) where the run has none, nullopt for
// another metric.
std::optional<double> friction_metric(const std::string& metric, const compare::Response& r) {
    const auto slip = [&](double multibody::SlipMeasures::*field) {
        return r.slip ? (*r.slip).*field / r.slip->b : kNaN;
    };
    if (metric == "base_slip") return slip(&multibody::SlipMeasures::base_largest);
    if (metric == "hinge_slip") return slip(&multibody::SlipMeasures::hinge_largest);
    if (metric == "residual_base_slip") return slip(&multibody::SlipMeasures::base_residual);
    if (metric == "residual_hinge_slip") return slip(&multibody::SlipMeasures::hinge_residual);
    if (metric == "slid_before_rocking") return r.slip ? (r.slip->slid_before_rocking() ? 1.0 : 0.0) : kNaN;
    if (metric == "base_friction_needed") return r.base_friction_needed.value_or(kNaN);
    if (metric == "hinge_friction_needed") return r.hinge_friction_needed.value_or(kNaN);
    return std::nullopt;
}

// The response metrics that follow the wall's rocking to the run's end (not its slips).
bool is_rocking_metric(const std::string& metric) {
    return metric == "peak_rotation" || metric == "peak_time" || metric == "overturned" || metric == "t_overturn";
}

// A response metric's row from a run: its value and status (nullopt: not a response metric).
std::optional<std::pair<double, std::string>> response_row(const std::string& metric, const compare::Response& r,
                                                           double alpha) {
    // A wall that slid off its support ended its run there: its rocking (peak, overturning) was not followed to the
    // end, so those metrics fail with the reason; the slips stay measured.
    if (r.slip && r.slip->slid_off && is_rocking_metric(metric)) return std::pair{kNaN, failed(*r.slip->slid_off)};
    std::optional<double> v;
    if (metric == "peak_rotation") v = r.peak / alpha;
    else if (metric == "peak_time") v = r.peak_time;
    else if (metric == "overturned") v = r.overturned ? 1.0 : 0.0;
    else if (metric == "t_overturn") v = r.t_overturn.value_or(kNaN);
    else if (metric == "energy_balance_error") v = r.energy_error.value_or(kNaN);
    else if (metric == "roller_tension_time") v = r.tension_at.value_or(kNaN);
    else v = friction_metric(metric, r);
    if (!v) return std::nullopt;
    return std::pair{*v, std::string(kOk)};
}

// A run's warnings: the analytic model's own, or an engine's wall that slid off its support, which ended the run
// there (multibody::SlipMeter).
std::vector<std::string> warnings_of(const Trajectory& t) {
    std::vector<std::string> w = t.warnings;
    if (t.slip && t.slip->slid_off) w.push_back(*t.slip->slid_off);
    return w;
}

// Why a free vibration has no first impact: the wall overturned, slid off its support (which ended the run), or did
// not come back within the run.
std::string no_impact_reason(const Trajectory& t) {
    if (t.overturned) return "no impact: the wall overturned";
    if (t.slip && t.slip->slid_off) return "no impact: " + *t.slip->slid_off;
    return "no impact within the run";
}

Trajectory run_from_rest(const multibody::Engine& engine, const RunSpec& run, const CaseSpec& c,
                         const GroundMotion& motion) {
    multibody::Excitation ex;
    ex.horizontal = motion;
    ex.theta0 = 0.0;
    ex.t_end = motion.duration() + c.response_tail;
    ex.stop_at_rest = true;
    ex.motion_only = true;  // the response metrics are read from theta1 alone
    multibody::EngineSettings settings = run.settings;
    if (run.engine == "analytic") settings.sample_dt = kAnalyticResponseSampleDt;
    // The band's impact ratio changed (a perturbation only the analytic model runs: Grid::run_applies).
    if (const double e = band_factors(c.perturbation).restitution_error; e != 0.0)
        settings.knobs[multibody::kRestitutionErrorKnob] = e;
    return engine.simulate(c.scene, ex, settings);
}

// The smallest scale of the record that overturns the wall: stepped up from lift-off, then bisected. Without one, why
// not: it overturned at the first scale run (`first`), or stood up to the last scale run below max_pga (`standing`).
struct Collapse {
    double scale = kNaN;
    enum class Miss { none, at_first, standing, failed } miss = Miss::none;
    double at = kNaN;         // at_first, standing: that scale
    double max_pga_g = kNaN;  // the search's ceiling [g]
    double threshold_g = kNaN;  // the wall's rest threshold [g], the PGA of the first scale run
    std::string why_not;      // failed: the reason
    std::vector<IdaPoint> points;  // every run of the search, in the order run
};
Collapse collapse_scale(const Grid& grid, const CaseSpec& c, const RunSpec& run, const multibody::Engine& engine) {
    const GroundMotion& record = grid.record(c);
    const double pga = record.pga();  // [m/s^2] at scale 1
    const double threshold = analytic_model(c.scene, Kinematics::exact)->rest_threshold(0.0);
    const double max_pga = c.max_pga_g > 0.0 ? c.max_pga_g * kStandardGravity : kDefaultMaxPgaOverThreshold * threshold;
    const double tolerance = c.tolerance > 0.0 ? c.tolerance : kDefaultCollapseTolerance;
    Collapse out;
    const auto overturns = [&](double scale) {
        const Response r = response_of(run_from_rest(engine, run, c, case_motion(grid, c, scale)), c.scene);
        // Off its support the wall neither stood nor overturned: the search cannot go on (multibody::SlipMeter).
        if (r.slip && r.slip->slid_off)
            throw EngineFailure(fmt::format("at scale {:.6g}: {}", scale, *r.slip->slid_off));
        out.points.push_back({scale, r.peak / c.scene.alpha(), r.overturned});
        return r.overturned;
    };
    double lo = threshold / pga, hi = kNaN;
    out.max_pga_g = max_pga / kStandardGravity;
    out.threshold_g = threshold / kStandardGravity;
    if (overturns(lo)) {
        out.miss = Collapse::Miss::at_first;
        out.at = lo;
        return out;
    }
    const double step = c.step > 0.0 ? c.step : kDefaultCollapseStep;
    for (double s = lo * (1.0 + step);; s *= 1.0 + step) {
        // The scale named is the last one run and found standing (the next step would pass max_pga): where a
        // fragility fit censors the record.
        if (s * pga > max_pga) {
            out.miss = Collapse::Miss::standing;
            out.at = lo;
            return out;
        }
        if (overturns(s)) {
            hi = s;
            break;
        }
        lo = s;
    }
    while (hi - lo > tolerance * hi) {
        const double mid = 0.5 * (lo + hi);
        (overturns(mid) ? hi : lo) = mid;
    }
    out.scale = hi;
    return out;
}

// A collapse metric's value at `scale`: the scale itself, or the record's intensity measure there (collapse_pga,
// collapse_pgv, collapse_sa, collapse_arias), with its name and unit for a status.
struct CollapseMeasure {
    double value = kNaN;
    std::string name, unit;
};
CollapseMeasure collapse_measure(const std::string& metric, const GroundMotion& record, const CaseSpec& c,
                                 double scale) {
    if (metric == "collapse_scale") return {scale, "scale", ""};
    Intensity im = c.intensity;
    im.measure = parse_intensity_measure(metric.substr(std::string("collapse_").size()));
    const std::string name = im.measure == IntensityMeasure::pga     ? "PGA"
                             : im.measure == IntensityMeasure::pgv   ? "PGV"
                             : im.measure == IntensityMeasure::arias ? "Arias intensity"
                                                                     : intensity_name(im);
    // The PGA as it always was (record.pga() in m/s^2 over g0, times the scale): its rows stay the same bytes.
    const double value = im.measure == IntensityMeasure::pga
                             ? scale * record.pga() / kStandardGravity
                             : intensity_at_scale(im.measure, record_intensity(record, im), scale);
    return {value, name, intensity_unit(im.measure)};
}

// A collapse metric's row: its value, or why there is none, in the metric's own measure (the fragility reads a
// standing record's last value from it: study/ensemble_measures.cpp).
std::pair<double, std::string> collapse_row(const std::string& metric, const Collapse& k, const GroundMotion& record,
                                            const CaseSpec& c) {
    switch (k.miss) {
        case Collapse::Miss::none: return {collapse_measure(metric, record, c, k.scale).value, kOk};
        case Collapse::Miss::failed: return {kNaN, failed(k.why_not)};
        case Collapse::Miss::at_first: {
            const double threshold_g = k.threshold_g;
            if (metric == "collapse_pga" || metric == "collapse_scale")
                return {kNaN, failed(fmt::format("overturns at the scale where the record's PGA equals the rest "
                                                 "threshold ({:.6g} g)",
                                                 threshold_g))};
            const CollapseMeasure m = collapse_measure(metric, record, c, k.at);
            return {kNaN, failed(fmt::format("overturns at the scale where the record's PGA equals the rest threshold "
                                             "({:.6g} g; {:.6g} {} in {})",
                                             threshold_g, m.value, m.unit, m.name))};
        }
        case Collapse::Miss::standing: {
            const CollapseMeasure m = collapse_measure(metric == "collapse_scale" ? "collapse_pga" : metric, record, c, k.at);
            return {kNaN, failed(fmt::format("does not overturn up to a {} of {:.6g} {} (the last run below max_pga "
                                             "{:.4g} g)",
                                             m.name, m.value, m.unit, k.max_pga_g))};
        }
    }
    return {kNaN, kOk};
}

// Whether measure() gives `metric` a row for this run: the part measures it, the run's backend has it (the analytic
// model's own metrics are left out for an engine), and it is not threshold_g (a task of its own).
bool reports(const PartSpec& part, const RunSpec& run, const std::string& metric) {
    const compare::MetricInfo& info = metric_info(metric);
    if (info.analytic_only && run.engine != "analytic") return false;
    if (info.source == compare::MetricSource::threshold) return false;
    return std::find(part.metrics.begin(), part.metrics.end(), metric) != part.metrics.end();
}

std::size_t threshold_metric(const Grid& grid) {
    const std::vector<std::string>& metrics = grid.spec().metrics;
    return static_cast<std::size_t>(std::find(metrics.begin(), metrics.end(), "threshold_g") - metrics.begin());
}

}  // namespace

void require_run_resolves(const Grid& grid, const CaseSpec& c, const RunSpec& run, const multibody::Engine& engine) {
    if (engine.name() == "analytic") return;  // its dt is the sampling only, and it has no wall rule to meet
    multibody::require_settings_fit_wall(engine.display_name(), run.settings, engine.setting_descriptions(), c.scene);
    const ExcitationKind kind = grid.spec().parts[c.part].kind;
    if (kind == ExcitationKind::pulse || kind == ExcitationKind::record || kind == ExcitationKind::scale_to_collapse) {
        multibody::Excitation ex;
        ex.horizontal = case_motion(grid, c, c.scale);
        ex.t_end = ex.horizontal.duration() + c.response_tail;
        multibody::require_step_resolves(engine.display_name(), c.scene, ex, run.settings.dt,
                                         !engine.dt_is_a_reporting_interval());
    }
    if (kind == ExcitationKind::free) {
        compare::FreeVibrationOptions free;  // as measure() runs it
        free.r = c.theta0;
        compare::require_free_vibration_steps(engine, run.settings, c.scene, free);
    }
    if (measures_threshold(grid, c)) compare::require_threshold_steps(engine, run.settings, c.scene);
}

void require_runs_resolve(const Grid& grid, const std::vector<int>& case_ids) {
    std::vector<std::unique_ptr<multibody::Engine>> engines;
    for (const RunSpec& run : grid.runs()) engines.push_back(multibody::make_engine(run.engine));
    for (const int id : case_ids) {
        const CaseSpec c = grid.make_case(id);
        for (std::size_t r = 0; r < grid.runs().size(); ++r) {
            const RunSpec& run = grid.runs()[r];
            if (!grid.run_applies(run, c)) continue;
            try {
                require_run_resolves(grid, c, run, *engines[r]);
            } catch (const InputError& e) {
                throw InputError(fmt::format("case {} ({} {}): {}", id, run.engine, run.settings_text, e.what()));
            }
        }
    }
}

Measurement measure_threshold(const Grid& grid, const CaseSpec& c, std::size_t run_index,
                              const multibody::Engine& engine) {
    const std::size_t m = threshold_metric(grid);
    // A rounded wall's threshold is the analytic model's closed form, Eq. (12r) / (17r): it cannot simulate the
    // rolling blocks (docs/model/analytic-core.md, "Rounded corners"), so the bisection's trials would all refuse.
    if (engine.name() == "analytic" && c.scene.corner_radius() > 0.0)
        return {m, analytic_model(c.scene, Kinematics::exact)->rest_threshold(0.0) / c.scene.gravity(), kOk, {}};
    try {
        return {m, compare::find_threshold(engine, grid.runs().at(run_index).settings, c.scene).value_g, kOk, {}};
    } catch (const EngineFailure& e) {
        return {m, kNaN, failed(e.what()), {}};
    } catch (const InputError& e) {
        return {m, kNaN, failed(e.what()), {}};
    }
}

bool measures_threshold(const Grid& grid, const CaseSpec& c) {
    const std::vector<std::string>& metrics = grid.spec().parts[c.part].metrics;
    return std::find(metrics.begin(), metrics.end(), "threshold_g") != metrics.end();
}

std::vector<Measurement> measure(const Grid& grid, const CaseSpec& c, std::size_t run_index,
                                 const multibody::Engine& engine, std::vector<IdaPoint>* ida) {
    const StudySpec& spec = grid.spec();
    const PartSpec& part = spec.parts[c.part];
    const RunSpec& run = grid.runs().at(run_index);
    const double alpha = c.scene.alpha();
    std::vector<Measurement> out;
    const auto add = [&](std::size_t m, double value, std::string status) {
        out.push_back({m, value, std::move(status), {}});
    };

    // Each source runs at most once, on the first metric that needs it.
    std::optional<compare::FreeVibrationResult> free;
    std::string free_failure;
    std::optional<Response> response;
    std::optional<std::vector<std::string>> response_warnings;
    std::string response_failure;
    std::optional<Collapse> collapse;

    const auto run_free = [&] {
        compare::FreeVibrationOptions o;
        o.r = c.theta0;
        free = compare::run_free_vibration(engine, run.settings, c.scene, o);
    };
    const auto guarded = [](auto&& body, std::string& failure) {
        try {
            body();
        } catch (const EngineFailure& e) {
            failure = e.what();
        } catch (const InputError& e) {  // a case the run cannot hold (e.g. beyond the paper kinematics' lock)
            failure = e.what();
        }
    };

    for (std::size_t m = 0; m < spec.metrics.size(); ++m) {
        const std::string& metric = spec.metrics[m];
        if (!reports(part, run, metric)) continue;
        switch (metric_info(metric).source) {
            case compare::MetricSource::closed_form: {
                ClosedForm f;
                try {
                    f = closed_form(metric, c, run);
                } catch (const InputError& e) {  // a formula outside its range is a row with the reason, not the end
                    f = {kNaN, e.what()};
                }
                add(m, f.value, f.why_not.empty() ? kOk : failed(f.why_not));
                break;
            }
            case compare::MetricSource::threshold: break;  // not reached (reports()): measure_threshold, a task of its own
            case compare::MetricSource::free: {
                if (!free && free_failure.empty()) guarded(run_free, free_failure);
                if (!free) {
                    add(m, kNaN, failed(free_failure));
                } else if (metric == "period") {
                    if (free->period) add(m, *free->period, kOk);
                    else add(m, kNaN, failed(no_impact_reason(free->trajectory)));
                } else {  // restitution
                    if (free->restitution) add(m, *free->restitution, kOk);
                    else if (!free->restitution_note.empty()) add(m, kNaN, failed(free->restitution_note));
                    else add(m, kNaN, failed(free->period ? "the first impact is not resolved by the samples"
                                                          : no_impact_reason(free->trajectory)));
                }
                break;
            }
            case compare::MetricSource::response: {
                if (!response && response_failure.empty())
                    guarded(
                        [&] {
                            if (part.kind == ExcitationKind::free) {
                                if (!free && free_failure.empty()) run_free();
                                if (!free) throw EngineFailure(free_failure);
                                response = response_of(free->trajectory, c.scene);
                            } else {
                                const Trajectory t = run_from_rest(engine, run, c, case_motion(grid, c, c.scale));
                                response = response_of(t, c.scene);
                                response_warnings = warnings_of(t);
                            }
                        },
                        response_failure);
                if (!response) {
                    add(m, kNaN, failed(response_failure));
                    break;
                }
                if (auto row = response_row(metric, *response, alpha)) add(m, row->first, std::move(row->second));
                break;
            }
            case compare::MetricSource::collapse: {
                std::string failure;
                if (!collapse) {
                    guarded([&] { collapse = collapse_scale(grid, c, run, engine); }, failure);
                    if (!collapse) {
                        collapse = Collapse{};
                        collapse->miss = Collapse::Miss::failed;
                        collapse->why_not = failure;
                    }
                }
                auto [value, status] = collapse_row(metric, *collapse, grid.record(c), c);
                add(m, value, std::move(status));
                break;
            }
        }
    }
    if (ida && collapse) *ida = collapse->points;
    // The analytic model's warnings from the run the rows come from (a threshold's trials have none to report).
    std::vector<std::string> warnings;
    if (free) warnings = warnings_of(free->trajectory);
    if (response_warnings) warnings = *response_warnings;
    std::string joined;
    for (const std::string& w : warnings) joined += (joined.empty() ? "" : "; ") + io::one_line(w);
    for (Measurement& m : out) m.warnings = joined;
    return out;
}

double simulated_seconds(const Grid& grid, const CaseSpec& c) {
    // Roughly: a free vibration a few seconds; a pulse or a record its duration and the tail; a collapse search ~35
    // such runs.
    constexpr double kFreeSeconds = 5.0;
    constexpr double kCollapseRuns = 35.0;
    const PartSpec& part = grid.spec().parts[c.part];
    const auto motion_seconds = [&] {
        return part.kind == ExcitationKind::pulse ? 3.0 * c.pulse_period + c.duration + c.response_tail
                                                  : compare::response_seconds(grid.record(c), c.response_tail);
    };
    double seconds = 0.0;
    for (const std::string& metric : part.metrics) {
        switch (metric_info(metric).source) {
            case compare::MetricSource::closed_form: break;
            case compare::MetricSource::threshold: break;  // a task of its own (compare::threshold_seconds)
            case compare::MetricSource::free: seconds += kFreeSeconds; break;
            case compare::MetricSource::response:
                seconds += part.kind == ExcitationKind::free ? kFreeSeconds : motion_seconds();
                break;
            case compare::MetricSource::collapse: seconds += kCollapseRuns * motion_seconds(); break;
        }
    }
    return seconds;
}

}  // namespace vssw::study

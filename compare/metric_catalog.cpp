#include "compare/metric_catalog.hpp"

#include "compare/targets.hpp"

namespace vssw::compare {

const std::vector<MetricInfo>& metric_catalog() {
    using S = MetricSource;
    using U = SuiteMeasure;
    static const std::vector<MetricInfo> catalog = {
        {"threshold_g", "g", true, S::threshold, false,
         "smallest constant ground acceleration that lifts the wall off rest (bisection on simulations, 1e-4)",
         U::threshold, false, "threshold acceleration", "threshold",
         "The smallest constant ground acceleration (in g, ramped in over 0.2 s, then held) that rotates the "
         "wall by 1 % of alpha off rest, found by bisection to 1e-4 for every backend alike, the analytic "
         "model's too (its closed form is Eq. (12), Eq. (17) for the parapet): an error of 0 means the same "
         "bisection bracket, i.e. within 1e-4.",
         kThresholdTarget},
        {"period", "s", true, S::free, false, "4 x the time from the release at theta0 to the first impact",
         U::free, false, "period", nullptr,
         "Four times the time from release at rest at theta1 = r alpha to the first impact (theta1 "
         "interpolated linearly across zero), against the analytic model with exact kinematics.",
         kPeriodTarget},
        {"restitution", "", true, S::free, false, "theta1' after / before the first impact of the free vibration",
         U::free, false, "restitution (first impact)", "restitution",
         "theta1' after over before the first impact, each extrapolated to the crossing from samples outside "
         "2 steps either side; the reference is the analytic model's impact under the report's assumption set: "
         "for the VSSW the whole mechanism's plastic impact, the roller acting (set mechanism, the default), or "
         "Eq. (19) (set paper); Housner's e for the parapet under either.",
         kRestitutionTarget},
        {"peak_rotation", "alpha1", true, S::response, false,
         "largest |theta1| / alpha1 (|theta| / alpha of a parapet) of the run; the collapse angle if it overturned",
         U::history, false, "peak rotation", "peak rotation",
         "The largest |theta1| / alpha under a ground-motion record, from rest; for an overturned run the collapse "
         "angle at which it was judged overturned, as in studies and vssw history.",
         0.0},
        {"peak_time", "s", true, S::response, false, "when the peak rotation was reached",
         U::history, false, "time of the peak rotation", "peak time",
         "When the largest |theta1| is reached under a ground-motion record; the overturning for an overturned "
         "run.",
         0.0},
        {"overturned", "", true, S::response, false, "1 if the wall reached its collapse angle, else 0",
         U::history, false, "overturning", nullptr,
         "Whether the wall overturns under a ground-motion record; the error column says whether the engine "
         "agrees with the analytic model.",
         0.0},
        {"t_overturn", "s", true, S::response, false, "when it overturned (empty if it did not)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"roller_tension_time", "s", true, S::response, true,
         "first time the paper's bilateral roller would have to pull (empty if it never does, or for a parapet)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"base_slip", "b", true, S::response, false,
         "largest slip at the base over the run, in b (engines, with friction given; empty otherwise)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"hinge_slip", "b", true, S::response, false,
         "largest slip at the hinge over the run, in b (engines, with friction given; empty otherwise)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"residual_base_slip", "b", true, S::response, false,
         "the base's slip at the run's end, signed along +x, in b (engines, with friction given)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"residual_hinge_slip", "b", true, S::response, false,
         "the hinge's slip at the run's end, signed along the lower block's top face, in b (engines, friction given)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"slid_before_rocking", "", true, S::response, false,
         "1 if a slip passed 1e-3 b before |theta1| passed 1e-3 alpha, else 0 (engines, with friction given)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"base_friction_needed", "", true, S::response, true,
         "largest |T|/N at the base while it pushes: the friction the no-sliding model needs (a VSSW)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"hinge_friction_needed", "", true, S::response, true,
         "largest |T|/N at the hinge while it pushes: the friction the no-sliding model needs (a VSSW)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"energy_balance_error", "", true, S::response, true,
         "the run's largest energy balance residual over the largest energy in play",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"collapse_scale", "", true, S::collapse, false,
         "smallest factor on the record that overturns the wall (stepped up from lift-off, then bisected)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"collapse_pga", "g", true, S::collapse, false, "the peak ground acceleration of the record at collapse_scale",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"collapse_pgv", "m/s", true, S::collapse, false,
         "the peak ground velocity of the record at collapse_scale (trapezoidal, from rest)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"collapse_sa", "g", true, S::collapse, false,
         "the record's pseudo-spectral acceleration at sa_period and sa_damping (default 0.05) at collapse_scale",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"collapse_arias", "m/s", true, S::collapse, false,
         "the record's Arias intensity at collapse_scale (it grows with the scale's square)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"threshold_closed_form_g", "g", true, S::closed_form, true, "Eq. (12) for a VSSW, Eq. (17) for a parapet",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"restitution_closed_form", "", true, S::closed_form, true, "Eq. (19) for a VSSW, Housner's e for a parapet",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"restitution_whole_mechanism", "", true, S::closed_form, true,
         "the whole mechanism's plastic impact, the roller acting (Housner's e for a parapet)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"period_linearised", "s", true, S::closed_form, true,
         "Eq. (22) (Housner's for a parapet) at theta0; empty with an overburden or theta0 beyond A",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"threshold_ratio_to_parapet", "", true, S::closed_form, true,
         "Eq. (12) over Eq. (17) of the parapet of the same height, thickness and xi (Fig. 3b; Eq. 18 at Eq. 15)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"restitution_ratio_to_parapet", "", true, S::closed_form, true,
         "Eq. (19) over Housner's e of the parapet of the same height and thickness (Fig. 5b)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"period_ratio_to_parapet", "", true, S::closed_form, true,
         "Eq. (22) at theta0 A over Housner's period at theta0 alpha of the same-size parapet (Fig. 7b; N = 0)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        {"peak_ratio_half_cycle", "", true, S::closed_form, true,
         "ratio of two peaks half a cycle apart from theta0, Eq. (20) with the run's impact law (Fig. 8; N = 0)",
         U::none, false, nullptr, nullptr, nullptr, 0.0},
        // The suite's own: both need the analytic run beside the engine's.
        {"rms_difference", "alpha1", false, S::response, false, "", U::history, false,
         "rms difference of the time histories", "rms difference",
         "The root mean square over the record of the difference between the engine's and the analytic "
         "model's theta1 / alpha. The reference column is the analytic peak rotation (in alpha), the engine "
         "column the rms difference (in alpha), the error column their ratio.",
         0.0},
    };
    return catalog;
}

const MetricInfo* find_metric(const std::string& name) {
    for (const MetricInfo& m : metric_catalog())
        if (name == m.name) return &m;
    return nullptr;
}

std::vector<const MetricInfo*> suite_metrics() {
    std::vector<const MetricInfo*> out;
    for (const SuiteMeasure kind : {SuiteMeasure::threshold, SuiteMeasure::free, SuiteMeasure::history})
        for (const MetricInfo& m : metric_catalog())
            if (m.suite == kind) out.push_back(&m);
    return out;
}

}  // namespace vssw::compare

#include "study/metric_catalog.hpp"

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::study {

const std::vector<MetricInfo>& metric_catalog() {
    using S = MetricSource;
    static const std::vector<MetricInfo> catalog = {
        {"threshold_g", "g", S::threshold, false,
         "smallest constant ground acceleration that lifts the wall off rest (bisection on simulations, 1e-4)"},
        {"period", "s", S::free, false, "4 x the time from the release at theta0 to the first impact"},
        {"restitution", "", S::free, false, "theta1' after / before the first impact of the free vibration"},
        {"peak_rotation", "alpha", S::response, false,
         "largest |theta1| / alpha1 (|theta| / alpha of a parapet) of the run; the collapse angle if it overturned"},
        {"peak_time", "s", S::response, false, "when the peak rotation was reached"},
        {"overturned", "", S::response, false, "1 if the wall reached its collapse angle, else 0"},
        {"t_overturn", "s", S::response, false, "when it overturned (empty if it did not)"},
        {"roller_tension_time", "s", S::response, true,
         "first time the paper's bilateral roller would have to pull (empty if it never does, or for a parapet)"},
        {"energy_balance_error", "", S::response, true,
         "the run's largest energy balance residual over the largest energy in play"},
        {"collapse_scale", "", S::collapse, false,
         "smallest factor on the record that overturns the wall (stepped up from lift-off, then bisected)"},
        {"collapse_pga", "g", S::collapse, false, "the peak ground acceleration of the record at collapse_scale"},
        {"threshold_closed_form_g", "g", S::closed_form, true, "Eq. (12) for a VSSW, Eq. (17) for a parapet"},
        {"restitution_closed_form", "", S::closed_form, true, "Eq. (19) for a VSSW, Housner's e for a parapet"},
        {"restitution_whole_mechanism", "", S::closed_form, true,
         "the whole mechanism's plastic impact, the roller acting (Housner's e for a parapet)"},
        {"period_linearised", "s", S::closed_form, true,
         "Eq. (22) (Housner's for a parapet) at theta0; empty with an overburden or theta0 beyond A"},
        {"threshold_ratio_to_parapet", "", S::closed_form, true,
         "Eq. (12) over Eq. (17) of the parapet of the same height, thickness and xi (Fig. 3b; Eq. 18 at Eq. 15)"},
        {"restitution_ratio_to_parapet", "", S::closed_form, true,
         "Eq. (19) over Housner's e of the parapet of the same height and thickness (Fig. 5b)"},
        {"period_ratio_to_parapet", "", S::closed_form, true,
         "Eq. (22) at theta0 A over Housner's period at theta0 alpha of the same-size parapet (Fig. 7b; N = 0)"},
        {"peak_ratio_half_cycle", "", S::closed_form, true,
         "ratio of two peaks half a cycle apart from theta0, Eq. (20) with the run's impact law (Fig. 8; N = 0)"},
    };
    return catalog;
}

const MetricInfo& metric_info(const std::string& name) {
    for (const MetricInfo& m : metric_catalog())
        if (name == m.name) return m;
    std::vector<std::string> known;
    for (const MetricInfo& m : metric_catalog()) known.push_back(m.name);
    throw InputError(fmt::format("unknown metric '{}' (known: {})", name, fmt::join(known, ", ")));
}

bool kind_measures(ExcitationKind kind, const MetricInfo& metric) {
    switch (metric.source) {
        case MetricSource::closed_form: return true;
        case MetricSource::threshold: return kind != ExcitationKind::closed_form;
        case MetricSource::free: return kind == ExcitationKind::free;
        case MetricSource::response:
            return kind == ExcitationKind::free || kind == ExcitationKind::pulse || kind == ExcitationKind::record;
        case MetricSource::collapse: return kind == ExcitationKind::scale_to_collapse;
    }
    return false;
}

std::vector<std::string> default_metrics(ExcitationKind kind) {
    switch (kind) {
        case ExcitationKind::closed_form: return {};
        case ExcitationKind::threshold: return {"threshold_g"};
        case ExcitationKind::free: return {"period", "restitution", "peak_rotation"};
        case ExcitationKind::pulse:
        case ExcitationKind::record: return {"peak_rotation", "overturned"};
        case ExcitationKind::scale_to_collapse: return {"collapse_scale", "collapse_pga"};
    }
    return {};
}

}  // namespace vssw::study

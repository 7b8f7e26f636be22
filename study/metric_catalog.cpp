#include "study/metric_catalog.hpp"

#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::study {

const std::vector<compare::MetricInfo>& metric_catalog() {
    static const std::vector<compare::MetricInfo> catalog = [] {
        std::vector<compare::MetricInfo> out;
        for (const compare::MetricInfo& m : compare::metric_catalog())
            if (m.in_study) out.push_back(m);
        return out;
    }();
    return catalog;
}

const compare::MetricInfo& metric_info(const std::string& name) {
    // The names measured once: a study looks each of its metrics up for every task.
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> out;
        for (const compare::MetricInfo& m : metric_catalog()) out.emplace_back(m.name);
        return out;
    }();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return metric_catalog()[i];
    throw InputError(fmt::format("unknown metric '{}' (known: {})", name, fmt::join(names, ", ")));
}

bool kind_measures(ExcitationKind kind, const compare::MetricInfo& metric) {
    switch (metric.source) {
        case compare::MetricSource::closed_form: return true;
        case compare::MetricSource::threshold: return kind != ExcitationKind::closed_form;
        case compare::MetricSource::free: return kind == ExcitationKind::free;
        case compare::MetricSource::response:
            return kind == ExcitationKind::free || kind == ExcitationKind::pulse || kind == ExcitationKind::record;
        case compare::MetricSource::collapse: return kind == ExcitationKind::scale_to_collapse;
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

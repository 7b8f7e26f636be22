#pragma once
// Every metric a study can ask for: its name (a results.csv `metric`), unit, what produces it, and whether only the
// analytic model has it. One table read by the study file's checks, the runner, the writers and `vssw study --help`.
#include <string>
#include <vector>

#include "study/spec.hpp"

namespace vssw::study {

enum class MetricSource {
    closed_form,  // a formula of the paper (or Housner's) on the case's wall: no simulation
    threshold,    // find_threshold (compare/experiments.hpp): bisection on simulated constant accelerations
    free,         // a free vibration from theta0 (kind = free)
    response,     // the case's run: a free vibration, a pulse or a record from rest
    collapse,     // the smallest scale of a record that overturns the wall (kind = scale-to-collapse)
};

struct MetricInfo {
    const char* name;
    const char* unit;        // "g", "s", "alpha" (theta1 / alpha1, or theta / alpha of a parapet), "" (a ratio)
    MetricSource source;
    bool analytic_only;      // rows only for the analytic model (its own checks and closed forms)
    const char* description; // one line for --help, study.md and results.json
};

const std::vector<MetricInfo>& metric_catalog();
// InputError naming the metric and listing the known ones.
const MetricInfo& metric_info(const std::string& name);
// Whether an excitation of this kind can give the metric (closed forms: every kind).
bool kind_measures(ExcitationKind kind, const MetricInfo& metric);
// What a study of this kind measures when its file names no metrics (closed-form studies must name theirs).
std::vector<std::string> default_metrics(ExcitationKind kind);

}  // namespace vssw::study

#pragma once
// The metrics a study can ask for: the entries of the project's one metric table (compare/metric_catalog.hpp) that a
// study measures, with its name (a results.csv `metric`), unit, what produces it, and whether only the analytic model
// has it. Read by the study file's checks, the runner, the writers and `vssw study --help`.
#include <string>
#include <vector>

#include "compare/metric_catalog.hpp"
#include "study/spec.hpp"

namespace vssw::study {


// In the order `vssw study --help` lists them.
const std::vector<compare::MetricInfo>& metric_catalog();
// InputError naming the metric and listing the known ones.
const compare::MetricInfo& metric_info(const std::string& name);
// Whether an excitation of this kind can give the metric (closed forms: every kind).
bool kind_measures(ExcitationKind kind, const compare::MetricInfo& metric);
// What a study of this kind measures when its file names no metrics (closed-form studies must name theirs).
std::vector<std::string> default_metrics(ExcitationKind kind);

}  // namespace vssw::study

#pragma once
// Every metric the project measures, in one table: its name (a results.csv `metric`, a report row's), its unit, and
// how each of the two places that measure it sees it. A study (study/metric_catalog.hpp) measures a metric on one
// backend's run; the validation suite (validation/suite.hpp) measures it on an engine against the analytic model and
// reports the relative error. The same name means the same quantity in both (the response metrics through one
// function, compare/response.hpp); the suite's descriptions say what it is compared with. Read by study files' checks, `vssw study --help`, the study runner and writers, the suite's runner,
// `vssw check` and the report.
#include <string>
#include <vector>

namespace vssw::compare {

// What produces a metric in a study.
enum class MetricSource {
    closed_form,  // a formula of the paper (or Housner's) on the case's wall: no simulation
    threshold,    // find_threshold (compare/experiments.hpp): bisection on simulated constant accelerations
    free,         // a free vibration from theta0 (kind = free)
    response,     // the case's run: a free vibration, a pulse or a record from rest
    collapse,     // the smallest scale of a record that overturns the wall (kind = scale-to-collapse)
};

// Which of the validation suite's cases measures a metric (its step cases measure the free ones).
enum class SuiteMeasure {
    none,       // not a suite metric
    threshold,  // find_threshold on the wall
    free,       // a free vibration from r alpha
    history,    // a ground-motion record from rest
};

struct MetricInfo {
    const char* name;
    const char* unit;  // "g", "s", "alpha1" (theta1 / alpha1, or theta / alpha of a parapet), "" (a ratio)
    // A study's view; in_study false: a suite-only metric (its study fields unused).
    bool in_study;
    MetricSource source;
    bool analytic_only;       // rows only for the analytic model (its own checks and closed forms)
    const char* description;  // one line for --help, study.md and results.json
    // The validation suite's view.
    SuiteMeasure suite;
    bool vssw_only;                  // measured on a VSSW only (not on a parapet)
    const char* title;               // the report's heading for it
    const char* short_title;         // in table headers and findings; nullptr: the name
    const char* report_description;  // the report's paragraph: what it is and what it is compared with
    double target;                   // the relative error asked of an engine (compare/targets.hpp); 0: none
};

// Every metric: the study metrics in the order `vssw study --help` lists them, then the suite-only ones.
const std::vector<MetricInfo>& metric_catalog();
// The entry of `name`, or nullptr when no metric has it.
const MetricInfo* find_metric(const std::string& name);
// The suite's metrics in the report's order: the threshold's, the free vibrations', the histories', each in
// catalogue order.
std::vector<const MetricInfo*> suite_metrics();

}  // namespace vssw::compare

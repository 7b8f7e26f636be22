#pragma once
// Bounds on the suite's metrics (`vssw check`): how far each engine may be from the analytic model, and how far the
// analytic core may drift from stored reference values. The file formats (TOML, JSON) are read in cli/; this is what
// they mean and how results are held against them.
#include <string>
#include <vector>

#include "validation/suite.hpp"

namespace vssw::validation {

// The analytic model's own value of a metric on a case, against a value stored when the core was last trusted:
// |value / reference - 1| <= max_drift (|value| <= max_drift when the reference is 0).
struct AnalyticBound {
    std::string case_id;
    std::string metric;
    double reference;
    double max_drift;
};

// An engine's relative error against the analytic model (MetricRow::rel_error) on each listed case:
// min_error <= rel_error <= max_error. A known, explained offset (Eq. (19) against the engines' whole-mechanism
// impact) is a range that excludes zero; an agreement target is [-x, x].
struct EngineBound {
    std::string engine;
    std::vector<std::string> case_ids;
    std::string metric;
    double min_error;
    double max_error;
};

// The verdicts `vssw stress --quick` may give (docs/guide/stress.md): each listed case on each listed engine must end
// with one of `allowed` ("ok", "refused", "failed"). Held in cli/ (cmd_check.cpp), which runs the stress cases.
struct StressBound {
    std::vector<std::string> case_ids;  // stress case names (stress/cases.cpp)
    std::vector<std::string> engines;   // empty: every backend compiled in
    std::vector<std::string> allowed;
};

// An engine's measure under a record ensemble (validation/earthquake.hpp): the value must lie in [min, max]. Measures:
// overturning_agreement, fragility_median_ratio, peak_ratio_median, inside_band (the share of runs inside the
// reference's band). Held in cli/ (cmd_check.cpp), which runs the ensemble.
struct EarthquakeBound {
    std::string study;  // the ensemble, as `vssw report --earthquake` names it ("default": the shipped one)
    std::string engine;
    std::string measure;
    double min, max;
};

struct Bounds {
    std::string suite = "default";  // where the case ids come from: a shipped suite or a suite file (validation::read_suite)
    std::vector<AnalyticBound> analytic;
    std::vector<EngineBound> engines;
    std::vector<StressBound> stress;
    std::vector<EarthquakeBound> earthquake;
};

// The case ids and engines the bounds need (each once, in first-mention order): `check` runs only these.
std::vector<std::string> cases_needed(const Bounds& bounds);
std::vector<std::string> engines_needed(const Bounds& bounds);

// One bound held against one measured value.
struct BoundVerdict {
    std::string engine;  // "analytic" for a drift bound
    std::string case_id;
    std::string metric;
    double value;     // the engine's rel_error, or the analytic model's value (NaN: not measured)
    double lo, hi;    // the allowed interval for `value`
    bool held;
    std::string note;  // why it failed when that is not the number (the engine failed, the metric is missing)
    // A stress bound's verdict and the verdicts allowed, shown instead of value, lo and hi (which are NaN).
    std::string value_label, allowed_label;
    bool earthquake = false;  // an [[earthquake]] bound: case is the ensemble's study, metric its measure
};

// Every bound against the results, in the bounds' order. A missing row, a NaN or an engine failure on the case is a
// bound that does not hold (nothing passes by not being measured).
std::vector<BoundVerdict> evaluate(const Bounds& bounds, const SuiteResults& results);

}  // namespace vssw::validation

#include "validation/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace vssw::validation {
namespace {

void add_once(std::vector<std::string>& list, const std::string& item) {
    if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

const MetricRow* find_row(const SuiteResults& results, const std::string& case_id, const std::string& engine,
                          const std::string& metric) {
    for (const MetricRow& row : results.rows)
        if (row.case_id == case_id && row.engine == engine && row.metric == metric) return &row;
    return nullptr;
}

const CaseFailure* find_failure(const SuiteResults& results, const std::string& case_id, const std::string& engine) {
    for (const CaseFailure& f : results.failures)
        if (f.case_id == case_id && f.engine == engine) return &f;
    return nullptr;
}

// The verdict when there is no number to hold against the bound.
std::string missing_note(const SuiteResults& results, const std::string& case_id, const std::string& engine,
                         const MetricRow* row) {
    if (const CaseFailure* f = find_failure(results, case_id, engine)) return "engine failed: " + f->message;
    if (row == nullptr) return "not measured (no such metric for this case)";
    return "not measured (NaN)";
}

}  // namespace

std::vector<std::string> cases_needed(const Bounds& bounds) {
    std::vector<std::string> ids;
    for (const AnalyticBound& b : bounds.analytic) add_once(ids, b.case_id);
    for (const EngineBound& b : bounds.engines)
        for (const std::string& id : b.case_ids) add_once(ids, id);
    return ids;
}

std::vector<std::string> engines_needed(const Bounds& bounds) {
    std::vector<std::string> names;
    for (const EngineBound& b : bounds.engines)
        if (b.engine != "analytic") add_once(names, b.engine);
    return names;
}

std::vector<BoundVerdict> evaluate(const Bounds& bounds, const SuiteResults& results) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    std::vector<BoundVerdict> verdicts;
    for (const AnalyticBound& b : bounds.analytic) {
        const MetricRow* row = find_row(results, b.case_id, "analytic", b.metric);
        const double value = row != nullptr ? row->engine_value : kNaN;
        // The allowed interval of the value itself: reference (1 -/+ max_drift), or +/- max_drift about 0.
        const double spread = b.reference != 0.0 ? std::abs(b.reference) * b.max_drift : b.max_drift;
        BoundVerdict v{"analytic", b.case_id, b.metric, value, b.reference - spread, b.reference + spread, false, "", "", ""};
        v.held = std::isfinite(value) && value >= v.lo && value <= v.hi;
        if (!std::isfinite(value)) v.note = missing_note(results, b.case_id, "analytic", row);
        verdicts.push_back(v);
    }
    for (const EngineBound& b : bounds.engines) {
        for (const std::string& case_id : b.case_ids) {
            const MetricRow* row = find_row(results, case_id, b.engine, b.metric);
            const double value = row != nullptr ? row->rel_error : kNaN;
            BoundVerdict v{b.engine, case_id, b.metric, value, b.min_error, b.max_error, false, "", "", ""};
            v.held = std::isfinite(value) && value >= b.min_error && value <= b.max_error;
            if (!std::isfinite(value)) v.note = missing_note(results, case_id, b.engine, row);
            verdicts.push_back(v);
        }
    }
    return verdicts;
}

}  // namespace vssw::validation

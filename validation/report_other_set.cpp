// The report's row on the analytic model under the other assumption set (validation::SuiteResults::other_set,
// validation/report.hpp): measured exactly as an engine is, by the same tables, and shown as what that set's
// assumptions change against the reference, never as a verdict.
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "validation/assumption_set_engine.hpp"
#include "validation/report.hpp"

namespace vssw::validation {
namespace {

// The results as if the other set were the one engine: the reference's own rows, then the other set's rows and
// failures. error_matrix reads nothing else, so the other set's cells are computed as an engine's are.
SuiteResults as_an_engine(const SuiteResults& res) {
    SuiteResults out;
    out.suite = res.suite;
    out.reference = res.reference;
    const OtherSetRun& other = *res.other_set;
    out.engines.push_back({"analytic", "", {}});
    out.engines.push_back({other.engine, "", {}});
    for (const MetricRow& r : res.rows)
        if (r.engine == "analytic") out.rows.push_back(r);
    out.rows.insert(out.rows.end(), other.rows.begin(), other.rows.end());
    out.failures = other.failures;
    return out;
}

std::string worst_text(const MatrixCell& c) {
    if (c.rows == 0) return c.failed > 0 ? fmt::format("{} failed", short_title(c.metric)) : "";
    if (c.metric == "overturned")
        return fmt::format("overturning differs on {} of {} record{}", c.outside, c.rows, c.rows == 1 ? "" : "s");
    if (!target_of(c.metric)) return "";
    return fmt::format("{} {} ({})", short_title(c.metric), io::percent(c.worst_rel_error), c.case_id);
}

}  // namespace

std::vector<MatrixCell> other_set_matrix(const ReportInput& in) {
    if (!in.results.other_set) return {};
    const SuiteResults alone = as_an_engine(in.results);
    const ReportInput other{in.suite, alone, in.meta, nullptr};
    return error_matrix(other);
}

std::string other_set_label(const SuiteResults& results) {
    return results.other_set ? assumption_set_engine_label(results.other_set->set) : "";
}

std::string other_set_finding(const ReportInput& in) {
    const std::vector<MatrixCell> cells = other_set_matrix(in);
    std::vector<std::string> parts;
    for (const MatrixCell& c : cells)
        if (std::string text = worst_text(c); !text.empty()) parts.push_back(std::move(text));
    if (parts.empty()) return "";
    const OtherSetRun& other = *in.results.other_set;
    return fmt::format(
        "The analytic model under the set {} differs from the reference, the set {}, by up to: {}. This is what the "
        "assumptions of the set {} change in the model, measured as an engine's error is; it is a finding about those "
        "assumptions, not an error of any engine, and carries no verdict.",
        describe(other.set), describe(in.results.reference), fmt::join(parts, "; "), to_string(other.set));
}

}  // namespace vssw::validation

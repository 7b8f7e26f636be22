// The findings of `vssw report` in plain words (validation/report.hpp): per engine, each metric against its target, the
// records a wall rocks much less under, the error against the step, the failures. Each sentence is built from the
// numbers and says only what they show.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "validation/report.hpp"
#include "multibody/engine.hpp"
#include "vssw_engine_facts.hpp"  // what each engine's dt is (generated: cmake/engines.cmake)

namespace vssw::validation {
namespace {

// Fitted orders below this magnitude: the error does not depend on the step (it is not discretisation error). A first
// order method gives ~1, so 0.3 separates "no trend" from "falling" with room for noisy points.
constexpr double kFlatOrder = 0.3;
// A fitted order is quoted as "roughly dt^p" only when the line explains this share of the variance of log|error|;
// below it the points scatter (e.g. an error that changes sign between steps) and the report says so.
constexpr double kRegularFit = 0.9;
// Errors whose magnitudes stay within this factor of each other over the steps studied "hardly change with the
// step": a first-order error would change by the ratio of the steps (5 to 10 over the suite's step studies).
constexpr double kFlatSpread = 1.5;

using Rows = std::vector<const MetricRow*>;

std::string possessive(const std::string& engine) { return multibody::engine_display_name(engine) + "'s"; }

// "the one case" or "all 4 cases".
std::string all_of(std::size_t n, const std::string& noun) {
    return n == 1 ? "the one " + noun : fmt::format("all {} {}s", n, noun);
}

std::string step_ms(double dt) { return fmt::format("{:g} ms", dt * 1e3); }

// The engine's measured rows of a metric, the step study left out.
Rows rows_of(const ReportInput& in, const std::string& engine, const std::string& metric) {
    Rows rows;
    for (const MetricRow& r : in.results.rows)
        if (r.engine == engine && r.metric == metric && !is_step_case(in, r.case_id) && std::isfinite(r.rel_error))
            rows.push_back(&r);
    return rows;
}

const MetricRow* largest_error(const Rows& rows) {
    return *std::max_element(rows.begin(), rows.end(), [](const MetricRow* a, const MetricRow* b) {
        return std::abs(a->rel_error) < std::abs(b->rel_error);
    });
}

std::string overturning_finding(const std::string& who, const Rows& rows) {
    std::vector<std::string> differ;
    for (const MetricRow* r : rows)
        if (r->rel_error != 0.0)
            differ.push_back(fmt::format("{} ({})", r->case_id,
                                         r->engine_value != 0.0
                                             ? "the engine's wall overturns, the analytic model's does not"
                                             : "the analytic model's wall overturns, the engine's does not"));
    return differ.empty() ? fmt::format("{} verdict on overturning agrees with the analytic model's on {}.", who,
                                        all_of(rows.size(), "history case"))
                          : fmt::format("{} verdict on overturning differs from the analytic model's on {} of {}: {}.",
                                        who, differ.size(), rows.size(), fmt::join(differ, "; "));
}

std::string peak_time_finding(const std::string& who, const Rows& rows) {
    const MetricRow* latest =
        *std::max_element(rows.begin(), rows.end(), [](const MetricRow* a, const MetricRow* b) {
            return std::abs(a->engine_value - a->analytic) < std::abs(b->engine_value - b->analytic);
        });
    return fmt::format("{} peak rotation comes up to {:.3g} s from the analytic model's ({}); no target is set on it.",
                       who, std::abs(latest->engine_value - latest->analytic), latest->case_id);
}

// One metric of one engine: against its target, or how far it is where the project sets none.
std::string metric_finding(const std::string& who, const std::string& metric, const Rows& rows) {
    if (metric == "overturned") return overturning_finding(who, rows);
    if (metric == "peak_time") return peak_time_finding(who, rows);
    const MetricRow* worst = largest_error(rows);
    if (metric == "rms_difference")
        return fmt::format("{} time histories differ from the analytic model's by an rms of up to {:.2g} % of the "
                           "analytic peak rotation ({}); no target is set on it.",
                           who, 100.0 * std::abs(worst->rel_error), worst->case_id);
    const std::string title = metric_title(metric);
    const std::optional<double> target = target_of(metric);
    if (!target)
        return fmt::format("{} {} differs from the analytic model's by up to {} ({}, {} case{}); the project sets no "
                           "target on it.",
                           who, title, io::percent(worst->rel_error), worst->case_id, rows.size(),
                           rows.size() == 1 ? "" : "s");
    const auto outside = static_cast<std::size_t>(std::count_if(
        rows.begin(), rows.end(), [&](const MetricRow* r) { return !within(r->rel_error, *target); }));
    if (outside == 0)
        return fmt::format("{} {} is within the {:g} % target on {} (largest error {} on {}).", who, title,
                           100.0 * *target, all_of(rows.size(), "case"), io::percent(worst->rel_error), worst->case_id);
    return fmt::format("{} {} is outside the {:g} % target on {} of {} case{} (largest error {} on {}).", who, title,
                       100.0 * *target, outside, rows.size(), rows.size() == 1 ? "" : "s", io::percent(worst->rel_error),
                       worst->case_id);
}

// Under the records: a wall that rocks much less than the analytic model, on which the engine's impacts keep less
// energy than the reference's in free vibration. Said only when both numbers are there.
std::vector<std::string> record_peak_findings(const ReportInput& in, const std::string& engine) {
    const std::string who = possessive(engine);
    std::map<std::string, Rows> low_peaks;  // by wall id
    for (const MetricRow* r : rows_of(in, engine, "peak_rotation"))
        if (std::isfinite(r->rel_error) && r->rel_error < -kReportMuchLowerPeak)
            low_peaks[r->case_id.substr(0, r->case_id.find('/'))].push_back(r);
    std::vector<std::string> out;
    for (const auto& [wall_id, peaks] : low_peaks) {
        double sum = 0.0;
        int n = 0;
        for (const MetricRow* e : rows_of(in, engine, "restitution"))
            if (e->case_id.rfind(wall_id + "/r", 0) == 0 && e->case_id.find("/dt") == std::string::npos &&
                std::isfinite(e->rel_error)) {
                sum += e->rel_error;
                ++n;
            }
        if (n == 0 || sum / n > -kReportRestitutionTarget) continue;
        std::vector<std::string> listed;
        for (const MetricRow* r : peaks)
            listed.push_back(fmt::format("{:.3g} alpha1 against {:.3g} on {}", r->engine_value, r->analytic,
                                         r->case_id));
        out.push_back(fmt::format(
            "{} {} rocks much less than the analytic model under the records ({}): on the same wall its impacts keep "
            "less energy than the reference's (first-impact restitution {} on average over its free vibrations).",
            who, wall_id, fmt::join(listed, "; "), io::percent(sum / n)));
    }
    return out;
}

// How one engine's error on one case and metric moves with the step.
std::string step_finding(const std::string& engine, const StepSeries& s) {
    std::vector<std::string> points;  // largest step first, as the error is expected to fall
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (std::size_t i = s.dt.size(); i-- > 0;) {
        points.push_back(fmt::format("{}: {}", step_ms(s.dt[i]), io::percent(s.rel_error[i])));
        if (std::isfinite(s.rel_error[i]) && s.rel_error[i] != 0.0) {
            lo = std::min(lo, std::abs(s.rel_error[i]));
            hi = std::max(hi, std::abs(s.rel_error[i]));
        }
    }
    const std::string span = fmt::format("{}", fmt::join(points, ", "));
    const std::string what = fmt::format("{} {} error on {}", possessive(engine), short_title(s.metric), s.base_case);
    // What the engine's dt is (its DT_MEANING fact): a step, or for an integrator with error control (Simbody's
    // compliant route) the reporting interval.
    std::string step = "step";
    for (const EngineFacts& e : kEngineFacts)
        if (engine == e.name) step = e.dt_meaning;
    const bool regular = s.r_squared >= kRegularFit;
    if (hi <= kFlatSpread * lo)
        return fmt::format("{} hardly changes with the {} ({}): it is not discretisation error.", what, step, span);
    if (s.order >= kFlatOrder && regular)
        return fmt::format("{} falls with the {}, roughly as dt^{:.1f} ({}).", what, step, s.order, span);
    if (s.order >= kFlatOrder)
        return fmt::format("{} falls with the {} overall but not regularly ({}; fitted order {:.1f}, r^2 {:.2f}).",
                           what, step, span, s.order, s.r_squared);
    if (s.order <= -kFlatOrder && regular)
        return fmt::format("{} grows as the {} falls ({}; fitted order {:.1f}).", what, step, span, s.order);
    return fmt::format("{} changes with the {} without a trend ({}).", what, step, span);
}

// Empty when the engine finished every case.
std::string failure_finding(const ReportInput& in, const std::string& engine) {
    std::set<std::string> all_cases;
    for (const MetricRow& r : in.results.rows) all_cases.insert(r.case_id);
    for (const CaseFailure& f : in.results.failures) all_cases.insert(f.case_id);
    std::vector<std::string> failed;
    for (const CaseFailure& f : in.results.failures)
        if (f.engine == engine) failed.push_back(fmt::format("{} ({})", f.case_id, f.message));
    if (failed.empty()) return "";
    return fmt::format("{} failed on {} of {} cases: {}.", multibody::engine_display_name(engine), failed.size(),
                       all_cases.size(), fmt::join(failed, "; "));
}

std::vector<std::string> engine_findings(const ReportInput& in, const std::string& engine) {
    const std::string who = possessive(engine);
    std::vector<std::string> out;
    for (const std::string& metric : metric_order(in.results)) {
        const Rows rows = rows_of(in, engine, metric);
        if (!rows.empty()) out.push_back(metric_finding(who, metric, rows));
    }
    for (std::string& s : record_peak_findings(in, engine)) out.push_back(std::move(s));
    for (const StepSeries& s : step_series(in))
        if (s.engine == engine && std::isfinite(s.order)) out.push_back(step_finding(engine, s));
    if (std::string failed = failure_finding(in, engine); !failed.empty()) out.push_back(std::move(failed));
    return out;
}

}  // namespace

std::vector<std::string> findings(const ReportInput& in, const std::string& only_engine) {
    std::vector<std::string> out;
    for (const std::string& engine : compared_engines(in.results)) {
        if (!only_engine.empty() && engine != only_engine) continue;
        for (std::string& s : engine_findings(in, engine)) out.push_back(std::move(s));
    }
    return out;
}

}  // namespace vssw::validation

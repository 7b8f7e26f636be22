#pragma once
// What `vssw report` says about a validation suite's results (validation/suite.hpp), computed by one set of functions
// that every writer (Markdown, HTML, JSON, CSV, plots) calls, so that they cannot disagree: the targets, the per-engine summary, the
// per-metric tables, the error-against-step study and the findings in plain words.
//
// Nothing here runs a simulation: the writers and these functions take a SuiteResults built by validation::run_suite or
// by hand (the tests).
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "validation/suite.hpp"
#include "compare/targets.hpp"
#include "io/text.hpp"

namespace vssw::validation {

// The accuracy the project asks of an engine (compare/targets.hpp).
constexpr double kReportThresholdTarget = compare::kThresholdTarget;
constexpr double kReportPeriodTarget = compare::kPeriodTarget;
constexpr double kReportRestitutionTarget = compare::kRestitutionTarget;
// A peak rotation under a record this far below the analytic model's (relative) is "much less" in the findings: the
// PW's peaks, whose impact the engines reproduce, scatter by about 25 % (rocking under a record is that sensitive).
constexpr double kReportMuchLowerPeak = 0.5;

// The target of a metric, none for those the project sets no target on (history metrics).
std::optional<double> target_of(const std::string& metric);
// A readable name ("threshold", "restitution (first impact)") and one sentence on how the metric is measured.
std::string metric_title(const std::string& metric);
std::string metric_description(const std::string& metric);

// Everything a writer needs beside the numbers.
struct ReportMeta {
    std::string date;    // when the report was made, ISO 8601 UTC
    std::string commit;  // vssw's git commit (at configure time), empty when unknown
    bool plots_made = false;
    std::string plots_note;  // why there are no plots (or which failed), empty when all were made
};

struct EarthquakePart;   // validation/earthquake.hpp
struct AssumptionsPart;  // validation/assumptions_part.hpp

struct ReportInput {
    const Suite& suite;  // labels and kinds of the cases; may hold no cases (kinds then come from the ids)
    const SuiteResults& results;
    ReportMeta meta;
    const EarthquakePart* earthquake = nullptr;  // the record ensemble's part, when it ran
    const AssumptionsPart* relaxations = nullptr;  // the paper's assumptions relaxed, when it ran
};

// The kind of a case: from the suite when it lists the case, else from the shape of its id (validation/suite.hpp).
CaseKind case_kind(const ReportInput& in, const std::string& case_id);
const char* kind_name(CaseKind kind);
// The engine step of a `step` case (from the suite, else from the "/dt<dt>/<engine>" end of its id); NaN if none.
double case_step(const ReportInput& in, const std::string& case_id);

// Whether a case belongs to the error-against-step study (summaries and tables leave those out).
bool is_step_case(const ReportInput& in, const std::string& case_id);
// A metric's name in a summary line ("threshold", "restitution").
std::string short_title(const std::string& metric);
// |rel_error| <= target; false when it was not measured.
bool within(double rel_error, double target);

// The cases that ran: those with a row or a failure (a step case of an engine not asked for did not run).
std::set<std::string> cases_that_ran(const SuiteResults& results);
// The one count of cases that report.html, report.md and the program's line all say: "42 cases" when every case of
// the suite ran, else "42 cases (4 more of the suite did not run: step-study cases of engines not asked
// for)".
std::string case_count_text(const Suite& suite, const SuiteResults& results);

// One engine in one line: how many metrics with a target are within it (step-study cases left out: they vary the
// step on purpose), the largest |error| per metric (signed), the failures.
struct MetricExtreme {
    std::string metric;
    double rel_error = 0.0;  // the signed error of largest magnitude
    std::string case_id;     // where
    int rows = 0;            // measured rows of this metric
    int outside = 0;         // of which outside the target (metrics without one: a nonzero error, e.g. overturned)
};
struct EngineSummary {
    std::string engine;
    int with_target = 0, within = 0, not_measured = 0, failures = 0;
    std::vector<MetricExtreme> extremes;  // in report order (metric_order)
    std::string line;                     // "ode: 31/33 metrics within target; max |error| ...; 0 failures"
};
// The engines other than "analytic", in the order of results.engines (then any only seen in rows or failures).
std::vector<std::string> compared_engines(const SuiteResults& results);
std::vector<EngineSummary> summarize(const ReportInput& in);

// A per-metric table over the non-step cases: the reference value and each engine's value and error.
struct MetricCell {
    bool present = false;
    bool failed = false;  // the engine failed on this case
    double value = 0.0, rel_error = 0.0;
};
struct MetricTableRow {
    std::string case_id;
    double reference = 0.0;
    std::string reference_name;    // MetricRow::reference
    std::vector<MetricCell> cells;  // one per engine of MetricTable::engines
};
struct MetricTable {
    std::string metric, unit;
    std::optional<double> target;
    std::vector<std::string> engines;
    std::vector<MetricTableRow> rows;
};
// The metrics in report order: threshold_g, period, restitution, the history metrics, then the others by name.
std::vector<std::string> metric_order(const SuiteResults& results);
std::vector<MetricTable> metric_tables(const ReportInput& in);

// The report at a glance: per engine and metric (step-study cases left out), the signed error of largest magnitude
// and whether every case is within the target. Pass iff the metric has a target, every row of the engine was
// measured (no NaN), none failed, and each |error| is within the target; metrics without a target have no verdict.
struct MatrixCell {
    std::string engine, metric;
    double worst_rel_error = std::numeric_limits<double>::quiet_NaN();  // NaN: nothing measured
    std::string case_id;  // where the worst error is
    std::optional<double> target;
    bool pass = false;
    int rows = 0;          // measured rows (finite error)
    int not_measured = 0;  // rows whose error is NaN
    int failed = 0;        // cases of this metric on which the engine failed (no row)
    int outside = 0;       // measured rows outside the target (overturned: rows that disagree)
};
// Engines in compared_engines order, metrics in metric_order; a cell for every pair where the engine has a row or a
// failure of that metric.
std::vector<MatrixCell> error_matrix(const ReportInput& in);

// The analytic model under the set that is not the reference (validation::SuiteResults::other_set), measured as an engine
// is: its cells as error_matrix computes an engine's, none when it did not run. Their `pass` is no verdict: the report
// shows the numbers with no mark, and no engine's verdict, summary or exit status reads them
// (validation/report_other_set.cpp).
std::vector<MatrixCell> other_set_matrix(const ReportInput& in);
// Its row's name, "analytic, paper's assumptions"; empty when it did not run.
std::string other_set_label(const SuiteResults& results);
// One sentence: what the other set's assumptions change against the reference, in numbers; empty when it did not run.
std::string other_set_finding(const ReportInput& in);

// The error-against-step study: per engine, per free-vibration case it belongs to ("<wall>/r<r>"), per metric, the
// points (dt, rel_error) in increasing dt.
struct StepSeries {
    std::string engine, base_case, metric;
    std::vector<double> dt, rel_error;
    // Least-squares slope of log|error| against log dt over the points with a nonzero error; NaN with fewer than 3.
    double order = 0.0;
    double r_squared = 0.0;  // of that fit; NaN without a fit
};
std::vector<StepSeries> step_series(const ReportInput& in);

// The findings in plain words, each one sentence or two built from the numbers (never a claim they do not show),
// engine after engine; only those of one engine when it is named.
std::vector<std::string> findings(const ReportInput& in, const std::string& only_engine = "");

}  // namespace vssw::validation

#include "validation/report_data.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "multibody/host/contact_schemes.hpp"
#include "validation/earthquake.hpp"

namespace vssw::study {

Json settings_json(const multibody::EngineSettings& s) {
    Json knobs = Json::object();
    for (const auto& [k, v] : s.knobs) knobs[k] = finite_or_null(v);
    Json j = {{"dt", finite_or_null(s.dt)}, {"knobs", knobs}};
    if (s.iterations > 0) j["iterations"] = s.iterations;
    return j;
}

std::string trace_number(double value, int digits) {
    return std::isfinite(value) ? fmt::format("{:.{}g}", value, digits) : "";
}

namespace {

Json suite_json(const ReportInput& in) {
    const compare::Suite& suite = in.suite;
    Json walls = Json::array(), records = Json::array(), cases = Json::array();
    for (const compare::SuiteWall& w : suite.walls) {
        Json j = {{"id", w.id}, {"label", w.label}};
        if (w.scene.vssw || w.scene.parapet) {
            j["kind"] = w.scene.is_vssw() ? "vssw" : "parapet";
            j["alpha"] = w.scene.alpha();
        }
        walls.push_back(j);
    }
    for (const compare::SuiteRecord& r : suite.records)
        records.push_back({{"id", r.id}, {"label", r.label}, {"path", r.path}, {"scale", r.scale}});
    for (const compare::SuiteCase& c : suite.cases) {
        Json j = {{"id", c.id}, {"kind", kind_name(c.kind)}, {"wall", c.wall_id}};
        if (c.kind == compare::CaseKind::free || c.kind == compare::CaseKind::step) j["r"] = c.r;
        if (c.kind == compare::CaseKind::history) j["record"] = c.record_id;
        j["dt"] = c.dt ? finite_or_null(*c.dt) : Json(nullptr);
        // A suite file's settings for the case ([settings], [part.settings]); other engines run at their defaults.
        if (!c.settings.empty()) {
            Json settings = Json::object();
            for (const auto& [engine, s] : c.settings) settings[engine] = settings_json(s);
            j["settings"] = settings;
        }
        cases.push_back(j);
    }
    return {{"name", in.results.suite.empty() ? suite.name : in.results.suite},
            {"walls", walls},
            {"records", records},
            {"cases", cases}};
}

Json rows_json(const std::vector<compare::MetricRow>& metric_rows) {
    Json rows = Json::array();
    for (const compare::MetricRow& r : metric_rows) {
        const std::optional<double> target = target_of(r.metric);
        rows.push_back({{"case_id", r.case_id},
                        {"engine", r.engine},
                        {"metric", r.metric},
                        {"unit", r.unit},
                        {"reference", r.reference},
                        {"analytic", finite_or_null(r.analytic)},
                        {"engine_value", finite_or_null(r.engine_value)},
                        {"rel_error", finite_or_null(r.rel_error)},
                        {"target", target ? Json(*target) : Json(nullptr)},
                        {"within_target", target ? Json(std::isfinite(r.rel_error) && std::abs(r.rel_error) <= *target)
                                                 : Json(nullptr)}});
    }
    return rows;
}

Json failures_json(const std::vector<compare::CaseFailure>& case_failures) {
    Json failures = Json::array();
    for (const compare::CaseFailure& f : case_failures)
        failures.push_back({{"case_id", f.case_id}, {"engine", f.engine}, {"message", f.message}});
    return failures;
}

// A matrix cell without its verdict (the caller adds `pass` where the cell has one).
Json matrix_cell_json(const MatrixCell& c) {
    return {{"engine", c.engine},
            {"metric", c.metric},
            {"worst_rel_error", finite_or_null(c.worst_rel_error)},
            {"case_id", c.case_id},
            {"target", c.target ? Json(*c.target) : Json(nullptr)},
            {"rows", c.rows},
            {"not_measured", c.not_measured},
            {"failed", c.failed}};
}

// The analytic model under the other set (compare::OtherSetRun): its rows and cells, no verdict; null when it did not
// run.
Json other_set_json(const ReportInput& in) {
    if (!in.results.other_set) return nullptr;
    const compare::OtherSetRun& other = *in.results.other_set;
    Json matrix = Json::array();
    for (const MatrixCell& c : other_set_matrix(in)) matrix.push_back(matrix_cell_json(c));
    return {{"engine", other.engine},
            {"assumptions", to_string(other.set)},
            {"label", other_set_label(in.results)},
            {"finding", other_set_finding(in)},
            {"matrix", matrix},
            {"rows", rows_json(other.rows)},
            {"failures", failures_json(other.failures)}};
}

}  // namespace

Json results_json(const ReportInput& in) {
    const compare::SuiteResults& res = in.results;
    Json engines = Json::array();
    for (const compare::EngineRunInfo& e : res.engines)
        engines.push_back({{"name", e.name}, {"version", e.version}, {"contact_scheme", multibody::contact_scheme(e.name).key},
                           {"settings", settings_json(e.settings)}});

    Json targets = Json::object();
    for (const std::string& metric : metric_order(res))
        if (const auto t = target_of(metric)) targets[metric] = *t;

    const Json rows = rows_json(res.rows);
    const Json failures = failures_json(res.failures);

    Json model_warnings = Json::array();
    for (const compare::ModelWarning& w : res.model_warnings)
        model_warnings.push_back({{"case_id", w.case_id}, {"message", w.message}});

    Json summary = Json::array();
    for (const EngineSummary& s : summarize(in)) {
        Json max_error = Json::object();
        for (const MetricExtreme& x : s.extremes)
            max_error[x.metric] = {{"rel_error", finite_or_null(x.rel_error)}, {"case_id", x.case_id}};
        summary.push_back({{"engine", s.engine},
                           {"line", s.line},
                           {"within", s.within},
                           {"with_target", s.with_target},
                           {"not_measured", s.not_measured},
                           {"failures", s.failures},
                           {"max_error", max_error}});
    }

    Json steps = Json::array();
    for (const StepSeries& s : step_series(in)) {
        Json dt = Json::array(), err = Json::array();
        for (double v : s.dt) dt.push_back(finite_or_null(v));
        for (double v : s.rel_error) err.push_back(finite_or_null(v));
        steps.push_back({{"engine", s.engine},
                         {"case_id", s.base_case},
                         {"metric", s.metric},
                         {"dt", dt},
                         {"rel_error", err},
                         {"order", finite_or_null(s.order)}});
    }

    Json matrix = Json::array();
    for (const MatrixCell& c : error_matrix(in)) {
        Json j = matrix_cell_json(c);
        j["pass"] = c.target ? Json(c.pass) : Json(nullptr);
        matrix.push_back(j);
    }

    Json traces = Json::array();
    for (const compare::Trace& t : res.traces)
        traces.push_back(
            {{"case_id", t.case_id}, {"engine", t.engine}, {"assumption", t.assumption}, {"samples", t.t.size()}});

    return {{"vssw", {{"commit", in.meta.commit.empty() ? Json(nullptr) : Json(in.meta.commit)},
                      {"report_format", kReportFormat}}},
            {"date", in.meta.date},
            {"suite", suite_json(in)},
            {"reference_assumptions", to_string(res.reference)},
            {"engines", engines},
            {"targets", targets},
            {"rows", rows},
            {"failures", failures},
            {"model_warnings", model_warnings},
            {"summary", summary},
            {"matrix", matrix},
            {"other_set", other_set_json(in)},
            {"findings", findings(in)},
            {"step_study", steps},
            {"traces", traces},
            {"earthquake", in.earthquake ? earthquake_json(*in.earthquake) : Json(nullptr)},
            {"plots", {{"made", in.meta.plots_made}, {"note", in.meta.plots_note}}},
            {"wall_time_s", finite_or_null(res.wall_time_s)},
            {"threads", res.threads}};
}

void write_metrics_csv(std::ostream& out, const compare::SuiteResults& results) {
    out << "case_id,engine,metric,unit,reference,analytic,engine_value,rel_error\n";
    for (const compare::MetricRow& r : results.rows)
        out << csv_field(r.case_id) << ',' << csv_field(r.engine) << ',' << csv_field(r.metric) << ','
            << csv_field(r.unit) << ',' << csv_field(r.reference) << ',' << csv_number(r.analytic) << ','
            << csv_number(r.engine_value) << ',' << csv_number(r.rel_error) << '\n';
}

void write_failures_csv(std::ostream& out, const compare::SuiteResults& results) {
    out << "case_id,engine,message\n";
    for (const compare::CaseFailure& f : results.failures)
        out << csv_field(f.case_id) << ',' << csv_field(f.engine) << ',' << csv_field(f.message) << '\n';
}

void write_traces_csv(std::ostream& out, const compare::SuiteResults& results) {
    out << "case_id,engine,t,theta1_over_alpha,assumption\n";
    for (const compare::Trace& tr : results.traces) {
        const std::string prefix = csv_field(tr.case_id) + ',' + csv_field(tr.engine) + ',';
        const std::string suffix = ',' + csv_field(tr.assumption) + '\n';
        const std::size_t n = std::min(tr.t.size(), tr.theta1_over_alpha.size());
        for (std::size_t i = 0; i < n; ++i)
            out << prefix << trace_number(tr.t[i], kTraceTimeDigits) << ','
                << trace_number(tr.theta1_over_alpha[i], kTraceValueDigits) << suffix;
    }
}

}  // namespace vssw::study

#include "validation/report_data.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "multibody/host/contact_schemes.hpp"
#include "validation/assumptions_part.hpp"
#include "validation/earthquake.hpp"

namespace vssw::validation {

io::Json settings_json(const multibody::EngineSettings& s) {
    io::Json knobs = io::Json::object();
    for (const auto& [k, v] : s.knobs) knobs[k] = io::finite_or_null(v);
    io::Json j = {{"dt", io::finite_or_null(s.dt)}, {"knobs", knobs}};
    if (s.iterations > 0) j["iterations"] = s.iterations;
    return j;
}

std::string trace_number(double value, int digits) {
    return std::isfinite(value) ? fmt::format("{:.{}g}", value, digits) : "";
}

namespace {

io::Json suite_json(const ReportInput& in) {
    const Suite& suite = in.suite;
    io::Json walls = io::Json::array(), records = io::Json::array(), cases = io::Json::array();
    for (const SuiteWall& w : suite.walls) {
        io::Json j = {{"id", w.id}, {"label", w.label}};
        if (w.scene.vssw || w.scene.parapet) {
            j["kind"] = w.scene.is_vssw() ? "vssw" : "parapet";
            j["alpha"] = w.scene.alpha();
        }
        walls.push_back(j);
    }
    for (const SuiteRecord& r : suite.records)
        records.push_back({{"id", r.id}, {"label", r.label}, {"path", r.path}, {"scale", r.scale}});
    for (const SuiteCase& c : suite.cases) {
        io::Json j = {{"id", c.id}, {"kind", kind_name(c.kind)}, {"wall", c.wall_id}};
        if (c.kind == CaseKind::free || c.kind == CaseKind::step) j["r"] = c.r;
        if (c.kind == CaseKind::history) j["record"] = c.record_id;
        j["dt"] = c.dt ? io::finite_or_null(*c.dt) : io::Json(nullptr);
        // A suite file's settings for the case ([settings], [part.settings]); other engines run at their defaults.
        if (!c.settings.empty()) {
            io::Json settings = io::Json::object();
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

io::Json rows_json(const std::vector<MetricRow>& metric_rows) {
    io::Json rows = io::Json::array();
    for (const MetricRow& r : metric_rows) {
        const std::optional<double> target = target_of(r.metric);
        rows.push_back({{"case_id", r.case_id},
                        {"engine", r.engine},
                        {"metric", r.metric},
                        {"unit", r.unit},
                        {"reference", r.reference},
                        {"analytic", io::finite_or_null(r.analytic)},
                        {"engine_value", io::finite_or_null(r.engine_value)},
                        // "error": a relative error, but for rms_difference the RMS over the peak and for
                        // overturned the difference (MetricRow, validation/suite.hpp).
                        {"error", io::finite_or_null(r.rel_error)},
                        {"target", target ? io::Json(*target) : io::Json(nullptr)},
                        {"within_target", target ? io::Json(std::isfinite(r.rel_error) && std::abs(r.rel_error) <= *target)
                                                 : io::Json(nullptr)}});
    }
    return rows;
}

io::Json failures_json(const std::vector<CaseFailure>& case_failures) {
    io::Json failures = io::Json::array();
    for (const CaseFailure& f : case_failures)
        failures.push_back({{"case_id", f.case_id}, {"engine", f.engine}, {"message", f.message}});
    return failures;
}

// A matrix cell without its verdict (the caller adds `pass` where the cell has one).
io::Json matrix_cell_json(const MatrixCell& c) {
    return {{"engine", c.engine},
            {"metric", c.metric},
            {"worst_error", io::finite_or_null(c.worst_rel_error)},
            {"case_id", c.case_id},
            {"target", c.target ? io::Json(*c.target) : io::Json(nullptr)},
            {"rows", c.rows},
            {"not_measured", c.not_measured},
            {"failed", c.failed}};
}

// The analytic model under the other set (validation::OtherSetRun): its rows and cells, no verdict; null when it did not
// run.
io::Json other_set_json(const ReportInput& in) {
    if (!in.results.other_set) return nullptr;
    const OtherSetRun& other = *in.results.other_set;
    io::Json matrix = io::Json::array();
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

io::Json results_json(const ReportInput& in) {
    const SuiteResults& res = in.results;
    io::Json engines = io::Json::array();
    for (const EngineRunInfo& e : res.engines)
        engines.push_back({{"name", e.name}, {"version", e.version}, {"contact_scheme", multibody::contact_scheme(e.name).key},
                           {"settings", settings_json(e.settings)}});

    io::Json targets = io::Json::object();
    for (const std::string& metric : metric_order(res))
        if (const auto t = target_of(metric)) targets[metric] = *t;

    const io::Json rows = rows_json(res.rows);
    const io::Json failures = failures_json(res.failures);

    io::Json model_warnings = io::Json::array();
    for (const ModelWarning& w : res.model_warnings)
        model_warnings.push_back({{"case_id", w.case_id}, {"message", w.message}});

    io::Json summary = io::Json::array();
    for (const EngineSummary& s : summarize(in)) {
        io::Json max_error = io::Json::object();
        for (const MetricExtreme& x : s.extremes)
            max_error[x.metric] = {{"error", io::finite_or_null(x.rel_error)}, {"case_id", x.case_id}};
        summary.push_back({{"engine", s.engine},
                           {"line", s.line},
                           {"within", s.within},
                           {"with_target", s.with_target},
                           {"not_measured", s.not_measured},
                           {"failures", s.failures},
                           {"max_error", max_error}});
    }

    io::Json steps = io::Json::array();
    for (const StepSeries& s : step_series(in)) {
        io::Json dt = io::Json::array(), err = io::Json::array();
        for (double v : s.dt) dt.push_back(io::finite_or_null(v));
        for (double v : s.rel_error) err.push_back(io::finite_or_null(v));
        steps.push_back({{"engine", s.engine},
                         {"case_id", s.base_case},
                         {"metric", s.metric},
                         {"dt", dt},
                         {"rel_error", err},
                         {"order", io::finite_or_null(s.order)}});
    }

    io::Json matrix = io::Json::array();
    for (const MatrixCell& c : error_matrix(in)) {
        io::Json j = matrix_cell_json(c);
        j["pass"] = c.target ? io::Json(c.pass) : io::Json(nullptr);
        matrix.push_back(j);
    }

    io::Json traces = io::Json::array();
    for (const Trace& t : res.traces)
        traces.push_back(
            {{"case_id", t.case_id}, {"engine", t.engine}, {"assumption", t.assumption}, {"samples", t.t.size()}});

    return {{"vssw", {{"commit", in.meta.commit.empty() ? io::Json(nullptr) : io::Json(in.meta.commit)},
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
            {"earthquake", in.earthquake ? earthquake_json(*in.earthquake) : io::Json(nullptr)},
            {"relaxations", in.relaxations ? assumptions_json(*in.relaxations) : io::Json(nullptr)},
            {"plots", {{"made", in.meta.plots_made}, {"note", in.meta.plots_note}}},
            {"wall_time_s", io::finite_or_null(res.wall_time_s)},
            {"threads", res.threads}};
}

void write_metrics_csv(std::ostream& out, const SuiteResults& results) {
    out << "case_id,engine,metric,unit,reference,analytic,engine_value,error\n";
    for (const MetricRow& r : results.rows)
        out << io::csv_field(r.case_id) << ',' << io::csv_field(r.engine) << ',' << io::csv_field(r.metric) << ','
            << io::csv_field(r.unit) << ',' << io::csv_field(r.reference) << ',' << io::csv_number(r.analytic) << ','
            << io::csv_number(r.engine_value) << ',' << io::csv_number(r.rel_error) << '\n';
}

void write_failures_csv(std::ostream& out, const SuiteResults& results) {
    out << "case_id,engine,message\n";
    for (const CaseFailure& f : results.failures)
        out << io::csv_field(f.case_id) << ',' << io::csv_field(f.engine) << ',' << io::csv_field(f.message) << '\n';
}

void write_traces_csv(std::ostream& out, const SuiteResults& results) {
    out << "case_id,engine,t,theta1_over_alpha1,assumption\n";
    for (const Trace& tr : results.traces) {
        const std::string prefix = io::csv_field(tr.case_id) + ',' + io::csv_field(tr.engine) + ',';
        const std::string suffix = ',' + io::csv_field(tr.assumption) + '\n';
        const std::size_t n = std::min(tr.t.size(), tr.theta1_over_alpha1.size());
        for (std::size_t i = 0; i < n; ++i)
            out << prefix << trace_number(tr.t[i], kTraceTimeDigits) << ','
                << trace_number(tr.theta1_over_alpha1[i], kTraceValueDigits) << suffix;
    }
}

}  // namespace vssw::validation

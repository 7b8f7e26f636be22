#include "validation/report.hpp"
#include "compare/metric_catalog.hpp"
#include "multibody/engine.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>

namespace vssw::validation {
namespace {

// A step-study series needs this many points with a nonzero error before its order is fitted (two points always fit
// a line; three can disagree with one).
constexpr std::size_t kMinPointsForOrder = 3;

// The free-vibration case a step case belongs to: its id without the "/dt<dt>/<engine>" end.
std::string step_base(const std::string& id) {
    const auto pos = id.rfind("/dt");
    return pos == std::string::npos ? id : id.substr(0, pos);
}

}  // namespace

bool is_step_case(const ReportInput& in, const std::string& id) { return case_kind(in, id) == CaseKind::step; }

// Titles, descriptions and targets: the suite's view in the one metric table (compare/metric_catalog.hpp); a metric
// not in it (a results file from another version) shows its name.
std::string short_title(const std::string& metric) {
    const compare::MetricInfo* m = compare::find_metric(metric);
    return m && m->short_title ? m->short_title : metric;
}

bool within(double rel_error, double target) { return std::isfinite(rel_error) && std::abs(rel_error) <= target; }

std::set<std::string> cases_that_ran(const SuiteResults& results) {
    std::set<std::string> ran;
    for (const MetricRow& r : results.rows) ran.insert(r.case_id);
    for (const CaseFailure& f : results.failures) ran.insert(f.case_id);
    return ran;
}

std::string case_count_text(const Suite& suite, const SuiteResults& results) {
    const std::set<std::string> ran = cases_that_ran(results);
    std::size_t not_run = 0;
    for (const SuiteCase& c : suite.cases) not_run += ran.count(c.id) == 0 ? 1 : 0;
    std::string text = fmt::format("{} case{}", ran.size(), ran.size() == 1 ? "" : "s");
    if (not_run > 0)
        text += fmt::format(" ({} more of the suite did not run: step-study cases of engines not asked for)", not_run);
    return text;
}

std::optional<double> target_of(const std::string& metric) {
    const compare::MetricInfo* m = compare::find_metric(metric);
    if (m && m->target > 0.0) return m->target;
    return std::nullopt;
}

std::string metric_title(const std::string& metric) {
    const compare::MetricInfo* m = compare::find_metric(metric);
    return m && m->title ? m->title : metric;
}

std::string metric_description(const std::string& metric) {
    const compare::MetricInfo* m = compare::find_metric(metric);
    return m && m->report_description ? m->report_description : "";
}

const char* kind_name(CaseKind kind) {
    switch (kind) {
        case CaseKind::threshold: return "threshold";
        case CaseKind::free: return "free";
        case CaseKind::history: return "history";
        case CaseKind::step: return "step";
    }
    return "unknown";
}

CaseKind case_kind(const ReportInput& in, const std::string& case_id) {
    for (const SuiteCase& c : in.suite.cases)
        if (c.id == case_id) return c.kind;
    // From the id's shape: "<wall>", "<wall>/r<r>", "<wall>/<record>", "<wall>/r<r>/dt<dt>/<engine>".
    const auto slash = case_id.find('/');
    if (slash == std::string::npos) return CaseKind::threshold;
    if (case_id.find("/dt", slash) != std::string::npos) return CaseKind::step;
    const std::string rest = case_id.substr(slash + 1);
    if (rest.size() > 1 && rest[0] == 'r' && (std::isdigit(static_cast<unsigned char>(rest[1])) || rest[1] == '.'))
        return CaseKind::free;
    return CaseKind::history;
}

double case_step(const ReportInput& in, const std::string& case_id) {
    for (const SuiteCase& c : in.suite.cases)
        if (c.id == case_id && c.dt) return *c.dt;
    const auto pos = case_id.rfind("/dt");
    if (pos == std::string::npos) return std::nan("");
    // "<wall>/r<r>/dt<dt>/<engine>": the number runs to the next '/' or the end.
    const std::string text = case_id.substr(pos + 3);
    char* end = nullptr;
    const double dt = std::strtod(text.c_str(), &end);
    return (end != text.c_str() && (*end == '\0' || *end == '/')) ? dt : std::nan("");
}

std::vector<std::string> compared_engines(const SuiteResults& results) {
    std::vector<std::string> names;
    auto add = [&](const std::string& name) {
        if (name != "analytic" && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    };
    for (const EngineRunInfo& e : results.engines) add(e.name);
    for (const MetricRow& r : results.rows) add(r.engine);
    for (const CaseFailure& f : results.failures) add(f.engine);
    return names;
}

std::vector<std::string> metric_order(const SuiteResults& results) {
    std::set<std::string> seen;
    for (const MetricRow& r : results.rows) seen.insert(r.metric);
    std::vector<std::string> order;
    for (const compare::MetricInfo* m : compare::suite_metrics())
        if (seen.erase(m->name) > 0) order.push_back(m->name);
    order.insert(order.end(), seen.begin(), seen.end());
    return order;
}

std::vector<EngineSummary> summarize(const ReportInput& in) {
    const SuiteResults& res = in.results;
    // The worst errors, their cases and the metric counts are the report-at-a-glance matrix's: one source, so the
    // summary line and the matrix cannot disagree on them. (The line's failure count is the suite's own: every failed
    // task of the engine, step-study cases included.)
    const std::vector<MatrixCell> cells = error_matrix(in);
    std::vector<EngineSummary> out;
    for (const std::string& engine : compared_engines(res)) {
        EngineSummary s;
        s.engine = engine;
        for (const CaseFailure& f : res.failures) s.failures += f.engine == engine ? 1 : 0;
        for (const MatrixCell& c : cells) {  // metric_order within each engine
            if (c.engine != engine) continue;
            if (c.target) {
                s.with_target += c.rows + c.not_measured;
                s.not_measured += c.not_measured;
                s.within += c.rows - c.outside;
            }
            if (c.rows > 0) s.extremes.push_back({c.metric, c.worst_rel_error, c.case_id, c.rows, c.outside});
        }
        std::vector<std::string> parts;
        for (const MetricExtreme& x : s.extremes) {
            if (x.metric == "overturned") {
                parts.push_back(x.outside == 0 ? fmt::format("overturning agrees on {}/{}", x.rows, x.rows)
                                               : fmt::format("overturning differs on {}/{}", x.outside, x.rows));
                continue;
            }
            // A single run's peak, its time and the rms difference under a record have no target: they switch
            // branch for a 1 % change of the scale (the earthquake part judges records by ensemble measures); the
            // Metrics tables and results.json keep them.
            if (!target_of(x.metric)) continue;
            parts.push_back(fmt::format("{} {}", short_title(x.metric), io::percent(x.rel_error)));
        }
        s.line = fmt::format("{}: {}/{} metrics within target", multibody::engine_display_name(engine), s.within, s.with_target);
        if (s.not_measured > 0) s.line += fmt::format(" ({} not measured)", s.not_measured);
        if (!parts.empty()) s.line += "; max |error| " + fmt::format("{}", fmt::join(parts, ", "));
        s.line += fmt::format("; {} failure{}", s.failures, s.failures == 1 ? "" : "s");
        out.push_back(std::move(s));
    }
    return out;
}

std::vector<MetricTable> metric_tables(const ReportInput& in) {
    const SuiteResults& res = in.results;
    const std::vector<std::string> engines = compared_engines(res);
    std::vector<MetricTable> tables;
    for (const std::string& metric : metric_order(res)) {
        MetricTable t;
        t.metric = metric;
        t.target = target_of(metric);
        t.engines = engines;
        std::map<std::string, std::size_t> index;  // case id -> row
        for (const MetricRow& r : res.rows) {
            if (r.metric != metric || is_step_case(in, r.case_id)) continue;
            if (t.unit.empty()) t.unit = r.unit;
            auto [it, inserted] = index.try_emplace(r.case_id, t.rows.size());
            if (inserted) {
                t.rows.push_back({r.case_id, r.analytic, r.reference, std::vector<MetricCell>(engines.size())});
            }
            MetricTableRow& row = t.rows[it->second];
            if (r.engine == "analytic") {  // the analytic model's own row: its value is the reference
                row.reference = r.analytic;
                continue;
            }
            const auto e = std::find(engines.begin(), engines.end(), r.engine);
            MetricCell& cell = row.cells[static_cast<std::size_t>(e - engines.begin())];
            cell.present = true;
            cell.value = r.engine_value;
            cell.rel_error = r.rel_error;
            if (row.reference_name.empty()) row.reference_name = r.reference;
        }
        for (const CaseFailure& f : res.failures) {
            const auto it = index.find(f.case_id);
            if (it == index.end()) continue;
            const auto e = std::find(engines.begin(), engines.end(), f.engine);
            if (e != engines.end()) t.rows[it->second].cells[static_cast<std::size_t>(e - engines.begin())].failed = true;
        }
        if (!t.rows.empty()) tables.push_back(std::move(t));
    }
    return tables;
}

std::vector<MatrixCell> error_matrix(const ReportInput& in) {
    std::vector<MatrixCell> cells;
    const std::vector<MetricTable> tables = metric_tables(in);
    const std::size_t engine_count = compared_engines(in.results).size();
    for (std::size_t e = 0; e < engine_count; ++e) {
        for (const MetricTable& t : tables) {
            MatrixCell c;
            c.engine = t.engines[e];
            c.metric = t.metric;
            c.target = t.target;
            for (const MetricTableRow& r : t.rows) {
                const MetricCell& m = r.cells[e];
                if (!m.present) {
                    c.failed += m.failed ? 1 : 0;
                    continue;
                }
                if (!std::isfinite(m.rel_error)) {
                    ++c.not_measured;
                    continue;
                }
                if (c.rows == 0 || std::abs(m.rel_error) > std::abs(c.worst_rel_error)) {
                    c.worst_rel_error = m.rel_error;
                    c.case_id = r.case_id;
                }
                ++c.rows;
                if (t.target ? !within(m.rel_error, *t.target) : m.rel_error != 0.0) ++c.outside;
            }
            if (c.rows + c.not_measured + c.failed == 0) continue;
            c.pass = t.target && c.rows > 0 && c.outside == 0 && c.not_measured == 0 && c.failed == 0;
            cells.push_back(std::move(c));
        }
    }
    return cells;
}

std::vector<StepSeries> step_series(const ReportInput& in) {
    std::vector<StepSeries> series;
    for (const MetricRow& r : in.results.rows) {
        if (r.engine == "analytic" || !is_step_case(in, r.case_id)) continue;
        const double dt = case_step(in, r.case_id);
        if (!std::isfinite(dt)) continue;
        const std::string base = step_base(r.case_id);
        auto it = std::find_if(series.begin(), series.end(), [&](const StepSeries& s) {
            return s.engine == r.engine && s.base_case == base && s.metric == r.metric;
        });
        if (it == series.end()) {
            series.push_back({r.engine, base, r.metric, {}, {}, 0.0});
            it = series.end() - 1;
        }
        it->dt.push_back(dt);
        it->rel_error.push_back(r.rel_error);
    }
    for (StepSeries& s : series) {
        std::vector<std::size_t> order(s.dt.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.dt[a] < s.dt[b]; });
        std::vector<double> dt, err;
        for (std::size_t i : order) {
            dt.push_back(s.dt[i]);
            err.push_back(s.rel_error[i]);
        }
        s.dt = dt;
        s.rel_error = err;
        // log|e| = p log dt + c, least squares over the points with a finite nonzero error.
        double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t i = 0; i < dt.size(); ++i) {
            if (!std::isfinite(err[i]) || err[i] == 0.0 || dt[i] <= 0.0) continue;
            const double x = std::log(dt[i]), y = std::log(std::abs(err[i]));
            n += 1;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        const double den = n * sxx - sx * sx;
        const bool fit = n >= static_cast<double>(kMinPointsForOrder) && den > 0.0;
        s.order = fit ? (n * sxy - sx * sy) / den : std::nan("");
        s.r_squared = std::nan("");
        if (fit) {  // the share of the variance of log|error| the line explains
            double syy = 0.0;
            for (std::size_t i = 0; i < dt.size(); ++i)
                if (std::isfinite(err[i]) && err[i] != 0.0 && dt[i] > 0.0) {
                    const double y = std::log(std::abs(err[i]));
                    syy += y * y;
                }
            const double var_y = n * syy - sy * sy;
            s.r_squared = var_y > 0.0 ? (n * sxy - sx * sy) * (n * sxy - sx * sy) / (den * var_y) : 1.0;
        }
    }
    std::stable_sort(series.begin(), series.end(), [](const StepSeries& a, const StepSeries& b) {
        return std::tie(a.engine, a.base_case, a.metric) < std::tie(b.engine, b.base_case, b.metric);
    });
    return series;
}

}  // namespace vssw::validation

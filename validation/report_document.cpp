#include "validation/report_document.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/text.hpp"
#include "multibody/host/contact_schemes.hpp"
#include "multibody/engine.hpp"
#include "validation/assumptions_part.hpp"
#include "validation/earthquake.hpp"

namespace vssw::validation {
namespace {

using Blocks = std::vector<io::DocBlock>;

std::string settings_text(const multibody::EngineSettings& s) {
    std::vector<std::string> knobs;
    for (const auto& [k, v] : s.knobs) knobs.push_back(fmt::format("{}={:g}", k, v));
    return knobs.empty() ? "defaults" : fmt::format("{}", fmt::join(knobs, ", "));
}

std::string case_detail(const ReportInput& in, const SuiteCase& c) {
    switch (c.kind) {
        case CaseKind::threshold: return "constant ground acceleration, bisection";
        case CaseKind::free: return fmt::format("free vibration from theta1 = {:g} alpha1", c.r);
        case CaseKind::step:
            return fmt::format("free vibration from theta1 = {:g} alpha1 at engine step {:g} ms{}", c.r,
                               c.dt ? *c.dt * 1e3 : NAN, c.engine.empty() ? "" : ", " + c.engine + " only");
        case CaseKind::history:
            for (const SuiteRecord& r : in.suite.records)
                if (r.id == c.record_id) return r.label;
            return c.record_id;
    }
    return "";
}

// A value for people, "n/a" when it was not measured.
std::string value_text(double v) { return std::isfinite(v) ? io::num(v) : "n/a"; }

std::string wall_label(const ReportInput& in, const std::string& id) {
    for (const SuiteWall& w : in.suite.walls)
        if (w.id == id) return w.label;
    return id;
}

io::DocBlock introduction(const ReportInput& in) {
    const SuiteResults& res = in.results;
    return io::paragraph(fmt::format(
        "Made {} by vssw{} on {}; {} thread{}, {:.1f} s. Every engine is measured against the analytic model "
        "of Sorrentino, Masiani & Griffith (2008) under the assumption set {}, every metric by the same code for "
        "every backend; relative error = engine / reference - 1. Targets: threshold {:g} %, period {:g} %, "
        "restitution {:g} %.",
        in.meta.date, in.meta.commit.empty() ? "" : " " + in.meta.commit, case_count_text(in.suite, res),
        res.threads, res.threads == 1 ? "" : "s", res.wall_time_s, describe(res.reference),
        100.0 * kReportThresholdTarget, 100.0 * kReportPeriodTarget, 100.0 * kReportRestitutionTarget));
}

// The matrix's text of a cell: the worst error (for overturning: agreement; for the rms difference: its share of the
// peak), then what was not measured or failed.
std::string matrix_text(const MatrixCell& c) {
    std::string text;
    if (c.rows == 0) text = c.failed > 0 ? "failed" : "n/a";
    else if (c.metric == "overturned")
        text = c.outside == 0 ? fmt::format("agrees {}/{}", c.rows, c.rows)
                              : fmt::format("differs {}/{}", c.outside, c.rows);
    else if (c.metric == "rms_difference")
        text = fmt::format("{:.2g} % of the peak", 100.0 * std::abs(c.worst_rel_error));
    else text = io::percent(c.worst_rel_error);
    if (c.rows > 0 && c.not_measured > 0) text += fmt::format(" ({} n/a)", c.not_measured);
    if (c.rows > 0 && c.failed > 0) text += fmt::format(" ({} failed)", c.failed);
    return text;
}

// The contact schemes of the compared engines, and what agreement within one and across them says.
std::string schemes_text(const std::vector<std::string>& engines) {
    std::string text = "Contact schemes (how each engine's defaults integrate the wall; docs/engines.md, \"Contact "
                       "schemes\"): ";
    std::vector<std::string> seen;
    for (const std::string& e : engines) {
        const multibody::ContactScheme s = multibody::contact_scheme(e);
        if (std::find(seen.begin(), seen.end(), s.key) != seen.end()) continue;
        std::vector<std::string> members;
        for (const std::string& other : engines)
            if (multibody::contact_scheme(other).key == s.key) members.push_back(multibody::engine_display_name(other));
        text += fmt::format("{}{} ({}): {}", seen.empty() ? "" : "; ", s.key, fmt::join(members, ", "), s.description);
        seen.push_back(s.key);
    }
    return text + ". Engines of one scheme share their dominant error, so their agreement with each other is one piece "
                  "of evidence, not several; agreement across schemes is independent.";
}

// The matrix's metrics: those with a target that some engine was measured on. A single run's peak under a record
// (no target) switches branch for a 1 % change of the scale, so it has no verdict here; the earthquake part judges the
// records by ensemble measures, and the tables under "Metrics" keep every single-run value.
std::vector<std::string> matrix_metrics(const ReportInput& in, const std::vector<MatrixCell>& cells) {
    std::vector<std::string> metrics;
    for (const std::string& m : metric_order(in.results))
        if (target_of(m).has_value() &&
            std::any_of(cells.begin(), cells.end(), [&](const MatrixCell& c) { return c.metric == m; }))
            metrics.push_back(m);
    return metrics;
}

// The analytic model under the other set, in the matrix's columns: its numbers with no verdict mark (no pass, no
// fail); under records the paper's model's numbers when the reference is the mechanism (the record ensemble's).
std::vector<io::DocCell> other_set_row(const ReportInput& in, const std::vector<std::string>& metrics) {
    const std::vector<MatrixCell> cells = other_set_matrix(in);
    std::vector<io::DocCell> row = {{other_set_label(in.results)}, {"- (a model, no contacts)"}};
    for (const std::string& m : metrics) {
        const auto c = std::find_if(cells.begin(), cells.end(), [&](const MatrixCell& x) { return x.metric == m; });
        io::DocCell cell{c == cells.end() ? "-" : matrix_text(*c)};
        if (c != cells.end() && !c->case_id.empty())
            cell.note = fmt::format("largest difference on {}; what the {} set's assumptions change, no verdict",
                                    c->case_id, to_string(in.results.other_set->set));
        row.push_back(std::move(cell));
    }
    if (in.earthquake) {
        const bool paper_row = in.results.other_set->set == AssumptionSet::paper;
        for (io::DocCell& c : paper_row ? earthquake_information_cells(*in.earthquake)
                                    : earthquake_information_cells(EarthquakePart{}))
            row.push_back(std::move(c));
    }
    return row;
}

void add_matrix(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "At a glance"));
    const std::vector<MatrixCell> cells = error_matrix(in);
    // Grouped by contact scheme: engines of one scheme share their dominant error (multibody/host/contact_schemes.hpp).
    const std::vector<std::string> engines = multibody::ordered_by_scheme(compared_engines(in.results));
    // The columns: the metrics some engine, or the other set, was measured on.
    std::vector<MatrixCell> all = cells;
    for (MatrixCell& c : other_set_matrix(in)) all.push_back(std::move(c));
    const std::vector<std::string> metrics = matrix_metrics(in, all);
    if (metrics.empty()) {
        b.push_back(io::paragraph("No engine was compared (the analytic model only)."));
        return;
    }
    std::vector<std::string> header = {"engine", "contact scheme"};
    for (const std::string& m : metrics)  // each has a target (matrix_metrics)
        header.push_back(fmt::format("{} (target {:g} %)", short_title(m), 100.0 * *target_of(m)));
    // The earthquake part's two ensemble measures, each with its target, as the last columns.
    if (in.earthquake)
        for (const std::string& h : earthquake_matrix_header()) header.push_back(h);
    io::DocBlock t = io::table(header, 2);
    t.css_class = "matrix";
    for (const std::string& e : engines) {
        std::vector<io::DocCell> row = {{multibody::engine_display_name(e)}, {multibody::contact_scheme(e).key}};
        for (const std::string& m : metrics) {
            const auto c = std::find_if(cells.begin(), cells.end(),
                                        [&](const MatrixCell& x) { return x.engine == e && x.metric == m; });
            if (c == cells.end()) {
                row.push_back({"-"});
                continue;
            }
            io::DocCell cell{matrix_text(*c)};
            cell.verdict = c->pass ? io::DocCell::Verdict::pass : io::DocCell::Verdict::fail;
            if (!c->case_id.empty())
                cell.note = fmt::format("worst on {}; {} of {} case{} outside the target", c->case_id, c->outside,
                                        c->rows, c->rows == 1 ? "" : "s");
            row.push_back(std::move(cell));
        }
        if (in.earthquake)
            for (io::DocCell& c : earthquake_matrix_cells(*in.earthquake, e)) row.push_back(std::move(c));
        t.rows.push_back(std::move(row));
    }
    if (in.results.other_set) t.rows.push_back(other_set_row(in, metrics));
    b.push_back(t);
    b.push_back(io::paragraph(
        "Each cell: the engine's error of largest magnitude over the cases of that metric (engine / reference - 1; the "
        "step study left out), passed when every case is measured and within the target, failed otherwise. The "
        "tables under \"Metrics\" give every case, the single runs under records too (no target, no verdict)."));
    if (in.results.other_set)
        b.push_back(io::paragraph(fmt::format(
            "The last row, {}, is the analytic model under the set {}, measured exactly as an engine against the "
            "reference (the set {}): its numbers are the cost of the assumptions of the set {}, not an error of any "
            "engine, and carry no verdict (no mark, and no effect on any engine's cells or on the report's exit "
            "status).",
            other_set_label(in.results), describe(in.results.other_set->set), to_string(in.results.reference),
            to_string(in.results.other_set->set))));
    b.push_back(io::paragraph(schemes_text(engines)));
    if (in.earthquake)
        for (io::DocBlock& block : earthquake_glance(*in.earthquake)) b.push_back(std::move(block));
}

void add_engines(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "Engines"));
    // Iterations only where an engine's settings set a count (Bullet's sequential-impulse iterations); the analytic
    // model, ODE's direct solver and Simbody have none.
    const bool any_iterations = std::any_of(in.results.engines.begin(), in.results.engines.end(),
                                            [](const EngineRunInfo& e) { return e.settings.iterations > 0; });
    std::vector<std::string> header = {"engine", "version", "dt [s]"};
    if (any_iterations) header.push_back("iterations");
    header.push_back("settings");
    // The earthquake part runs its ensemble file's settings ([settings.ENGINE]), which may differ from the suite's.
    if (in.earthquake) header.push_back("under records");
    io::DocBlock engines = io::table(header, header.size());
    for (const EngineRunInfo& e : in.results.engines) {
        std::vector<io::DocCell> row = {{e.name}, {e.version}, {fmt::format("{:g}", e.settings.dt)}};
        if (any_iterations)
            row.push_back({e.settings.iterations > 0 ? std::to_string(e.settings.iterations) : "-"});
        row.push_back({settings_text(e.settings)});
        if (in.earthquake) {
            const auto& v = in.earthquake->engines;
            const auto it = std::find_if(v.begin(), v.end(), [&](const EarthquakeVerdict& x) { return x.engine == e.name; });
            row.push_back({it == v.end() ? "-" : it->settings.empty() ? "defaults" : it->settings});
        }
        engines.rows.push_back(std::move(row));
    }
    b.push_back(engines);
    b.push_back(io::paragraph("The step cases of the error-against-step study override dt; everything else runs at the "
                          "settings above (under records: the settings the earthquake ensemble file gives)."));
}

void add_summary(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "Summary"));
    std::vector<std::string> lines;
    for (const EngineSummary& s : summarize(in)) lines.push_back(s.line);
    if (lines.empty()) lines.push_back("No engine was compared (the analytic model only).");
    b.push_back(io::list(lines));
    b.push_back(io::paragraph("Counted over the cases with a target, the step study left out (it varies the step on "
                          "purpose); max |error| is the signed error of largest magnitude per metric."));
}

void add_findings(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "Findings"));
    bool any_finding = false;
    for (const std::string& engine : compared_engines(in.results)) {
        const std::vector<std::string> found = findings(in, engine);
        if (found.empty()) continue;
        b.push_back(io::heading(3, multibody::engine_display_name(engine)));
        b.push_back(io::list(found));
        any_finding = true;
    }
    if (const std::string other = other_set_finding(in); !other.empty()) {
        b.push_back(io::heading(3, other_set_label(in.results)));
        b.push_back(io::list({other}));
        any_finding = true;
    }
    if (!any_finding) b.push_back(io::paragraph("Nothing to say: no engine results."));
}

void add_failures(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "Failures"));
    if (in.results.failures.empty()) {
        b.push_back(io::paragraph("None: every engine finished every case."));
        return;
    }
    io::DocBlock t = io::table({"case", "engine", "message"}, 3);
    for (const CaseFailure& f : in.results.failures)
        t.rows.push_back({{f.case_id}, {f.engine}, {f.message, true}});
    b.push_back(t);
    b.push_back(io::paragraph("A failed case has no value for that engine where it failed (a failed run: none at all; "
                          "an impact ratio outside (0, 1]: no restitution); the rest of the report is unaffected."));
}

void add_model_warnings(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "Where the analytic model warns"));
    if (in.results.model_warnings.empty()) {
        b.push_back(io::paragraph("Nowhere: along every analytic run the roller pushed, no contact pulled, the friction "
                              "needed stayed within that of masonry joints, and Eq. (3) was not used past its "
                              "validity."));
        return;
    }
    io::DocBlock t = io::table({"case", "warning"}, 2);
    for (const ModelWarning& w : in.results.model_warnings) t.rows.push_back({{w.case_id}, {w.message, true}});
    b.push_back(t);
    b.push_back(io::paragraph("The analytic values of these cases are the model's own, but one of its assumptions fails "
                          "along the run: an engine that differs there may be right."));
}

// What the metric is and what it is measured against; empty when there is nothing to say.
std::string metric_explanation(const MetricTable& mt) {
    std::set<std::string> references;
    for (const MetricTableRow& r : mt.rows)
        if (!r.reference_name.empty()) references.insert(r.reference_name);
    std::string text = metric_description(mt.metric);
    if (!references.empty())
        text += fmt::format("{}Reference: {}.", text.empty() ? "" : " ", fmt::join(references, "; "));
    if (mt.metric == "period" || mt.metric == "restitution")
        text += " Each engine's error is against the analytic model sampled at that engine's own sampling "
                "interval, so that both sides carry the same sampling error; the reference column shows the "
                "analytic model at its own (0.1 ms), which can differ from those in the last digits.";
    if (mt.target) text += " Errors in bold are outside the target.";
    return text;
}

// A case's row: the reference, then each engine's value and error (overturning as yes/no and agrees/differs).
std::vector<io::DocCell> metric_row(const MetricTable& mt, const MetricTableRow& r) {
    const bool yes_no_metric = mt.metric == "overturned";
    std::vector<io::DocCell> row = {{r.case_id}, {yes_no_metric ? io::yes_no(r.reference != 0.0) : value_text(r.reference)}};
    for (const MetricCell& c : r.cells) {
        if (c.failed && !c.present) {
            row.push_back({"failed", true});
            row.push_back({"failed", true});
        } else if (!c.present) {
            row.push_back({"-"});
            row.push_back({"-"});
        } else if (yes_no_metric) {
            row.push_back({io::yes_no(c.value != 0.0)});
            row.push_back({c.rel_error == 0.0 ? "agrees" : "differs", c.rel_error != 0.0});
        } else {
            const bool outside = mt.target && !(std::isfinite(c.rel_error) && std::abs(c.rel_error) <= *mt.target);
            row.push_back({value_text(c.value)});
            row.push_back({io::percent(c.rel_error), outside});
        }
    }
    return row;
}

void add_metric_tables(Blocks& b, const ReportInput& in) {
    b.push_back(io::heading(2, "Metrics"));
    for (const MetricTable& mt : metric_tables(in)) {
        b.push_back(io::heading(3, fmt::format("{}{}{}", metric_title(mt.metric),
                                           mt.unit.empty() ? "" : " [" + mt.unit + "]",
                                           mt.target ? fmt::format(" (target {:g} %)", 100.0 * *mt.target)
                                                     : " (no target)")));
        if (const std::string text = metric_explanation(mt); !text.empty()) b.push_back(io::paragraph(text));
        std::vector<std::string> header = {"case", "reference"};
        for (const std::string& e : mt.engines) {
            header.push_back(multibody::engine_display_name(e));
            header.push_back(multibody::engine_display_name(e) + " error");
        }
        io::DocBlock t = io::table(header, 1);
        for (const MetricTableRow& r : mt.rows) t.rows.push_back(metric_row(mt, r));
        b.push_back(t);
    }
}

void add_step_study(Blocks& b, const ReportInput& in) {
    const std::vector<StepSeries> steps = step_series(in);
    if (steps.empty()) return;
    b.push_back(io::heading(2, "Error against step size"));
    b.push_back(io::paragraph("Free vibrations re-run at several engine steps; the order is the least-squares slope of "
                          "log |error| against log dt (1 for a first-order integrator; near 0 when the error does not "
                          "come from the step)."));
    io::DocBlock t = io::table({"engine", "case", "metric", "relative error at dt", "fitted order"}, 4);
    for (const StepSeries& s : steps) {
        std::vector<std::string> points;
        for (std::size_t i = 0; i < s.dt.size(); ++i)
            points.push_back(fmt::format("{:g} ms: {}", s.dt[i] * 1e3, io::percent(s.rel_error[i])));
        t.rows.push_back({{multibody::engine_display_name(s.engine)}, {s.base_case}, {metric_title(s.metric)},
                          {fmt::format("{}", fmt::join(points, ", "))},
                          {std::isfinite(s.order) ? fmt::format("{:.2f}", s.order) : "-"}});
    }
    b.push_back(t);
}

// The error plot of each metric of the matrix (error_<metric>, validation/report_plots.hpp), in the matrix's order.
std::vector<std::string> measure_plot_names(const ReportInput& in) {
    std::vector<std::string> names;
    for (const std::string& m : matrix_metrics(in, error_matrix(in))) names.push_back("error_" + io::file_stem(m));
    return names;
}

// Right after the matrix: a figure for each of its measures (the errors per case and engine, the fragility under
// records), so that the first screens answer "which engine, how far off, where" before any detail.
void add_measure_figures(Blocks& b, const ReportInput& in, const std::vector<std::string>& measure_plots,
                         const io::PlotResult& plots, bool plots_skipped) {
    if (plots_skipped) return;
    Blocks figures;
    for (const std::string& name : measure_plots)
        for (const io::Plot& p : plots.plots)
            if (p.made && p.name == name) figures.push_back(io::plot(p.title, p.name));
    if (in.earthquake)
        for (io::DocBlock& block : earthquake_figure(*in.earthquake)) figures.push_back(std::move(block));
    if (figures.empty()) return;
    b.push_back(io::heading(2, "One figure per measure"));
    b.push_back(io::paragraph("Each engine's relative error on each case of a measure of the matrix, the target dashed (in "
                          "report.html, hover a point for its value); under records, each engine's fragility curve "
                          "beside the reference's."));
    for (io::DocBlock& f : figures) b.push_back(std::move(f));
}

// The plots not shown among the figures per measure (`shown`).
void add_plots(Blocks& b, const std::vector<std::string>& shown, const io::PlotResult& plots, bool plots_skipped) {
    b.push_back(io::heading(2, "Plots"));
    if (plots_skipped) {
        b.push_back(io::paragraph("Plots were not made (--no-plots)."));
        return;
    }
    if (!plots.note.empty()) b.push_back(io::paragraph("Plots: " + plots.note + "."));
    // The figures per measure are at the top (when drawn): the others here.
    const auto is_shown = [&](const io::Plot& p) { return std::find(shown.begin(), shown.end(), p.name) != shown.end(); };
    if (std::any_of(plots.plots.begin(), plots.plots.end(), [&](const io::Plot& p) { return p.made && is_shown(p); }))
        b.push_back(io::paragraph("The error plots of the matrix's measures are under \"One figure per measure\"."));
    io::PlotResult rest = plots;
    rest.plots.erase(std::remove_if(rest.plots.begin(), rest.plots.end(), is_shown), rest.plots.end());
    for (io::DocBlock& block : io::plot_blocks(rest)) b.push_back(std::move(block));
    if (plots.plots.empty() && plots.note.empty()) b.push_back(io::paragraph("No data to plot."));
}

void add_cases(Blocks& b, const ReportInput& in) {
    const std::set<std::string> ran = cases_that_ran(in.results);
    io::DocBlock t = io::table({"case", "kind", "wall", "what is done"}, 4);
    std::size_t not_run = 0;
    for (const SuiteCase& c : in.suite.cases) {
        if (ran.count(c.id) == 0) {
            ++not_run;
            continue;
        }
        t.rows.push_back({{c.id}, {kind_name(c.kind)}, {wall_label(in, c.wall_id)}, {case_detail(in, c)}});
    }
    if (t.rows.empty()) return;
    b.push_back(io::heading(2, "Cases"));
    b.push_back(t);
    if (not_run > 0)
        b.push_back(io::paragraph(fmt::format("{} more case{} of the suite did not run: the step study of {} not asked "
                                          "for (--engines).",
                                          not_run, not_run == 1 ? "" : "s", not_run == 1 ? "an engine" : "engines")));
}

void add_files(Blocks& b) {
    b.push_back(io::heading(2, "Files"));
    b.push_back(io::list({"results.json: everything above, machine-readable (NaN as null)",
                      "metrics.csv: one line per (case, engine, metric)", "failures.csv: one line per failure",
                      "traces.csv: the time histories (case_id, engine, t, theta1_over_alpha1, assumption)",
                      "plots/: each plot as .svg with the .gp script and .dat data that drew it"}));
}

}  // namespace

io::Document build_document(const ReportInput& in, const io::PlotResult& plots, bool plots_skipped) {
    io::Document doc;
    doc.title = fmt::format("vssw validation report: suite '{}'",
                            in.results.suite.empty() ? in.suite.name : in.results.suite);
    Blocks& b = doc.blocks;
    b.push_back(introduction(in));
    add_matrix(b, in);
    const std::vector<std::string> measure_plots = measure_plot_names(in);
    add_measure_figures(b, in, measure_plots, plots, plots_skipped);
    b.push_back(io::contents());
    add_engines(b, in);
    add_summary(b, in);
    add_findings(b, in);
    if (in.earthquake)
        for (io::DocBlock& block : earthquake_section(*in.earthquake)) b.push_back(std::move(block));
    if (in.relaxations)
        for (io::DocBlock& block : assumptions_section(*in.relaxations)) b.push_back(std::move(block));
    add_failures(b, in);
    add_model_warnings(b, in);
    add_metric_tables(b, in);
    add_step_study(b, in);
    add_plots(b, measure_plots, plots, plots_skipped);
    add_cases(b, in);
    add_files(b);
    return doc;
}

}  // namespace vssw::validation

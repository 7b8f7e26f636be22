#include "study/study_document.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "study/ensemble_outputs.hpp"
#include "study/spec.hpp"
#include "study/study_plots.hpp"
#include "study/study_prose.hpp"
#include "io/text.hpp"

namespace vssw::study {

const char* const kRunHeading = "Run";

namespace {

using Blocks = std::vector<io::DocBlock>;

std::string levels_text(const ColumnLevels& c) {
    std::vector<std::string> texts;
    for (std::uint32_t l : c.order) texts.push_back(c.texts[l]);
    return fmt::format("{}", fmt::join(texts, ", "));
}

std::string plural(long n, const std::string& noun) { return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s"); }

void add_introduction(Blocks& b, const StudyData& d) {
    if (!d.description.empty()) b.push_back(io::paragraph(d.description));
    const io::Json& study = d.manifest.at("study");
    b.push_back(io::paragraph(fmt::format("Study file {} (excitation: {}), identity {}. Written from the study folder's "
                                      "manifest.json and results.csv.",
                                      study.value("file", std::string()), d.kind,
                                      study.value("identity", std::string()))));
}

// The study's main figures, which open the page: the first tornado chart of the paper's physical assumptions (what a
// study that relaxes them is for), then those of the first of these sections that has any (the paper's rocking
// curves, an ensemble's fragility, the overturning maps, the values against the varied parameters), at most
// kGlanceFigures of them, then the first tornado chart (the largest effects of the model's assumptions).
std::vector<io::Plot> main_figures(const io::PlotResult& plots) {
    std::vector<io::Plot> out;
    const auto first_of = [&](const char* section) {
        for (const io::Plot& p : plots.plots)
            if (p.made && p.section == section) {
                out.push_back(p);
                return;
            }
    };
    first_of(kPhysicalTornadoSection);
    for (const char* section : {kRockingSection, kEnsembleSection, kMapSection, kValueSection}) {
        std::size_t added = 0;
        for (const io::Plot& p : plots.plots)
            if (p.made && p.section == section && added < kGlanceFigures) {
                out.push_back(p);
                ++added;
            }
        if (added > 0) break;
    }
    first_of(kTornadoSection);
    return out;
}

bool is_shown(const std::vector<io::Plot>& shown, const io::Plot& p) {
    return std::any_of(shown.begin(), shown.end(), [&](const io::Plot& s) { return s.name == p.name; });
}

io::DocBlock effects_table(const StudyData& d, const std::vector<Effect>& effects);

// What a reader came for, first: the main figures and the largest effects; every detail follows.
void add_glance(Blocks& b, const StudyDocumentInput& in, const std::vector<io::Plot>& figures) {
    const StudyData& d = in.data;
    // Each parameter and metric once, at its largest (effects come sorted largest first), as the sentences below
    // do: a parameter with many levels would otherwise fill the table with its own levels.
    std::vector<Effect> largest;
    std::set<std::pair<std::string, std::size_t>> said;
    for (const Effect& e : in.effects)
        if (e.pairs > 0 && largest.size() < kGlanceEffects && said.insert({e.parameter, e.metric}).second)
            largest.push_back(e);
    if (figures.empty() && largest.empty()) return;
    b.push_back(io::heading(2, "At a glance"));
    for (const io::Plot& p : figures) b.push_back(io::plot(p.title, p.name));
    if (largest.empty()) return;
    b.push_back(io::paragraph(fmt::format(
        "The {}, each parameter and metric at the level of its largest effect against its first (every level under "
        "\"Largest sensitivities first\"):",
        largest.size() == 1 ? std::string("largest effect") : fmt::format("{} largest effects", largest.size()))));
    b.push_back(effects_table(d, largest));
}

void add_varied(Blocks& b, const StudyData& d) {
    b.push_back(io::heading(2, "What varied"));
    std::vector<std::string> items;
    for (std::size_t c : d.varied())
        items.push_back(fmt::format("{}{}: {}", d.columns[c].key, d.columns[c].assumption ? " (assumption)" : "",
                                    levels_text(d.columns[c])));
    if (items.empty()) b.push_back(io::paragraph("Nothing: every case is the same wall under the same excitation."));
    else b.push_back(io::list(items));
}

void add_runs(Blocks& b, const StudyData& d) {
    b.push_back(io::heading(2, "What was run"));
    std::vector<std::string> items;
    std::vector<std::string> engines;
    for (const io::Json& e : d.manifest.at("engines"))
        engines.push_back(fmt::format("{} ({})", e.at("name").get<std::string>(), e.at("version").get<std::string>()));
    items.push_back(fmt::format("Engines: {}.", fmt::join(engines, ", ")));
    std::vector<std::string> series;
    for (const Series& s : d.series) series.push_back(s.label);
    items.push_back(fmt::format("Runs of every case (a line each in the plots): {}.", fmt::join(series, "; ")));
    std::vector<std::string> assumptions;
    for (std::size_t c : d.assumption_columns)
        if (c != std::string::npos && !d.columns[c].order.empty())
            assumptions.push_back(fmt::format("{} {}", d.columns[c].key, levels_text(d.columns[c])));
    if (!assumptions.empty())
        items.push_back(fmt::format("The analytic model's assumptions: {} (engines ignore them).",
                                    fmt::join(assumptions, "; ")));
    std::vector<std::string> skipped;
    for (const io::Json& s : d.manifest.value("skipped_runs", io::Json::array())) skipped.push_back(s.get<std::string>());
    items.push_back(skipped.empty() ? "Skipped runs: none."
                                    : fmt::format("Skipped runs: {}.", fmt::join(skipped, "; ")));
    std::vector<std::string> metrics;
    for (const MetricMeta& m : d.metrics) metrics.push_back(fmt::format("{}: {}", metric_label(m), m.description));
    items.push_back(fmt::format("Metrics: {}.", fmt::join(metrics, "; ")));
    b.push_back(io::list(items));
}

void add_counts(Blocks& b, const StudyData& d) {
    b.push_back(io::heading(2, "Counts"));
    const io::Json& cases = d.manifest.at("cases");
    const io::Json& tasks = d.manifest.at("tasks");
    std::vector<std::string> items;
    items.push_back(fmt::format("{} of the {} in the grid (a repeat, such as a parapet at a second hinge, is left "
                                "out).",
                                plural(cases.at("run").get<long>(), "case"), cases.at("in_grid").get<long>()));
    items.push_back(fmt::format("{} (case x run).",
                                plural(tasks.at("run").get<long>() + tasks.at("resumed").get<long>(), "task")));
    std::string failed = fmt::format("{}, {} failed", plural(static_cast<long>(d.rows.size()), "row"), d.failed_rows);
    if (d.failed_rows > 0) {
        std::vector<std::pair<std::string, long>> reasons(d.failure_reasons.begin(), d.failure_reasons.end());
        std::stable_sort(reasons.begin(), reasons.end(),
                         [](const auto& x, const auto& y) { return x.second > y.second; });
        if (reasons.size() > kMaxFailureReasons) reasons.resize(kMaxFailureReasons);
        std::vector<std::string> listed;
        for (const auto& [reason, n] : reasons) listed.push_back(fmt::format("\"{}\" ({})", reason, n));
        failed +=
            fmt::format("; the most common reason{}: {}", reasons.size() == 1 ? "" : "s", fmt::join(listed, ", "));
    }
    items.push_back(failed + ".");
    items.push_back(fmt::format("{} ({}) carry the analytic model's own warnings (one of its assumptions failing along "
                                "the run; the warnings column says which).",
                                plural(d.warned_rows, "row"), plural(d.warned_tasks, "task")));
    b.push_back(io::list(items));
}

io::DocBlock effects_table(const StudyData& d, const std::vector<Effect>& effects) {
    io::DocBlock t = io::table({"parameter", "from", "to", "metric", "median change", "range", "pairs"}, 4);
    for (const Effect& e : effects) {
        std::string median = "-", range = "-";
        if (e.pairs > 0 && e.binary) {
            median = fmt::format("net {}", io::percent(e.median));
            range = fmt::format("{} to 1, {} to 0", e.up, e.down);
        } else if (e.pairs > 0) {
            const bool factor = shown_as_factor(e);
            median = change_text(e.median, factor);
            range = fmt::format("{} to {}", change_text(e.lo, factor), change_text(e.hi, factor));
        }
        t.rows.push_back({{e.parameter}, {e.from}, {e.to}, {d.metrics[e.metric].name}, {median}, {range},
                          {std::to_string(e.pairs)}});
    }
    return t;
}

void add_sensitivities(Blocks& b, const StudyData& d, const std::vector<Effect>& effects) {
    b.push_back(io::heading(2, "Largest sensitivities first"));
    if (d.varied().empty()) {
        b.push_back(io::paragraph("Nothing varied: there is no sensitivity to report."));
        return;
    }
    b.push_back(io::paragraph(
        "Each varied parameter against its first level: runs are paired that differ in that parameter alone (the same "
        "engine and settings, the same levels of everything else that varies), and the change of a metric is its "
        "value over the value at the first level, minus 1 (for a 0/1 metric, the pairs that flip). Sorted by the size "
        "of the median change (of the share of pairs that flip); a sentence for each parameter and metric at its "
        "largest, the table below for every level."));
    // One sentence per parameter and metric, its largest change (effects come sorted largest first): a parameter
    // with many levels would otherwise fill the list with its own levels and hide the others (the table has them all).
    std::vector<std::string> sentences;
    std::set<std::pair<std::string, std::size_t>> said;
    for (const Effect& e : effects)
        if (sentences.size() < kMaxSensitivitySentences && e.pairs > 0 && said.insert({e.parameter, e.metric}).second)
            sentences.push_back(effect_sentence(d, e));
    if (sentences.empty()) b.push_back(io::paragraph("No pair of runs gives a change: every paired value is missing."));
    else b.push_back(io::list(sentences));
    const bool any_assumption = std::any_of(d.columns.begin(), d.columns.end(), [](const ColumnLevels& c) {
        return (c.assumption || c.physical) && c.varied;
    });
    if (!any_assumption)
        b.push_back(io::paragraph("No assumption of the analytic model or of the paper varied: nothing here is the "
                                  "effect of one, and there are no tornado charts."));
    b.push_back(effects_table(d, effects));
}

void add_agreement(Blocks& b, const StudyData& d, const std::vector<Agreement>& agreement) {
    if (agreement.empty()) return;
    b.push_back(io::heading(2, "Engines against the analytic model"));
    b.push_back(io::paragraph("Case by case, each engine's value against the analytic model's under each of its "
                          "assumption sets: the median and largest |engine/analytic - 1| (for a 0/1 metric, the cases "
                          "whose values differ). Each sentence names the set with the smallest median gap first."));
    b.push_back(io::list(agreement_sentences(d, agreement)));
    for (std::size_t i = 0; i < agreement.size();) {
        const std::size_t engine = agreement[i].engine;
        b.push_back(io::heading(3, d.series[engine].label));
        io::DocBlock t = io::table({"metric", "analytic model with", "cases", "median |engine/analytic - 1|", "largest"}, 2);
        for (; i < agreement.size() && agreement[i].engine == engine; ++i) {
            const Agreement& g = agreement[i];
            const bool none = g.cases == 0;
            const std::string median = none       ? "-"
                                       : g.binary ? fmt::format("{} disagree", g.disagree)
                                                  : unsigned_percent(g.median);
            t.rows.push_back({{d.metrics[g.metric].name},
                              {assumption_set(d, g.analytic)},
                              {std::to_string(g.cases)},
                              {median},
                              {none || g.binary ? "-" : unsigned_percent(g.largest)}});
        }
        b.push_back(t);
    }
}

void add_plots(Blocks& b, const StudyDocumentInput& in, const std::vector<io::Plot>& shown) {
    b.push_back(io::heading(2, "Plots"));
    if (in.plots_skipped) {
        b.push_back(io::paragraph("Plots were not made (--no-plots)."));
        return;
    }
    if (!in.plots.note.empty()) b.push_back(io::paragraph("Plots: " + in.plots.note + "."));
    for (const std::string& note : in.plot_notes.notes) b.push_back(io::paragraph(note));
    // The main figures are at the top ("At a glance"): the others here.
    io::PlotResult rest = in.plots;
    rest.plots.erase(std::remove_if(rest.plots.begin(), rest.plots.end(),
                                    [&](const io::Plot& p) { return is_shown(shown, p); }),
                     rest.plots.end());
    if (!shown.empty()) b.push_back(io::paragraph("The main figures are under \"At a glance\"."));
    for (io::DocBlock& block : io::plot_blocks(rest)) b.push_back(std::move(block));
    if (in.plots.plots.empty() && in.plots.note.empty()) b.push_back(io::paragraph("No plot applies to this study."));
}

void add_run(Blocks& b, const StudyData& d) {
    const io::Json& m = d.manifest;
    b.push_back(io::heading(2, kRunHeading));
    const std::string commit = m.at("vssw").value("commit", std::string());
    const std::size_t shards = m.contains("merged_from") ? m.at("merged_from").size() : 0;
    b.push_back(io::paragraph(fmt::format(
        "Ended {} (vssw {}), {:.1f} s on {} thread{} x {} process{}{}.", m.value("date", std::string()),
        commit.empty() ? "of an unknown commit" : commit, m.value("wall_time_s", 0.0), m.value("threads", 1),
        m.value("threads", 1) == 1 ? "" : "s", m.value("processes", 1), m.value("processes", 1) == 1 ? "" : "es",
        shards > 0 ? fmt::format(", merged from {} shards (the longest shard's time)", shards) : "")));
}

void add_files(Blocks& b) {
    b.push_back(io::heading(2, "Files"));
    b.push_back(io::list({"results.csv: one row per case x run x metric (the parameters as columns, the value, its unit, "
                      "status, the analytic model's warnings)",
                      "results.json: the same rows with the manifest's keys (numbers as numbers, empty as null)",
                      "manifest.json: the study as read, its identity, shard, engines' versions, commit, wall time",
                      "study.md, study.html: this document (the HTML self-contained, plots inline)",
                      "plots/: each plot as .svg with the .gp script and .dat data that drew it"}));
}

}  // namespace

io::Document build_study_document(const StudyDocumentInput& in) {
    const StudyData& d = in.data;
    io::Document doc;
    doc.title = fmt::format("vssw study: {}", d.name);
    Blocks& b = doc.blocks;
    add_introduction(b, d);
    // The main figures open the page and are not shown again under "Plots".
    const std::vector<io::Plot> figures = in.plots_skipped ? std::vector<io::Plot>{} : main_figures(in.plots);
    add_glance(b, in, figures);
    add_varied(b, d);
    add_runs(b, d);
    add_counts(b, d);
    add_sensitivities(b, d, in.effects);
    add_agreement(b, d, in.agreement);
    if (in.ensemble) add_ensemble_section(b, d, *in.ensemble);
    add_plots(b, in, figures);
    add_run(b, d);
    add_files(b);
    return doc;
}

}  // namespace vssw::study

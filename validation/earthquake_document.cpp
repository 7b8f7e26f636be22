// The earthquake part in the report's document: two verdict columns of the matrix under "At a glance", the fragility
// plot among the figures per measure, and a section with the numbers, their intervals and the ensemble's plots.
#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "multibody/engine.hpp"
#include "validation/earthquake.hpp"

namespace vssw::study {
namespace {

std::string interval_text(const compare::Interval& i, const char* format) {
    if (!std::isfinite(i.value)) return "n/a";
    return fmt::format("{} [{}, {}]", fmt::format(fmt::runtime(format), i.value),
                       std::isfinite(i.lo) ? fmt::format(fmt::runtime(format), i.lo) : "?",
                       std::isfinite(i.hi) ? fmt::format(fmt::runtime(format), i.hi) : "?");
}

DocCell verdict_cell(std::string text, bool pass, std::string note) {
    DocCell c{std::move(text)};
    c.verdict = pass ? DocCell::Verdict::pass : DocCell::Verdict::fail;
    c.note = std::move(note);
    return c;
}

std::string peak_text(const compare::Quartiles& q) {
    if (q.n == 0 || !std::isfinite(q.median)) return "n/a";
    return fmt::format("{:.3f} ({:.3f}-{:.3f}, {} runs)", q.median, q.q1, q.q3, q.n);
}

std::string ensemble_text(const EarthquakePart& p) {
    return fmt::format("{} records x {} PGA levels of study '{}'", p.records, p.levels, p.study_name);
}

std::string agreement_header() {
    return fmt::format("overturning agreement (target >= {:g})", kOverturningAgreementTarget);
}
std::string fragility_header() {
    return fmt::format("fragility median / reference (target 1 +- {:g})", kFragilityMedianTarget);
}

DocCell agreement_cell(const EarthquakeVerdict& v) {
    return verdict_cell(interval_text(v.agreement, "{:.3f}"), v.agreement_pass,
                        fmt::format("{} runs, 95 % Wilson interval", v.agreement.n));
}
DocCell fragility_cell(const EarthquakeVerdict& v) {
    // No fit: a short cell (the reason in its tooltip and under the section's table), the table stays narrow.
    return verdict_cell(v.fit_note.empty() ? interval_text(v.median_ratio, "{:.3f}") : "no fit", v.fragility_pass,
                        v.fit_note.empty() ? "95 % paired bootstrap interval over the records" : v.fit_note);
}

// The ensemble's plots that were drawn, in the order the report shows them.
struct EnsemblePlot {
    std::string kind;  // "fragility" or "stripes": the file stem in the ensemble's plots/
    std::string name;  // for plot(): the path from the report's plots/ without ".svg"
    std::string title;
};
std::vector<EnsemblePlot> drawn_plots(const EarthquakePart& p) {
    std::vector<EnsemblePlot> out;
    const std::filesystem::path plots = p.folder / "plots";
    for (const auto& [kind, title] :
         {std::pair<const char*, const char*>{"fragility",
                                              "Under records: lognormal fragility fits and the stripes' shares"},
          {"stripes", "Under records: share overturned at each PGA level (95 % Wilson bars)"}})
        if (std::filesystem::exists(plots / (std::string(kind) + ".svg")))
            out.push_back({kind, "../" + p.folder.filename().string() + "/plots/" + kind, title});
    return out;
}

DocBlock verdict_table(const EarthquakePart& p) {
    DocBlock t = table({"engine", agreement_header(), fragility_header(),
                        "peak ratio where both stand: median (quartiles)", "inside the reference's band"},
                       1);
    t.apart_from = 3;
    t.css_class = "matrix";
    for (const EarthquakeVerdict& v : p.engines) {
        t.rows.push_back({{multibody::engine_display_name(v.engine)},
                          agreement_cell(v),
                          fragility_cell(v),
                          {peak_text(v.peak_ratio)},
                          {v.band_runs > 0 ? fmt::format("{} of {}", v.inside, v.band_runs) : "n/a"}});
    }
    return t;
}

}  // namespace

std::vector<std::string> earthquake_summary_lines(const EarthquakePart& p) {
    std::vector<std::string> lines;
    for (const EarthquakeVerdict& v : p.engines)
        lines.push_back(fmt::format(
            "{} under records: overturning agrees on {}/{} (target >= {:g}) {}; fragility median {} (target 1 +- {:g}) "
            "{}",
            multibody::engine_display_name(v.engine),
            std::isfinite(v.agreement.value) ? std::lround(v.agreement.value * static_cast<double>(v.agreement.n)) : 0,
            v.agreement.n, kOverturningAgreementTarget, v.agreement_pass ? "pass" : "FAIL",
            v.fit_note.empty() ? "x " + interval_text(v.median_ratio, "{:.3f}") : "not fitted (" + v.fit_note + ")",
            kFragilityMedianTarget, v.fragility_pass ? "pass" : "FAIL"));
    return lines;
}

std::vector<std::string> earthquake_matrix_header() {
    return {"records: " + agreement_header(), "records: " + fragility_header()};
}

std::vector<DocCell> earthquake_matrix_cells(const EarthquakePart& p, const std::string& engine) {
    for (const EarthquakeVerdict& v : p.engines)
        if (v.engine == engine) return {agreement_cell(v), fragility_cell(v)};
    return {{"-"}, {"-"}};
}

std::vector<DocBlock> earthquake_glance(const EarthquakePart& p) {
    return {paragraph(fmt::format(
        "The two \"records\" columns judge the engines under earthquake records ({}; the reference is {}): the share "
        "of runs on which each engine agrees with the reference whether the wall overturns, and its lognormal "
        "fragility median against the reference's, each with its 95 % interval. Single runs are not judged: their "
        "peaks switch branch for a 1 % change of the scale. Details under \"Under earthquake records\".",
        ensemble_text(p), p.reference))};
}

std::vector<DocBlock> earthquake_figure(const EarthquakePart& p) {
    std::vector<DocBlock> b;
    for (const EnsemblePlot& e : drawn_plots(p))
        if (e.kind == "fragility") b.push_back(plot(e.title, e.name));
    return b;
}

std::vector<DocBlock> earthquake_section(const EarthquakePart& p) {
    std::vector<DocBlock> b;
    b.push_back(heading(2, "Under earthquake records"));
    b.push_back(paragraph(fmt::format(
        "{}: {}. The reference is {}: what the engines' physics shares (exact kinematics, the whole mechanism's "
        "impact, a roller that can only push); its fragility median is {} g. Each engine ran every record at every "
        "level once{}. A run an engine failed counts as one it does not agree on. {} rows, {} failed; {:.1f} s.",
        ensemble_text(p), p.description, p.reference, interval_text(p.reference_median, "{:.3g}"),
        p.band ? "; the reference ran each also at PGA x (1 +- 1e-3) and with the record's first sample dropped, "
                 "whose spread is the response's own sensitivity (the band)"
               : " (no band: the study does not ask for one)",
        p.rows, p.failed_rows, p.wall_time_s)));
    b.push_back(verdict_table(p));
    b.push_back(paragraph(fmt::format(
        "Targets, set from measurements (docs/earthquakes.md, which keeps each engine's): overturning agreement at "
        "least {:g} (the reference's own band flips 1 run in 40 on a larger ensemble); fragility median within {:g} % "
        "of the reference's (the paper's Eq. (19) impact moves the reference's own median by +14 %). With 16 runs an "
        "interval is wide: a "
        "verdict says what this ensemble shows, studies/ensemble-full.toml measures it on 46 motions and three walls.",
        kOverturningAgreementTarget, 100.0 * kFragilityMedianTarget)));
    std::vector<std::string> unfitted;
    for (const EarthquakeVerdict& v : p.engines)
        if (!v.fit_note.empty())
            unfitted.push_back(fmt::format("{}: {}", multibody::engine_display_name(v.engine), v.fit_note));
    if (!unfitted.empty()) {
        b.push_back(paragraph("No fragility fit:"));
        b.push_back(list(unfitted));
    }
    std::vector<std::string> outside;
    for (const EarthquakeVerdict& v : p.engines)
        if (!v.outside.empty())
            outside.push_back(fmt::format("{}: {}", multibody::engine_display_name(v.engine), fmt::join(v.outside, "; ")));
    if (!outside.empty()) {
        b.push_back(paragraph("Runs whose peak lies outside the reference's band (where a difference is the engine's "
                              "and not the response's own sensitivity, or the band is narrower than the step's "
                              "error):"));
        b.push_back(list(outside));
    }
    // The fragility plot is among the figures per measure at the top (earthquake_figure): the rest here.
    for (const EnsemblePlot& e : drawn_plots(p))
        if (e.kind != "fragility") b.push_back(plot(e.title, e.name));
    b.push_back(paragraph(fmt::format(
        "Every number is in {0}/agreement.csv and {0}/fragility.csv, every run in {0}/results.csv; {0}/study.html "
        "is the ensemble's own study report.",
        p.folder.filename().string())));
    return b;
}

}  // namespace vssw::study

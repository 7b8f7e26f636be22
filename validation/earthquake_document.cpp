// The earthquake part in the report's document: two verdict columns of the matrix under "At a glance", the fragility
// plot among the figures per measure, and a section with the numbers, their intervals and the ensemble's plots.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "multibody/engine.hpp"
#include "validation/earthquake.hpp"

namespace vssw::validation {
namespace {

std::string interval_text(const compare::Interval& i, const char* format) {
    if (!std::isfinite(i.value)) return "n/a";
    return fmt::format("{} [{}, {}]", fmt::format(fmt::runtime(format), i.value),
                       std::isfinite(i.lo) ? fmt::format(fmt::runtime(format), i.lo) : "?",
                       std::isfinite(i.hi) ? fmt::format(fmt::runtime(format), i.hi) : "?");
}

io::DocCell verdict_cell(std::string text, bool pass, std::string note) {
    io::DocCell c{std::move(text)};
    c.verdict = pass ? io::DocCell::Verdict::pass : io::DocCell::Verdict::fail;
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

std::string peak_header() {
    return fmt::format("peak ratio where both stand, median [95 %] (target: median within x {:.3f}^+-1)",
                       std::exp(kPeakLogRatioTarget));
}
std::string overturning_header() {
    return fmt::format("overturning: discordant b/c, McNemar p (target p >= {:g}, agreement >= {:g})", kMcNemarAlpha,
                       kOverturningAgreementTarget);
}
std::string fragility_header() { return "fragility median / reference (information)"; }

// exp of the median ln ratio with its interval: the median peak ratio ("0.965 [n.r.]": too few records for one).
std::string peak_ratio_text(const EarthquakeVerdict& v) {
    const compare::Interval& d = v.log_peak.median;
    if (!v.log_peak.reason.empty() && std::isfinite(d.value)) return fmt::format("{:.3f} [n.r.]", std::exp(d.value));
    return interval_text({std::exp(d.value), std::exp(d.lo), std::exp(d.hi), d.n}, "{:.3f}");
}
// What "[n.r.]" says, for the paragraphs under the tables ("" when every interval is resolved).
std::string unresolved_peak_text(const EarthquakePart& p) {
    for (const EarthquakeVerdict& v : p.engines)
        if (!v.log_peak.reason.empty())
            return fmt::format(" [n.r.]: the peak ratio's interval is {}.", v.log_peak.reason);
    return "";
}
std::string overturning_text(const EarthquakeVerdict& v) {
    return fmt::format("{}/{}{}, p {:.3f}, {}/{}", v.overturned_alone, v.stood_alone,
                       v.failed_paired > 0 ? fmt::format(" +{} failed", v.failed_paired) : "", v.mcnemar_p,
                       std::isfinite(v.agreement.value)
                           ? std::lround(v.agreement.value * static_cast<double>(v.agreement.n))
                           : 0,
                       v.agreement.n);
}

io::DocCell peak_cell(const EarthquakeVerdict& v) {
    return verdict_cell(peak_ratio_text(v), v.peak_pass,
                        fmt::format("{} runs of {} records; {}", v.log_peak.values, v.log_peak.records,
                                    v.log_peak.reason.empty()
                                        ? "95 % interval: order statistics of the records' medians"
                                        : v.log_peak.reason));
}
io::DocCell overturning_cell(const EarthquakeVerdict& v) {
    return verdict_cell(overturning_text(v), v.overturning_pass,
                        "b: it overturned where the reference stood, c: the reverse (a failed run counts on the "
                        "larger side); exact McNemar p; runs agreeing");
}
io::DocCell fragility_cell(const EarthquakeVerdict& v) {
    // No fit: a short cell (the reason in its tooltip and under the section's table), the table stays narrow.
    io::DocCell c{v.fit_note.empty() ? interval_text(v.median_ratio, "{:.3f}") : "not resolved"};
    c.note = v.fit_note.empty() ? "95 % paired bootstrap interval over the records" : v.fit_note;
    return c;
}

// The ensemble's plots that were drawn, in the order the report shows them.
struct EnsemblePlot {
    std::string kind;  // "fragility_by_engine", "engine_peaks", "fragility" or "stripes": the stem in its plots/
    std::string name;  // for plot(): the path from the report's plots/ without ".svg"
    std::string title;
};
std::vector<EnsemblePlot> drawn_plots(const EarthquakePart& p) {
    std::vector<EnsemblePlot> out;
    const std::filesystem::path plots = p.folder / "plots";
    for (const auto& [kind, title] :
         {std::pair<const char*, const char*>{"fragility_by_engine",
                                              "Under records: each engine's fragility against the reference's, a "
                                              "panel per engine (a fit not resolved: its stripes only)"},
          {"engine_peaks", "Under records: each engine's peak against the reference's, run by run (log-log; the "
                           "identity line, the reference's band as a bar, overturned runs at the edge)"},
          {"fragility", "Under records: lognormal fragility fits and the stripes' shares, every series overlaid"},
          {"stripes", "Under records: share overturned at each PGA level (95 % Wilson bars)"}})
        if (std::filesystem::exists(plots / (std::string(kind) + ".svg")))
            out.push_back({kind, "../" + p.folder.filename().string() + "/plots/" + kind, title});
    return out;
}

io::DocBlock verdict_table(const std::vector<EarthquakeVerdict>& verdicts, bool band) {
    std::vector<std::string> header = {"engine", peak_header(), overturning_header(), fragility_header(),
                                       "peak ratio: median (quartiles)"};
    if (band) header.push_back("inside the reference's band");
    io::DocBlock t = io::table(header, 1);
    t.apart_from = 3;
    t.css_class = "matrix";
    for (const EarthquakeVerdict& v : verdicts) {
        std::vector<io::DocCell> row = {{multibody::engine_display_name(v.engine)}, peak_cell(v), overturning_cell(v),
                                    fragility_cell(v), {peak_text(v.peak_ratio)}};
        if (band) row.push_back({v.band_runs > 0 ? fmt::format("{} of {}", v.inside, v.band_runs) : "n/a"});
        t.rows.push_back(std::move(row));
    }
    return t;
}

// The detection limit in words: what this ensemble's verdicts fail.
std::string detection_text(const EarthquakePart& p) {
    if (p.stand_ins.empty()) return "no stand-ins ran";
    double largest = 0.0;
    for (const auto& [error, v] : p.stand_ins) largest = std::max(largest, std::abs(error));
    if (!std::isfinite(p.detection_limit))
        return fmt::format("this ensemble does not fail every restitution error up to {:g} %: its verdicts detect "
                           "less than that",
                           100.0 * largest);
    return fmt::format("this ensemble fails a restitution error of {:g} % or more", 100.0 * p.detection_limit);
}

}  // namespace

std::vector<std::string> earthquake_summary_lines(const EarthquakePart& p) {
    std::vector<std::string> lines;
    for (const EarthquakeVerdict& v : p.engines)
        lines.push_back(fmt::format(
            "{} under records: {}; peaks x {} (target: median within x {:.3f}^+-1) {}; overturning b/c {} (target p >= "
            "{:g}, agreement >= {:g}) {}; fragility median {} (information)",
            multibody::engine_display_name(v.engine), v.pass ? "pass" : "FAIL", peak_ratio_text(v),
            std::exp(kPeakLogRatioTarget), v.peak_pass ? "pass" : "FAIL", overturning_text(v), kMcNemarAlpha,
            kOverturningAgreementTarget, v.overturning_pass ? "pass" : "FAIL",
            v.fit_note.empty() ? "x " + interval_text(v.median_ratio, "{:.3f}") : v.fit_note));
    lines.push_back("Under records: " + detection_text(p) + " (analytic stand-ins)");
    return lines;
}

std::vector<std::string> earthquake_matrix_header() {
    return {"records: " + peak_header(), "records: " + overturning_header()};
}

std::vector<io::DocCell> earthquake_matrix_cells(const EarthquakePart& p, const std::string& engine) {
    for (const EarthquakeVerdict& v : p.engines)
        if (v.engine == engine) return {peak_cell(v), overturning_cell(v)};
    return {{"-"}, {"-"}};
}

std::vector<io::DocCell> earthquake_information_cells(const EarthquakePart& p) {
    if (!p.paper_model) return {{"-"}, {"-"}};
    const EarthquakeVerdict& v = *p.paper_model;
    std::vector<io::DocCell> cells = {io::DocCell(peak_ratio_text(v)), io::DocCell(overturning_text(v))};
    for (io::DocCell& c : cells) c.note = "the paper's model against the reference under records: no verdict";
    return cells;
}

std::vector<io::DocBlock> earthquake_glance(const EarthquakePart& p) {
    return {io::paragraph(fmt::format(
        "The two \"records\" columns judge the engines under earthquake records ({}; the reference is {}), run by "
        "run against the reference: the median ratio of its peak to the reference's where both stand (95 % interval "
        "over records), and the runs where only it or only the reference overturned (an exact McNemar test). An "
        "engine passes only when both pass; {}. Details under \"Under earthquake records\".{}",
        ensemble_text(p), p.reference, detection_text(p), unresolved_peak_text(p)))};
}

std::vector<io::DocBlock> earthquake_figure(const EarthquakePart& p) {
    std::vector<io::DocBlock> b;
    for (const EnsemblePlot& e : drawn_plots(p))
        if (e.kind == "fragility_by_engine") b.push_back(io::plot(e.title, e.name));
    return b;
}

std::vector<io::DocBlock> earthquake_section(const EarthquakePart& p) {
    std::vector<io::DocBlock> b;
    b.push_back(io::heading(2, "Under earthquake records"));
    b.push_back(io::paragraph(fmt::format(
        "{}: {}. The reference is {}: what the engines' physics shares (exact kinematics, the whole mechanism's "
        "impact, a roller that can only push); its fragility median is {}. Each engine ran every record at every "
        "level once{}. A run an engine failed counts as one it does not agree on. {} rows, {} failed; {:.1f} s.",
        ensemble_text(p), p.description, p.reference,
        p.reference_note.empty() ? interval_text(p.reference_median, "{:.3g}") + " g" : p.reference_note,
        p.band ? "; the reference ran each also at PGA x (1 +- 1e-2), every impact's ratio x (1 +- 2e-2) and the "
                 "wall's size x (1 +- 1e-2): how far its response moves within the free-vibration targets (the band)"
               : " (no band: the study does not ask for one)",
        p.rows, p.failed_rows, p.wall_time_s)));
    b.push_back(verdict_table(p.engines, p.band));
    b.push_back(io::paragraph(fmt::format(
        "An engine passes when both verdicts pass. Peaks: over the runs where both stand, the median of ln(its peak / "
        "the reference's) within +-{:g} (the median peak ratio within x {:.3f}^+-1; every engine at its defaults and "
        "at a quarter of its step measured within 0.036, a restitution error of 5 % at 0.052 or more: thin margins on "
        "this ensemble, docs/earthquakes.md; the bracket, not judged, is the distribution-free 95 % interval from the "
        "records' own medians, shown from 6 records with a run where both stand, else n.r.: not resolved). "
        "Overturning: b runs where only it overturned, c where "
        "only the reference did; the exact McNemar p of b against c at least {:g}, and agreement on at least {:g} of "
        "the runs. The fragility median's ratio is information: on a few records its interval spans tens of percent.",
        kPeakLogRatioTarget, std::exp(kPeakLogRatioTarget), kMcNemarAlpha, kOverturningAgreementTarget)));
    if (!p.stand_ins.empty()) {
        b.push_back(io::paragraph(fmt::format(
            "Detection limit: {}. The analytic model with every impact's velocity ratio changed by a known fraction "
            "(its restitution_error setting) ran on the same runs as stand-in engines and was judged by the same "
            "rules ({}/stand-ins):",
            detection_text(p), p.folder.filename().string())));
        std::vector<EarthquakeVerdict> stand_ins;
        for (const auto& [error, v] : p.stand_ins) stand_ins.push_back(v);
        b.push_back(verdict_table(stand_ins, false));
    }
    std::vector<std::string> unfitted;
    for (const EarthquakeVerdict& v : p.engines)
        if (!v.fit_note.empty())
            unfitted.push_back(fmt::format("{}: {}", multibody::engine_display_name(v.engine), v.fit_note));
    if (!unfitted.empty()) {
        b.push_back(io::paragraph("Fragility ratios not resolved (the data do not support a fit or an interval):"));
        b.push_back(io::list(unfitted));
    }
    std::vector<std::string> outside;
    for (const EarthquakeVerdict& v : p.engines)
        if (!v.outside.empty())
            outside.push_back(fmt::format("{}: {}", multibody::engine_display_name(v.engine), fmt::join(v.outside, "; ")));
    if (!outside.empty()) {
        b.push_back(io::paragraph("Runs whose peak lies outside the reference's band (where a difference is the engine's "
                              "and not the response's own sensitivity, or the band is narrower than the step's "
                              "error):"));
        b.push_back(io::list(outside));
    }
    // The fragility per engine is among the figures per measure at the top (earthquake_figure): the rest here.
    for (const EnsemblePlot& e : drawn_plots(p))
        if (e.kind != "fragility_by_engine") b.push_back(io::plot(e.title, e.name));
    b.push_back(io::paragraph(fmt::format(
        "Every number is in {0}/agreement.csv and {0}/fragility.csv, every run in {0}/results.csv; {0}/study.html "
        "is the ensemble's own study report.",
        p.folder.filename().string())));
    return b;
}

}  // namespace vssw::validation

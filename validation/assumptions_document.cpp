// The report's section "What the paper's assumptions cost", its JSON and its terminal lines
// (validation/assumptions_part.hpp).
#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/metric_catalog.hpp"
#include "io/json.hpp"
#include "validation/assumptions_part.hpp"

namespace vssw::validation {
namespace {

// A change the model gives and one the engines give can differ by twice the metric's target with every engine within
// the target of the model: a change is a ratio of two values, each held to the target (compare/targets.hpp).
constexpr double kChangeTargetsPerValueTarget = 2.0;

// A relative change as the report writes it ("-9.2 %"), a 0/1 metric's as the net share of runs that flip.
std::string change_text(double change, bool binary) {
    if (!std::isfinite(change)) return "-";
    if (binary && change == 0.0) return "no run flips";
    return binary ? fmt::format("{:+.1f} % of runs flip", 100.0 * change) : fmt::format("{:+.2f} %", 100.0 * change);
}

std::string engines_text(const RelaxationEffect& e) {
    if (e.engine_pairs == 0) return "-";
    if (e.absolute) return fmt::format("{:.2g} to {:.2g} b", e.engines_lo, e.engines_hi);
    if (e.engines_lo == e.engines_hi) return change_text(e.engines_lo, e.binary);
    if (e.binary) return fmt::format("{:+.1f} % to {:+.1f} % of runs flip", 100.0 * e.engines_lo, 100.0 * e.engines_hi);
    return fmt::format("{} to {}", change_text(e.engines_lo, false), change_text(e.engines_hi, false));
}

std::string relaxation_text(const RelaxationEffect& e) { return fmt::format("{} {} -> {}", e.parameter, e.from, e.to); }

// The largest change a relaxation gives: the model's or either end of the engines', whichever is farthest from 0.
double reach(const RelaxationEffect& e) {
    double out = 0.0;
    for (const double change : {e.model, e.engines_lo, e.engines_hi})
        if (std::isfinite(change)) out = std::max(out, std::abs(change));
    return out;
}

// How far the model's change may lie outside the engines' range and still agree with them: the metric's target
// (kChangeTargetsPerValueTarget of it) where it has one, none for a metric without (peak_rotation, a 0/1 metric).
double change_tolerance(const RelaxationEffect& e) {
    const compare::MetricInfo* m = compare::find_metric(e.metric);
    return !e.binary && m ? kChangeTargetsPerValueTarget * m->target : 0.0;
}

// Where the model follows a relaxation: is its change inside the engines' range, widened by change_tolerance?
bool model_within_engines(const RelaxationEffect& e) {
    const double tolerance = change_tolerance(e);
    return std::isfinite(e.model) && e.engine_pairs > 0 && e.model >= e.engines_lo - tolerance &&
           e.model <= e.engines_hi + tolerance;
}

// "<relaxation> moves <metric> most: ...", the model's and the engines' changes, either missing said as such.
std::string largest_change_line(const RelaxationEffect& e) {
    const std::string head = fmt::format("{} moves {} most: ", relaxation_text(e), e.metric);
    if (!std::isfinite(e.model)) return head + engines_text(e) + " by the engines; the model does not follow it.";
    if (e.engine_pairs == 0) return head + change_text(e.model, false) + " by the model; no engine measured it.";
    return head + fmt::format("{} by the model, {} by the engines.", change_text(e.model, false), engines_text(e));
}

// One line per relaxed parameter: its farthest level's largest change.
std::vector<std::string> conclusions(const AssumptionsPart& p) {
    std::vector<std::string> out;
    std::set<std::string> said;
    for (auto it = p.effects.rbegin(); it != p.effects.rend(); ++it) {
        if (said.count(it->parameter)) continue;
        const RelaxationEffect* largest = nullptr;
        for (const RelaxationEffect& e : p.effects)
            if (e.parameter == it->parameter && e.to == it->to && !e.binary && !e.absolute &&
                (!largest || reach(e) > reach(*largest)))
                largest = &e;
        if (!largest) continue;
        said.insert(it->parameter);
        out.push_back(largest_change_line(*largest));
    }
    std::reverse(out.begin(), out.end());
    // The slips each relaxation lets the engines make (the runs' own values, not changes), one line per level.
    std::vector<std::pair<std::string, std::vector<std::string>>> slips;
    for (const RelaxationEffect& e : p.effects) {
        if (!e.absolute) continue;
        if (slips.empty() || slips.back().first != relaxation_text(e)) slips.push_back({relaxation_text(e), {}});
        slips.back().second.push_back(fmt::format("{} up to {:.2g} b", e.metric, e.engines_hi));
    }
    for (const auto& [where, what] : slips)
        out.push_back(fmt::format("Sliding, measured by the engines ({}): {}.", where, fmt::join(what, ", ")));
    long followed = 0, within = 0;
    for (const RelaxationEffect& e : p.effects)
        if (std::isfinite(e.model) && e.engine_pairs > 0) {
            ++followed;
            within += model_within_engines(e) ? 1 : 0;
        }
    if (followed > 0)
        out.push_back(fmt::format("Where the model follows a relaxation, its change lies within the engines' range, "
                                  "give or take twice the metric's target, in {} of {} relaxation-metric pairs.",
                                  within, followed));
    return out;
}

}  // namespace

std::vector<io::DocBlock> assumptions_section(const AssumptionsPart& p) {
    std::vector<io::DocBlock> b;
    b.push_back(io::heading(2, "What the paper's assumptions cost"));
    b.push_back(io::paragraph(fmt::format(
        "{} ({}). Each of the paper's physical assumptions is relaxed alone, from the paper's level to a realistic "
        "one, and each run is paired with the same wall and backend under the paper's assumption: the change is the "
        "metric's over the paired value, minus 1. The model column is the analytic model's change where it follows "
        "the relaxation; the engines column spans the engines and walls, and where the model cannot follow, that span "
        "is the answer's uncertainty. {} rows, {} failed; {:.1f} s.",
        p.description, p.study_name, p.rows, p.failed_rows, p.wall_time_s)));
    for (std::size_t i = 0; i < p.tornadoes.size(); ++i) b.push_back(io::plot(p.tornado_titles[i], p.tornadoes[i]));
    const std::vector<std::string> lines = conclusions(p);
    if (!lines.empty()) {
        b.push_back(io::paragraph("What a user may conclude:"));
        b.push_back(io::list(lines));
    }
    io::DocBlock t = io::table({"relaxation", "metric", "the model", "the engines", "pairs (model, engines)"}, 2);
    for (const RelaxationEffect& e : p.effects)
        t.rows.push_back({{relaxation_text(e)}, {e.absolute ? e.metric + " (the runs' own, not a change)" : e.metric},
                          {change_text(e.model, e.binary)}, {engines_text(e)},
                          {fmt::format("{}, {}", e.model_pairs, e.engine_pairs)}});
    if (!t.rows.empty()) b.push_back(t);
    if (!p.model_warnings.empty()) {
        b.push_back(io::paragraph("Where the model warns (outside its validity: those runs are left out of its "
                                  "changes):"));
        b.push_back(io::list(p.model_warnings));
    }
    if (!p.refusals.empty()) {
        b.push_back(io::paragraph("Failed runs, by engine and reason (what an engine or the model cannot express, "
                                  "and what it failed to measure):"));
        b.push_back(io::list(p.refusals));
    }
    b.push_back(io::paragraph(fmt::format("Every run is in {0}/results.csv; {0}/study.html is the study's own report.",
                                          p.folder.filename().string())));
    return b;
}

io::Json assumptions_json(const AssumptionsPart& p) {
    io::Json effects = io::Json::array();
    for (const RelaxationEffect& e : p.effects)
        effects.push_back({{"parameter", e.parameter},
                           {"from", e.from},
                           {"to", e.to},
                           {"metric", e.metric},
                           {"binary", e.binary},
                           {"absolute", e.absolute},
                           {"model_change", io::finite_or_null(e.model)},
                           {"model_pairs", e.model_pairs},
                           {"engines_change_min", io::finite_or_null(e.engines_lo)},
                           {"engines_change_max", io::finite_or_null(e.engines_hi)},
                           {"engine_pairs", e.engine_pairs}});
    return {{"study", p.study_name},     {"file", p.study_file}, {"folder", p.folder.filename().string()},
            {"rows", p.rows},            {"failed_rows", p.failed_rows}, {"wall_time_s", p.wall_time_s},
            {"effects", effects},        {"refusals", p.refusals}, {"model_warnings", p.model_warnings},
            {"conclusions", conclusions(p)}};
}

std::vector<std::string> assumptions_summary_lines(const AssumptionsPart& p) {
    std::vector<std::string> out = {fmt::format("what the paper's assumptions cost ({}, {} rows, {} failed):",
                                                p.study_name, p.rows, p.failed_rows)};
    for (const std::string& line : conclusions(p)) out.push_back("  " + line);
    return out;
}

}  // namespace vssw::validation

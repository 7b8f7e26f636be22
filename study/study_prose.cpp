#include "study/study_prose.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/text.hpp"

namespace vssw::study {
namespace {

// A relative change this small is the last digits of doubles and of the integrator's tolerance (rtol 1e-10), not an
// effect: a sentence says "unchanged" and gives the bound.
constexpr double kNegligibleChange = 1e-9;
// From ten times the first level's value on (a change of +900 %), changes are given as factors.
constexpr double kFactorFrom = 9.0;

std::string pairs_text(long pairs, const std::string& parameter) {
    return pairs == 1 ? fmt::format("one pair of runs that differ in {} alone", parameter)
                      : fmt::format("{} pairs of runs that differ in {} alone", pairs, parameter);
}

// The gap of one engine series to one analytic series on one metric, in words.
std::string gap_text(const Agreement& g) {
    if (g.binary) return fmt::format("disagree on {} of {} case{}", g.disagree, g.cases, g.cases == 1 ? "" : "s");
    return fmt::format("median {}, largest {} over {} case{}", unsigned_percent(g.median), unsigned_percent(g.largest),
                       g.cases, g.cases == 1 ? "" : "s");
}

// "the analytic model with kinematics=exact"; "the analytic model" when no assumption varies.
std::string with_set(const StudyData& d, std::size_t series) {
    const std::string set = assumption_set(d, series);
    return set == "the analytic model" ? set : "the analytic model with " + set;
}

// The medians as the sentence prints them: sets whose printed medians are equal are equally close.
std::string median_text(const Agreement& g) {
    return g.binary ? std::to_string(g.disagree) + "/" + std::to_string(g.cases) : unsigned_percent(g.median);
}

std::string agreement_sentence(const StudyData& d, const std::vector<const Agreement*>& sets) {
    const Agreement& first = *sets.front();
    const std::string head = fmt::format("{}, {}", d.metrics[first.metric].name, d.series[first.engine].label);
    const std::string measure = first.binary ? "" : " (|engine/analytic - 1|)";
    if (sets.size() == 1)
        return fmt::format("{} against {}{}: {}.", head, with_set(d, first.analytic), measure, gap_text(first));
    std::vector<const Agreement*> sorted = sets;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Agreement* a, const Agreement* b) {
        return a->binary ? a->disagree * b->cases < b->disagree * a->cases : a->median < b->median;
    });
    std::vector<std::string> closest, gaps;
    for (const Agreement* g : sorted) {
        if (median_text(*g) == median_text(*sorted.front())) closest.push_back(assumption_set(d, g->analytic));
        gaps.push_back(fmt::format("with {}: {}", assumption_set(d, g->analytic), gap_text(*g)));
    }
    if (closest.size() == sorted.size())
        return fmt::format("{} is as close to the analytic model with each assumption set{}: {}.", head, measure,
                           fmt::join(gaps, "; "));
    return fmt::format("{} is closest to the analytic model with {}{}: {}.", head, fmt::join(closest, " or "), measure,
                       fmt::join(gaps, "; "));
}

}  // namespace

std::string unsigned_percent(double value) {
    std::string text = io::percent(std::abs(value));
    if (!text.empty() && text.front() == '+') text.erase(0, 1);
    return text;
}

bool shown_as_factor(const Effect& e) { return !e.binary && e.extent() >= kFactorFrom; }

std::string change_text(double relative_change, bool as_factor) {
    return as_factor ? fmt::format("x{:.3g}", 1.0 + relative_change) : io::percent(relative_change);
}

std::string effect_sentence(const StudyData& d, const Effect& e) {
    if (e.pairs == 0) return "";
    const std::string& metric = d.metrics[e.metric].name;
    const std::string change = fmt::format("{} from {} to {}", e.parameter, e.from, e.to);
    if (e.binary) {
        if (e.up == 0 && e.down == 0)
            return fmt::format("{} leaves {} unchanged on {}.", change, metric, pairs_text(e.pairs, e.parameter));
        return fmt::format("{} turns {} from 0 to 1 on {} and from 1 to 0 on {} of {} (net {} of the pairs).", change,
                           metric, e.up, e.down, pairs_text(e.pairs, e.parameter), io::percent(e.median));
    }
    if (e.extent() <= kNegligibleChange)
        return fmt::format("{} leaves {} unchanged (within {:g} relative on {}).", change, metric, kNegligibleChange,
                           pairs_text(e.pairs, e.parameter));
    if (shown_as_factor(e)) {
        if (e.pairs == 1)
            return fmt::format("{} multiplies {} by {:.3g} ({}).", change, metric, 1.0 + e.median,
                               pairs_text(e.pairs, e.parameter));
        return fmt::format("{} multiplies {} by a median of {:.3g} (from {:.3g} to {:.3g} over {}).", change, metric,
                           1.0 + e.median, 1.0 + e.lo, 1.0 + e.hi, pairs_text(e.pairs, e.parameter));
    }
    if (e.pairs == 1)
        return fmt::format("{} changes {} by {} ({}).", change, metric, io::percent(e.median),
                           pairs_text(e.pairs, e.parameter));
    return fmt::format("{} changes {} by a median of {} (from {} to {} over {}).", change, metric, io::percent(e.median),
                       io::percent(e.lo), io::percent(e.hi), pairs_text(e.pairs, e.parameter));
}

std::string assumption_set(const StudyData& d, std::size_t series) {
    const Series& s = d.series[series];
    std::string label = d.series_label(s);
    const std::string prefix = "analytic";
    label = label.size() > prefix.size() ? label.substr(prefix.size() + 1) : "";
    return label.empty() ? "the analytic model" : label;
}

std::vector<std::string> agreement_sentences(const StudyData& d, const std::vector<Agreement>& agreement) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < agreement.size();) {
        std::vector<const Agreement*> sets;
        std::size_t j = i;
        for (; j < agreement.size() && agreement[j].engine == agreement[i].engine &&
               agreement[j].metric == agreement[i].metric;
             ++j)
            if (agreement[j].cases > 0) sets.push_back(&agreement[j]);
        if (!sets.empty()) out.push_back(agreement_sentence(d, sets));
        i = j;
    }
    return out;
}

}  // namespace vssw::study

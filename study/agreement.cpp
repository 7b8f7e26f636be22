#include "study/agreement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "study/effects.hpp"

namespace vssw::study {
namespace {

using Values = std::map<std::pair<int, std::size_t>, double>;  // (case id, metric) -> value

Values values_of(const StudyData& d, const Series& s) {
    Values v;
    for (const StudyRow& r : d.rows)
        if (d.in_series(r, s)) v.emplace(std::make_pair(r.case_id, static_cast<std::size_t>(r.metric)), r.value);
    return v;
}

Agreement compare(const StudyData& d, std::size_t e, std::size_t a, std::size_t metric, const Values& engine,
                  const Values& analytic) {
    Agreement g{e, a, metric, d.metrics[metric].binary, 0, 0, std::nan(""), std::nan("")};
    std::vector<double> gaps;
    for (const auto& [key, value] : engine) {
        if (key.second != metric || !std::isfinite(value)) continue;
        const auto it = analytic.find(key);
        if (it == analytic.end() || !std::isfinite(it->second)) continue;
        if (g.binary) {
            ++g.cases;
            g.disagree += value != it->second ? 1 : 0;
        } else if (it->second != 0.0) {
            ++g.cases;
            gaps.push_back(std::abs(value / it->second - 1.0));
        }
    }
    if (g.binary && g.cases > 0) g.median = g.largest = static_cast<double>(g.disagree) / static_cast<double>(g.cases);
    if (!gaps.empty()) {
        g.median = median(gaps);
        g.largest = *std::max_element(gaps.begin(), gaps.end());
    }
    return g;
}

}  // namespace

std::vector<Agreement> engine_agreement(const StudyData& d) {
    std::vector<std::size_t> engines, analytic;
    for (std::size_t s = 0; s < d.series.size(); ++s) (d.series[s].analytic() ? analytic : engines).push_back(s);
    std::vector<Agreement> out;
    if (engines.empty() || analytic.empty()) return out;
    std::vector<Values> analytic_values;
    for (std::size_t a : analytic) analytic_values.push_back(values_of(d, d.series[a]));
    for (std::size_t e : engines) {
        const Values engine = values_of(d, d.series[e]);
        for (std::size_t m = 0; m < d.metrics.size(); ++m) {
            const bool measured = std::any_of(engine.begin(), engine.end(), [&](const auto& kv) {
                return kv.first.second == m && std::isfinite(kv.second);
            });
            if (!measured) continue;
            for (std::size_t i = 0; i < analytic.size(); ++i)
                out.push_back(compare(d, e, analytic[i], m, engine, analytic_values[i]));
        }
    }
    return out;
}

}  // namespace vssw::study

#include "study/overturned_runs.hpp"

#include <cmath>
#include <cstddef>

#include "study/effects.hpp"  // median

namespace vssw::study {

Overturning::Overturning(const StudyData& d) {
    std::size_t metric = d.metrics.size();
    bool from_time = false;
    for (std::size_t m = 0; m < d.metrics.size(); ++m)
        if (d.metrics[m].name == "overturned" && d.metrics[m].any_value) metric = m;
    if (metric == d.metrics.size())
        for (std::size_t m = 0; m < d.metrics.size(); ++m)
            if (d.metrics[m].name == "t_overturn") {
                metric = m;
                from_time = true;
            }
    if (metric == d.metrics.size()) return;
    measured_ = true;
    for (const StudyRow& r : d.rows)
        if (r.metric == metric) runs_[{r.case_id, r.levels}] = from_time ? std::isfinite(r.value) : r.value == 1.0;
}

bool Overturning::overturned(const StudyRow& r) const {
    const auto it = runs_.find({r.case_id, r.levels});
    return it != runs_.end() && it->second;
}

std::pair<double, bool> peak_point(const std::vector<double>& peaks) {
    const double m = median(peaks);
    return {std::isinf(m) ? kOverturnedDrawnAt : m, std::isinf(m)};
}

}  // namespace vssw::study

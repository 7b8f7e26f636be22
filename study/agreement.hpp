#pragma once
// Each engine against each of the analytic model's assumption sets, case by case (study/study_data.hpp): which set an
// engine is closest to is what a study that runs both finds (e.g. the engines' landing is the whole mechanism's
// plastic impact, not Eq. 19).
#include <cstddef>
#include <vector>

#include "study/study_data.hpp"

namespace vssw::study {

struct Agreement {
    std::size_t engine = 0, analytic = 0;  // series, in StudyData::series
    std::size_t metric = 0;
    bool binary = false;
    long cases = 0;      // cases with both values (continuous: the analytic one not 0)
    long disagree = 0;   // binary: cases whose values differ
    // |engine / analytic - 1| over the cases: median and largest (binary: the share that disagree, both). NaN for none.
    double median = 0.0, largest = 0.0;
};

// Every engine series x metric with engine values x analytic series, in series and metric order; empty when the study
// ran no engine or not the analytic model.
std::vector<Agreement> engine_agreement(const StudyData& data);

}  // namespace vssw::study

#pragma once
// How much each varied parameter moves each metric, from a study's results (study/study_data.hpp).
//
// Runs are paired that differ in one parameter alone: the same engine and settings, the same levels of every other
// varied parameter (a row to which one of those does not apply pairs at each of its levels), the same metric. A pair's
// change is the metric at a level over the metric at the parameter's first level, minus 1; a 0/1 metric (overturned)
// has no relative change: its pairs are counted as flipping 0 -> 1 (up), 1 -> 0 (down) or not. The assumptions of the
// analytic model are parameters like the others; engines, which ignore them, have no pairs in them.
#include <cstddef>
#include <string>
#include <vector>

#include "study/study_data.hpp"

namespace vssw::study {

struct Effect {
    std::size_t column = 0;  // the parameter, in StudyData::columns
    std::string parameter, from, to;  // its key, its first level and the level compared with it
    bool assumption = false;  // the analytic model's (kinematics, impact, roller)
    bool physical = false;    // one of the paper's physical assumptions relaxed (kPhysicalAssumptionKeys)
    std::size_t metric = 0;  // in StudyData::metrics
    bool binary = false;
    long pairs = 0;          // pairs with a finite change (binary: with both values)
    long up = 0, down = 0;   // binary: pairs going 0 -> 1 and 1 -> 0
    // The relative change over the pairs: median, smallest, largest. Binary: net share (up - down) / pairs, then
    // -down / pairs and up / pairs. NaN without pairs.
    double median = 0.0, lo = 0.0, hi = 0.0;

    // What "largest first" sorts by: |median| (binary: the share of pairs that flip); 0 without pairs.
    double magnitude() const;
    // The span's reach: max(|lo|, |hi|); 0 without pairs.
    double extent() const;
};

// Every varied parameter x each level after its first x every metric with a value: largest magnitude first, then
// largest extent, then in column and level order.
std::vector<Effect> parameter_effects(const StudyData& data);

// The median of the values (the mean of the middle two for an even count); NaN for none.
double median(std::vector<double> values);

}  // namespace vssw::study

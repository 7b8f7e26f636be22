#pragma once
// How a study's plots show an overturned run's peak rotation, one way in every plot: the run counts as the largest
// peak, and a point whose median is such a run is drawn at 1 (theta1 = alpha) with a ring, the legend's "overturned".
// (The peak_rotation value of an overturned run is its collapse angle over alpha, 10 or more for a slender wall: a
// height no rocking run reaches, which would squash every other point.)
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "study/study_data.hpp"

namespace vssw::study {

// Whether each run overturned, by (case id, the run's columns): the metric overturned, else t_overturn (a time only
// when it did). Not measured when the study has neither.
class Overturning {
public:
    explicit Overturning(const StudyData& d);
    bool measured() const { return measured_; }
    bool overturned(const StudyRow& r) const;

private:
    bool measured_ = false;
    std::map<std::pair<int, std::vector<std::uint32_t>>, bool> runs_;
};

// The height an overturned run's peak is drawn at in every plot of the peak rotation (theta1 = alpha1, the rest
// threshold's angle), ringed: its value, the collapse angle over alpha1, would squash every rocking peak.
inline constexpr double kOverturnedDrawnAt = 1.0;
// The peak an overturned run counts as in a point's median: larger than any.
inline constexpr double kOverturnedPeak = std::numeric_limits<double>::infinity();
// The ring around a point drawn as overturned (gnuplot), in every plot.
inline constexpr const char* kOverturnedRing = "pt 6 ps 2 lc rgb 'black'";
// The point's value and whether it is drawn as overturned: the median of the peaks (kOverturnedPeak for an
// overturned run), at kOverturnedDrawnAt when that median is an overturned run; NaN for none.
std::pair<double, bool> peak_point(const std::vector<double>& peaks);

}  // namespace vssw::study

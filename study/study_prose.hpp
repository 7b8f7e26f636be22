#pragma once
// A study's findings in plain words, each sentence built from the numbers (study/effects.hpp, study/agreement.hpp)
// and saying nothing they do not show.
#include <string>
#include <vector>

#include "study/agreement.hpp"
#include "study/effects.hpp"
#include "study/study_data.hpp"

namespace vssw::study {

// "hinge from 0.5 to 0.7 changes period by a median of +20.0 % (from +19.0 % to +21.0 % over 8 pairs of runs that
// differ in hinge alone)."; a 0/1 metric in runs that flip. Empty for an effect without pairs.
std::string effect_sentence(const StudyData& d, const Effect& e);

// A relative change as a percentage ("+20.0 %"), or as a factor on the first level's value ("x7.8e+07") when the
// effect reaches ten times that value: percentages in the millions read as noise. The same form for an effect's
// median, smallest and largest change.
bool shown_as_factor(const Effect& e);
std::string change_text(double relative_change, bool as_factor);

// An analytic series by its assumptions, for sentences and tables: "kinematics=exact impact=eq19" ("the analytic
// model" when no assumption varies), its settings after them.
std::string assumption_set(const StudyData& d, std::size_t series);

// One sentence per engine series and metric: how far it is from the analytic model and, when several assumption sets
// ran, which one it is closest to (the smallest median gap) and how far the others are. In series, then metric order.
std::vector<std::string> agreement_sentences(const StudyData& d, const std::vector<Agreement>& agreement);

// A gap or a share as a percentage without a sign: "0.41 %", "13.2 %".
std::string unsigned_percent(double value);

}  // namespace vssw::study

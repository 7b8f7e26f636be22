#pragma once
// The plots of a study (DIR/plots/, drawn by io/gnuplot.hpp), from its results alone (study/study_data.hpp); only
// what the study varies is plotted, and the number of plots is bounded however large the study:
//   value_<metric>_vs_<parameter>  the metric against each varied parameter, one line per series (an engine with its
//                                  settings; the analytic model per assumption set); a panel per combination of the
//                                  other varied wall and excitation parameters (kMaxPanels at most: beyond, the median
//                                  over the last ones); a number on a numeric axis, a word as categories
//   tornado_<metric>               each varied assumption's effect on the metric (study/effects.hpp), largest first:
//                                  the bar spans the smallest to the largest change, the mark is the median
//   tornado_physical_<metric>      the same for each of the paper's physical assumptions relaxed (N off the centre,
//                                  ...), over the model and the engines alike: the bar spans walls and backends
//   rocking_<record>...            record studies: peak rotation against alpha, a panel per R, an open circle at 1
//                                  where the run overturned (the paper's Fig. 10/11), a plot per record and level
//   overturning_map...             pulse studies: amplitude against pulse period, each run coloured by its peak
//                                  rotation (capped at 1), overturned runs marked, a panel per series
#include <string>
#include <vector>

#include "study/effects.hpp"
#include "io/gnuplot.hpp"
#include "study/study_data.hpp"

namespace vssw::study {

// At most this many value plots (metric x varied parameter) in a study, metrics in the study's order: 40 plots of 12
// panels is already more than a reader goes through; the prose names what was left out.
constexpr std::size_t kMaxValuePlots = 40;

struct StudyPlots {
    std::vector<io::PlotScript> scripts;
    std::vector<std::string> notes;  // what was not drawn and why, one sentence each, for study.md
};

// The document sections the plots appear under.
extern const char* const kValueSection;
extern const char* const kTornadoSection;
extern const char* const kPhysicalTornadoSection;
extern const char* const kRockingSection;
extern const char* const kMapSection;

void add_value_plots(const StudyData& d, StudyPlots& out);
void add_tornado_plots(const StudyData& d, const std::vector<Effect>& effects, StudyPlots& out);
void add_rocking_curves(const StudyData& d, StudyPlots& out);
void add_overturning_maps(const StudyData& d, StudyPlots& out);

// All of the above.
StudyPlots study_plot_scripts(const StudyData& d, const std::vector<Effect>& effects);

}  // namespace vssw::study

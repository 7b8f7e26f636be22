#pragma once
// The earthquake part's own plots (validation/earthquake.hpp), drawn into its folder's plots/ beside the study's:
//   engine_peaks.svg         each engine's peak against the reference's, run by run, log-log, one panel per engine on
//                            the same axes, the identity line, the reference's band (its perturbed repeats' [min, max])
//                            as a vertical bar at its peak, and the runs where either overturned at the panel's edge
//   fragility_by_engine.svg  each engine's stripes and lognormal fit in a panel of its own with the reference's in
//                            each, so that no engine hides under another; a fit that is not resolved drawn as its
//                            stripe points only, with a note
#include <vector>

#include "io/gnuplot.hpp"
#include "study/ensemble_measures.hpp"

namespace vssw::validation {

// The scripts of both plots for every series that is not the reference (none without a reference).
std::vector<io::PlotScript> earthquake_plot_scripts(const study::StudyData& d, const study::EnsembleMeasures& e);

}  // namespace vssw::validation

#pragma once
// The ensemble measures (study/ensemble_measures.hpp) as a study writes them beside results.csv:
//   fragility.csv  one row per series and wall with an IDA fit: engine, assumptions, intensity, median, beta,
//                  median_lo, median_hi, beta_lo, beta_hi, records, collapsed, then median_ratio, ratio_lo,
//                  ratio_hi (to the reference's median, paired bootstrap), settings, wall, reference, seed, replicates,
//                  failed_replicates, intensity_unit (the median's: g, or m/s for pgv and arias)
//   agreement.csv  one row per series, wall and measure: engine, assumptions, measure, value, lo, hi, n, then
//                  settings, wall, reference
//   plots/fragility.svg  the fitted curves with the bootstrap band of their medians and the records' collapse PGAs
//                  (a panel per wall); plots/stripes.svg the share overturned per PGA level with Wilson bars
//   an "Ensemble" section in study.md and study.html
#include <ostream>
#include <string>
#include <vector>

#include "io/document.hpp"
#include "study/ensemble_measures.hpp"
#include "study/study_data.hpp"
#include "study/study_plots.hpp"

namespace vssw::study {

constexpr const char* kFragilityCsv = "fragility.csv";
constexpr const char* kAgreementCsv = "agreement.csv";
extern const char* const kEnsembleSection;

// Why a fit is "not resolved" (the fit's reason, or every bootstrap resample giving the same median), "" when it is.
std::string fit_note(const compare::FitBootstrap& f);
void write_fragility_csv(std::ostream& out, const StudyData& d, const EnsembleMeasures& e);
void write_agreement_csv(std::ostream& out, const StudyData& d, const EnsembleMeasures& e);
// The fragility and stripe plots (nothing when the measures do not apply or hold no fit / stripe).
void add_ensemble_plots(const StudyData& d, const EnsembleMeasures& e, StudyPlots& out);
// The document's "Ensemble" section (nothing when the measures do not apply).
void add_ensemble_section(std::vector<io::DocBlock>& blocks, const StudyData& d, const EnsembleMeasures& e);

}  // namespace vssw::study

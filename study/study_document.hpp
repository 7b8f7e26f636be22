#pragma once
// The content of study.md and study.html (io/document.hpp): what the study is, what varied and what ran, the
// counts, the largest sensitivities first, the engines against each analytic assumption set, the plots, the run.
#include "study/agreement.hpp"
#include "io/document.hpp"
#include "study/effects.hpp"
#include "study/ensemble_measures.hpp"
#include "io/gnuplot.hpp"
#include "study/study_data.hpp"
#include "study/study_plots.hpp"

namespace vssw::study {

// At most this many sentences of sensitivities (the table below them holds every effect): past twenty the reader is
// in the table anyway.
constexpr std::size_t kMaxSensitivitySentences = 20;
// Failure reasons listed by name, the most common first.
constexpr std::size_t kMaxFailureReasons = 3;
// The page opens with at most this many main figures (and a tornado chart) and this many of the largest effects: a
// first screen or two; everything else follows under its own heading.
constexpr std::size_t kGlanceFigures = 2;
constexpr std::size_t kGlanceEffects = 5;

struct StudyDocumentInput {
    const StudyData& data;
    const std::vector<Effect>& effects;
    const std::vector<Agreement>& agreement;
    const StudyPlots& plot_notes;  // its notes (its scripts are drawn into `plots`)
    const io::PlotResult& plots;
    bool plots_skipped = false;    // --no-plots
    const EnsembleMeasures* ensemble = nullptr;  // the "Ensemble" section's measures (none: no section)
};

io::Document build_study_document(const StudyDocumentInput& in);

// The heading of the paragraph that says when and where the study ran: the only part of the document that differs
// between one run of a study and a merge of its shards.
extern const char* const kRunHeading;

}  // namespace vssw::study

#pragma once
// What a study folder holds besides results.csv and manifest.json, written from those two alone, as read back or as
// just written (study/study_data.hpp; so that one run, a resumed run and a merge of shards are written by the same
// code):
//   results.json           the manifest's keys and every row (results_files.hpp)
//   plots/                 gnuplot SVGs with their .gp scripts and .dat data (study/study_plots.hpp); without gnuplot
//                          the scripts and data only, and a warning
//   fragility.csv, agreement.csv  record studies over >= 2 records: each series against the reference (IDA fits,
//                          overturning agreement, peak ratios; study/ensemble_outputs.hpp)
//   study.md, study.html   the study in plain words, the largest sensitivities first, the engines against each of the
//                          analytic model's assumption sets, the plots inline (study/study_document.hpp)
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vssw::study {

// The file names in DIR (besides those of study/runner.hpp).
constexpr const char* kPlotsDir = "plots";
constexpr const char* kStudyMarkdown = "study.md";
constexpr const char* kStudyHtml = "study.html";

struct OutputOptions {
    bool plots = true;                // false: --no-plots
    std::string gnuplot = "gnuplot";  // the program (looked up in PATH unless it holds a '/')
};

struct StudyData;         // study/study_data.hpp
struct EnsembleMeasures;  // study/ensemble_measures.hpp

struct OutputFiles {
    std::vector<std::filesystem::path> written;  // results.json, plots/ (when it has plots), study.md, study.html
    std::vector<std::string> warnings;  // for stderr, one line each (e.g. gnuplot missing)
};

// DIR/manifest.json as JSON (InputError naming it when it is missing or malformed).
nlohmann::ordered_json read_manifest(const std::filesystem::path& dir);

// InputError naming the file when DIR's results cannot be read or a file cannot be written.
OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options);
// The same from DIR's results already in memory (StudyRunResult::data: the run that has just written them).
OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options, const StudyData& data);
// The same from DIR's results already read and measured (read_study_data, ensemble_measures): a caller that needs
// them too (the report's earthquake part) computes the measures, bootstraps included, once.
OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options, const StudyData& data,
                                const EnsembleMeasures& ensemble);

}  // namespace vssw::study

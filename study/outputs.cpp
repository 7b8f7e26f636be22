#include "study/outputs.hpp"

#include <fstream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "study/agreement.hpp"
#include "io/atomic_file.hpp"
#include "io/document_html.hpp"
#include "io/document_markdown.hpp"
#include "study/effects.hpp"
#include "study/ensemble_measures.hpp"
#include "study/ensemble_outputs.hpp"
#include "study/ida_curves.hpp"
#include "study/results_files.hpp"
#include "study/runner.hpp"
#include "study/study_data.hpp"
#include "study/study_document.hpp"
#include "study/study_plots.hpp"

namespace vssw::study {

nlohmann::ordered_json read_manifest(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / kManifestFile;
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
        throw InputError(fmt::format("cannot read '{}' (not a study folder?)", path.string()));
    std::ifstream in = open_input_file(path, "the study's manifest", kMaxTextFileBytes);
    try {
        return nlohmann::ordered_json::parse(in);
    } catch (const std::exception& e) {
        throw InputError(fmt::format("'{}' is not a study manifest: {}", path.string(), e.what()));
    }
}

OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options) {
    return write_study_outputs(dir, options, read_study_data(dir));
}

OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options, const StudyData& data) {
    return write_study_outputs(dir, options, data, ensemble_measures(data));
}

OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options, const StudyData& data,
                                const EnsembleMeasures& ensemble) {
    OutputFiles files;
    io::write_file(dir / kResultsJson,
               [&](std::ostream& out) { write_results_json(out, data); });
    files.written.push_back(dir / kResultsJson);

    const std::vector<Effect> effects = parameter_effects(data);
    const std::vector<Agreement> agreement = engine_agreement(data);
    if (ensemble.applies) {
        io::write_file(dir / kFragilityCsv, [&](std::ostream& out) { write_fragility_csv(out, data, ensemble); });
        io::write_file(dir / kAgreementCsv, [&](std::ostream& out) { write_agreement_csv(out, data, ensemble); });
        files.written.push_back(dir / kFragilityCsv);
        files.written.push_back(dir / kAgreementCsv);
    }
    StudyPlots scripts;
    io::PlotResult plots;
    const std::filesystem::path plots_dir = dir / kPlotsDir;
    if (options.plots) {
        scripts = study_plot_scripts(data, effects);
        add_ensemble_plots(data, ensemble, scripts);
        if (std::filesystem::exists(dir / kIdaCsv)) add_ida_plot(data, ensemble, read_ida_csv(dir / kIdaCsv), scripts);
        plots = io::draw_plots(scripts.scripts, plots_dir, options.gnuplot);
        if (!plots.note.empty()) files.warnings.push_back("plots: " + plots.note);
        if (!scripts.scripts.empty()) files.written.push_back(plots_dir);
    }
    const io::Document doc = build_study_document({data, effects, agreement, scripts, plots, !options.plots, &ensemble});
    io::write_file(dir / kStudyMarkdown, [&](std::ostream& out) { io::write_markdown(out, doc); });
    io::write_file(dir / kStudyHtml, [&](std::ostream& out) { io::write_html(out, doc, plots_dir); });
    files.written.push_back(dir / kStudyMarkdown);
    files.written.push_back(dir / kStudyHtml);
    return files;
}

}  // namespace vssw::study

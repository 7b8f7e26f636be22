#include "validation/earthquake.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "study/ensemble_measures.hpp"
#include "study/grid.hpp"
#include "study/outputs.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "study/study_data.hpp"

namespace vssw::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kShippedStudy = "ensemble-report.toml";

// The study file with its engines replaced by the analytic model (the reference) and the report's.
StudySpec with_engines(const std::string& file, const std::vector<std::string>& engines) {
    const StudySpec read = read_study_file(file);
    Json doc = read.as_read;
    Json names = Json::array({"analytic"});
    for (const std::string& e : engines)
        if (e != "analytic") names.push_back(e);
    doc["engines"] = names;
    StudySpec spec = study_from_json(nlohmann::json::parse(doc.dump()), file, read.base_dir);
    spec.path = read.path;
    return spec;
}

void require_stripe_ensemble(const StudySpec& spec, const std::string& file) {
    for (const PartSpec& p : spec.parts)
        if (p.kind != ExcitationKind::record || !p.excitation_axis("file") || !p.excitation_axis("pga"))
            throw InputError(fmt::format("earthquake study {}: every part must be an ensemble of stripes (kind = "
                                         "\"ensemble\" with levels): its records' overturning is what the report "
                                         "judges",
                                         file));
}

EarthquakeVerdict verdict_of(const StudyData& d, const SeriesMeasures& m) {
    EarthquakeVerdict v;
    v.engine = d.series[m.series].engine;
    v.agreement = m.stripes ? m.overturning : compare::Interval{kNaN, kNaN, kNaN, 0};
    v.median_ratio = m.fitted() ? m.ratio.ratio : compare::Interval{kNaN, kNaN, kNaN, 0};
    if (!m.fitted()) v.fit_note = "no stripes to fit";
    else if (!m.fit.fit.ok()) v.fit_note = m.fit.fit.reason;
    else if (!std::isfinite(v.median_ratio.value)) v.fit_note = "the reference's fragility was not fitted";
    v.peak_ratio = m.peak_ratio;
    if (m.band) {
        v.inside = m.inside.inside;
        v.band_runs = m.inside.runs;
        v.outside = m.outside_band;
    }
    v.agreement_pass = v.agreement.value >= kOverturningAgreementTarget;
    v.fragility_pass = std::abs(v.median_ratio.value - 1.0) <= kFragilityMedianTarget;
    return v;
}

Json interval_json(const compare::Interval& i) {
    return Json{{"value", finite_or_null(i.value)}, {"lo", finite_or_null(i.lo)}, {"hi", finite_or_null(i.hi)},
                {"n", i.n}};
}

}  // namespace

std::string earthquake_study_file(const std::string& name_or_path) {
    if (name_or_path == "none") return "";
    const std::string file =
        name_or_path == "default" ? shipped_studies_dir() + "/" + kShippedStudy : name_or_path;
    require_stripe_ensemble(read_study_file(file), file);
    return file;
}

EarthquakePart run_earthquake_part(const std::string& study_file, const std::vector<std::string>& engines,
                                   const std::filesystem::path& dir, const EarthquakeRunOptions& options) {
    const StudySpec spec = with_engines(study_file, engines);
    require_stripe_ensemble(spec, study_file);
    const Grid grid(spec);
    StudyRunOptions run;
    run.threads = options.threads;
    run.progress = options.progress;
    run.commit = options.commit;
    const FolderLock lock = prepare_study_dir(grid, dir, run);
    const StudyRunResult result = run_study(grid, dir, run);
    OutputOptions output;
    output.plots = options.plots;
    output.gnuplot = options.gnuplot;
    write_study_outputs(dir, output);

    EarthquakePart part;
    part.study_file = study_file;
    part.study_name = spec.name;
    part.description = spec.description;
    part.folder = dir;
    part.rows = result.rows;
    part.failed_rows = result.failed_rows;
    part.wall_time_s = result.meta.wall_time_s;
    const StudyData d = read_study_data(dir);
    const EnsembleMeasures e = ensemble_measures(d);
    if (e.has_reference) {
        const Series& ref = d.series[e.reference];
        part.reference = fmt::format("the analytic model ({})", assumptions_text(ref));
    }
    // The ensemble as the file gives it (results.csv's pga column also holds the band's perturbed levels).
    for (const PartSpec& p : spec.parts) {
        part.records += p.excitation_axis("file")->levels.size();
        part.levels = std::max(part.levels, p.excitation_axis("pga")->levels.size());
    }
    for (const SeriesMeasures& m : e.measures)
        if (e.has_reference && m.series == e.reference) part.reference_median = m.fit.median;
    for (const std::string& engine : engines)
        for (const SeriesMeasures& m : e.measures)
            if (d.series[m.series].engine == engine) part.engines.push_back(verdict_of(d, m));
    return part;
}

Json earthquake_json(const EarthquakePart& part) {
    Json engines = Json::array();
    for (const EarthquakeVerdict& v : part.engines) {
        Json agreement = interval_json(v.agreement), ratio = interval_json(v.median_ratio);
        agreement["pass"] = v.agreement_pass;
        ratio["pass"] = v.fragility_pass;
        ratio["note"] = v.fit_note;
        engines.push_back({{"engine", v.engine},
                           {"overturning_agreement", agreement},
                           {"fragility_median_ratio", ratio},
                           {"peak_ratio", {{"median", finite_or_null(v.peak_ratio.median)},
                                           {"q1", finite_or_null(v.peak_ratio.q1)},
                                           {"q3", finite_or_null(v.peak_ratio.q3)},
                                           {"n", v.peak_ratio.n}}},
                           {"inside_band", {{"inside", v.inside}, {"runs", v.band_runs}, {"outside", v.outside}}}});
    }
    return Json{{"study", part.study_name},
                {"folder", part.folder.filename().string()},
                {"reference", part.reference},
                {"reference_median_g", interval_json(part.reference_median)},
                {"targets", {{"overturning_agreement_min", kOverturningAgreementTarget},
                             {"fragility_median_within", kFragilityMedianTarget}}},
                {"records", part.records},
                {"levels", part.levels},
                {"rows", part.rows},
                {"failed_rows", part.failed_rows},
                {"engines", engines}};
}

}  // namespace vssw::study

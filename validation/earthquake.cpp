#include "validation/earthquake.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "io/json.hpp"
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

// The study file with its engines replaced by the analytic model (the reference) and the report's; the settings it
// gives engines that are not run are dropped (the report chooses the engines, at the file's settings for those it
// names).
StudySpec with_engines(const std::string& file, const std::vector<std::string>& engines) {
    const StudySpec read = read_study_file(file);
    Json doc = read.as_read;
    Json names = Json::array({"analytic"});
    for (const std::string& e : engines)
        if (e != "analytic") names.push_back(e);
    doc["engines"] = names;
    const auto prune = [&names](Json& table) {
        if (!table.contains("settings") || !table["settings"].is_object()) return;
        for (auto it = table["settings"].begin(); it != table["settings"].end();)
            it = std::find(names.begin(), names.end(), it.key()) == names.end() ? table["settings"].erase(it)
                                                                                 : std::next(it);
    };
    prune(doc);
    if (doc.contains("part") && doc["part"].is_array())
        for (Json& part : doc["part"]) prune(part);
    StudySpec spec = study_from_json(nlohmann::json::parse(dump_json(doc)), file, read.base_dir);
    spec.path = read.path;
    return spec;
}

// What the report can judge: one wall, stripes of at least two records that measure overturning and peaks, one run
// per engine (a verdict per engine), and the reference among the analytic model's assumption sets.
void require_stripe_ensemble(const StudySpec& spec, const std::string& file) {
    const auto refuse = [&file](const std::string& why) {
        throw InputError(fmt::format("earthquake study {}: {}", file, why));
    };
    if (spec.parts.size() != 1) refuse("one part (one wall's ensemble) is what the report judges");
    const PartSpec& p = spec.parts.front();
    if (p.ensemble && !p.ensemble->collapse && p.ensemble->intensity != "pga")
        refuse(fmt::format("its levels must be PGAs (intensity = \"pga\", not \"{}\"): the report's verdicts and "
                           "prose read PGA levels",
                           p.ensemble->intensity));
    if (!p.ensemble || p.ensemble->collapse || !p.excitation_axis("pga"))
        refuse("it must be an ensemble of stripes (kind = \"ensemble\" with levels): its records' overturning is "
               "what the report judges");
    for (const std::string& m : {std::string("overturned"), std::string("peak_rotation")})
        if (std::find(spec.metrics.begin(), spec.metrics.end(), m) == spec.metrics.end())
            refuse("its metrics must include overturned and peak_rotation (what the verdicts are made of)");
    if (p.excitation_axis("file")->levels.size() < 2) refuse("an ensemble needs at least two records");
    for (const Axis& a : p.wall)
        if (a.varied()) refuse(fmt::format("one wall: '{}' varies", a.key));
    for (const EngineSpec& e : p.engines)
        for (const Axis& a : e.settings)
            if (a.varied()) refuse(fmt::format("one run per engine: {}'s '{}' varies", e.name, a.key));
}

void require_judgeable(const StudySpec& spec, const std::string& file) {
    require_stripe_ensemble(spec, file);
    const Grid grid(spec);  // the checks a study's grid makes (records read, steps resolve), before anything runs
    bool reference = false;
    for (const RunSpec& r : grid.runs())
        reference = reference || (r.engine == "analytic" && r.kinematics == Kinematics::exact &&
                                  r.impact.kind == ImpactLaw::Kind::whole_mechanism && r.roller == Roller::unilateral);
    if (!reference)
        throw InputError(fmt::format("earthquake study {}: the analytic model must run with kinematics = \"exact\", "
                                     "impact = \"whole-mechanism\", roller = \"unilateral\" (the reference: what "
                                     "the engines realise)",
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
    v.failed_runs = m.failed_runs;
    v.agreement_pass = v.agreement.value >= kOverturningAgreementTarget;
    v.fragility_pass = std::abs(v.median_ratio.value - 1.0) <= kFragilityMedianTarget;
    return v;
}

Json interval_json(const compare::Interval& i) {
    return Json{{"value", finite_or_null(i.value)}, {"lo", finite_or_null(i.lo)}, {"hi", finite_or_null(i.hi)},
                {"n", i.n}};
}

}  // namespace

std::string earthquake_study_file(const std::string& name_or_path, const std::vector<std::string>& engines) {
    if (name_or_path == "none") return "";
    const std::string file =
        name_or_path == "default" ? shipped_studies_dir() + "/" + kShippedStudy : name_or_path;
    require_judgeable(with_engines(file, engines), file);
    return file;
}

EarthquakePart run_earthquake_part(const std::string& study_file, const std::vector<std::string>& engines,
                                   const std::filesystem::path& dir, const EarthquakeRunOptions& options) {
    const StudySpec spec = with_engines(study_file, engines);
    require_judgeable(spec, study_file);
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
    part.preferred_reference = e.preferred_reference;
    part.band = d.column("perturbation") != std::string::npos;
    for (const std::string& engine : engines) {
        const auto m = std::find_if(e.measures.begin(), e.measures.end(),
                                    [&](const SeriesMeasures& x) { return d.series[x.series].engine == engine; });
        if (m != e.measures.end()) {
            part.engines.push_back(verdict_of(d, *m));
            continue;
        }
        EarthquakeVerdict none;  // no row at all: every run failed before measuring
        none.engine = engine;
        none.agreement = none.median_ratio = {kNaN, kNaN, kNaN, 0};
        none.fit_note = "no result on any run";
        part.engines.push_back(none);
    }
    return part;
}

Json earthquake_json(const EarthquakePart& part) {
    Json engines = Json::array();
    for (const EarthquakeVerdict& v : part.engines) {
        Json agreement = interval_json(v.agreement), ratio = interval_json(v.median_ratio);
        agreement["pass"] = v.agreement_pass;
        ratio["pass"] = v.fragility_pass;
        ratio["note"] = v.fit_note;
        agreement["failed_runs"] = v.failed_runs;
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

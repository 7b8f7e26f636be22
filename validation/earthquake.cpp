#include "validation/earthquake.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "io/json.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "study/ensemble_measures.hpp"
#include "study/ensemble_outputs.hpp"
#include "study/grid.hpp"
#include "study/outputs.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "study/study_data.hpp"
#include "validation/earthquake_plots.hpp"
#include "validation/study_engines.hpp"

namespace vssw::validation {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kShippedStudy = "ensemble-report.toml";
constexpr const char* kShippedFullStudy = "ensemble-report-full.toml";

// What the report can judge: one wall, stripes of at least two records that measure overturning and peaks, one run
// per engine (a verdict per engine), and the reference among the analytic model's assumption sets.
void require_stripe_ensemble(const study::StudySpec& spec, const std::string& file) {
    const auto refuse = [&file](const std::string& why) {
        throw InputError(fmt::format("earthquake study {}: {}", file, why));
    };
    if (spec.parts.size() != 1) refuse("one part (one wall's ensemble) is what the report judges");
    const study::PartSpec& p = spec.parts.front();
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
    for (const study::Axis& a : p.wall)
        if (a.varied()) refuse(fmt::format("one wall: '{}' varies", a.key));
    for (const study::EngineSpec& e : p.engines)
        for (const study::Axis& a : e.settings)
            if (a.varied()) refuse(fmt::format("one run per engine: {}'s '{}' varies", e.name, a.key));
}

void require_judgeable(const study::StudySpec& spec, const std::string& file) {
    require_stripe_ensemble(spec, file);
    const study::Grid grid(spec);  // the checks a study's grid makes (records read, steps resolve), before anything runs
    bool reference = false;
    for (const study::RunSpec& r : grid.runs())
        reference = reference || (r.engine == "analytic" && r.kinematics == Kinematics::exact &&
                                  r.impact.kind == ImpactLaw::Kind::whole_mechanism && r.roller == Roller::unilateral);
    if (!reference)
        throw InputError(fmt::format("earthquake study {}: the analytic model must run with kinematics = \"exact\", "
                                     "impact = \"whole-mechanism\", roller = \"unilateral\" (the reference: what "
                                     "the engines realise)",
                                     file));
}

EarthquakeVerdict verdict_of(const study::StudyData& d, const study::SeriesMeasures& m) {
    EarthquakeVerdict v = judge_series(d.series[m.series].engine, m);
    v.settings = d.series[m.series].settings;  // as results.csv has them: what the engine ran at
    return v;
}

// The report's ensemble for the analytic model and `engine` at `settings` (an object of lists: a series per
// combination), without the band.
study::StudySpec settings_spec(const std::string& file, const std::string& engine, const io::Json& settings) {
    const study::StudySpec read = study::read_study_file(file);
    io::Json doc = read.as_read;
    doc["engines"] = engine == "analytic" ? io::Json::array({"analytic"}) : io::Json::array({"analytic", engine});
    doc["settings"] = io::Json{{engine, settings}};
    if (doc.contains("excitation") && doc["excitation"].is_object()) doc["excitation"].erase("band");
    study::StudySpec spec = study::study_from_json(nlohmann::json::parse(io::dump_json(doc)), file, read.base_dir);
    spec.path = read.path;
    return spec;
}

// The ensemble for the analytic model alone, its three assumptions each at the two sets' values: the reference
// (the set mechanism, which ensemble_measures() prefers) and the set paper among the series, so that the paper's model
// is paired run by run with the reference as an engine is. The other combinations are analytic runs too (milliseconds
// each) and are not judged; the paper's kinematics with the unilateral roller is no model and is skipped.
study::StudySpec assumption_sets_spec(const std::string& file) {
    const study::StudySpec read = study::read_study_file(file);
    io::Json doc = read.as_read;
    doc["engines"] = io::Json::array({"analytic"});
    doc.erase("settings");
    if (doc.contains("part") && doc["part"].is_array())
        for (io::Json& part : doc["part"]) part.erase("settings");
    if (doc.contains("excitation") && doc["excitation"].is_object()) doc["excitation"].erase("band");
    doc["assumptions"] = io::Json{{"kinematics", io::Json::array({"exact", "paper"})},
                              {"impact", io::Json::array({"whole-mechanism", "eq19"})},
                              {"roller", io::Json::array({"unilateral", "bilateral"})}};
    study::StudySpec spec = study::study_from_json(nlohmann::json::parse(io::dump_json(doc)), file, read.base_dir);
    spec.path = read.path;
    return spec;
}

// A series' settings text ("dt=0.001 cfm=1e-05") as an object of numbers.
io::Json settings_of(const std::string& text) {
    io::Json out = io::Json::object();
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find(' ', at);
        if (end == std::string::npos) end = text.size();
        const std::string token = text.substr(at, end - at);
        const std::size_t eq = token.find('=');
        if (eq != std::string::npos) out[token.substr(0, eq)] = std::strtod(token.c_str() + eq + 1, nullptr);
        at = end + 1;
    }
    return out;
}

// The smallest |error| from which on every stand-in fails; NaN when the largest does not.
double detection_limit(const std::vector<std::pair<double, EarthquakeVerdict>>& stand_ins) {
    std::vector<double> magnitudes;
    for (const auto& [error, v] : stand_ins) magnitudes.push_back(std::abs(error));
    std::sort(magnitudes.begin(), magnitudes.end());
    double limit = kNaN;
    for (auto m = magnitudes.rbegin(); m != magnitudes.rend(); ++m) {
        const bool all_fail = std::all_of(stand_ins.begin(), stand_ins.end(), [&](const auto& s) {
            return std::abs(s.first) < *m || !s.second.pass;
        });
        if (!all_fail) break;
        limit = *m;
    }
    return limit;
}

io::Json interval_json(const compare::Interval& i) {
    return io::Json{{"value", io::finite_or_null(i.value)}, {"lo", io::finite_or_null(i.lo)}, {"hi", io::finite_or_null(i.hi)},
                {"n", i.n}};
}

}  // namespace

EarthquakeVerdict judge_series(const std::string& engine, const study::SeriesMeasures& m) {
    EarthquakeVerdict v;
    v.engine = engine;
    v.agreement = m.stripes ? m.overturning : compare::Interval{kNaN, kNaN, kNaN, 0};
    v.median_ratio = m.fitted() ? m.ratio.ratio : compare::Interval{kNaN, kNaN, kNaN, 0};
    if (!m.fitted()) v.fit_note = "no stripes to fit";
    else if (!m.fit.fit.ok()) v.fit_note = m.fit.fit.reason;
    else if (!std::isfinite(v.median_ratio.value)) v.fit_note = "the reference's fragility was not fitted";
    else if (!m.ratio.reason.empty()) v.fit_note = m.ratio.reason;
    else if (v.median_ratio.lo == v.median_ratio.hi)
        v.fit_note = "not resolved: every resample gives the same ratio (the records cannot move it)";
    v.ratio_failed = m.ratio.failed;
    if (!v.fit_note.empty()) v.median_ratio = {kNaN, kNaN, kNaN, v.median_ratio.n};  // never a number
    v.peak_ratio = m.peak_ratio;
    if (m.band) {
        v.inside = m.inside.inside;
        v.band_runs = m.inside.runs;
        v.outside = m.outside_band;
    }
    v.failed_runs = m.failed_runs;
    v.agreement_pass = v.agreement.value >= kOverturningAgreementTarget;
    v.fragility_pass = std::abs(v.median_ratio.value - 1.0) <= kFragilityMedianTarget;
    v.log_peak = m.log_peak_ratio;
    v.overturned_alone = m.overturned_alone;
    v.stood_alone = m.stood_alone;
    v.failed_paired = m.failed_paired;
    // A failed run counts against the engine: on the side of the larger discordant count.
    const long b = m.overturned_alone + (m.overturned_alone >= m.stood_alone ? m.failed_paired : 0);
    const long c = m.stood_alone + (m.overturned_alone >= m.stood_alone ? 0 : m.failed_paired);
    v.mcnemar_p = compare::mcnemar_exact_p(b, c);
    // The median within the margin (NaN: no run where both stand: fails).
    const compare::Interval& d = v.log_peak.median;
    v.band_half_width = m.band_half_width;
    v.peak_pass = std::abs(d.value) <= kPeakLogRatioTarget;
    v.overturning_pass = m.stripes && v.mcnemar_p >= kMcNemarAlpha && v.agreement_pass;
    v.pass = v.peak_pass && v.overturning_pass;
    return v;
}

namespace {

// Runs the study of `spec` into dir (its rows only, no outputs) and keeps its rows: the stand-ins' and the paper's
// model's ensembles beside the report's.
study::StudyData run_rows(const study::StudySpec& spec, const std::filesystem::path& dir, const EarthquakeRunOptions& options) {
    const study::Grid grid(spec);
    const study::StudyRunOptions run = study_run_options(options);
    study::StudyRunResult result;
    {
        const io::FolderLock lock = study::prepare_study_dir(grid, dir, run);
        result = study::run_study(grid, dir, run);
    }
    return study::take_study_data(result, dir);
}

}  // namespace

std::vector<SettingsVerdict> judge_settings(const std::string& study_file, const std::string& engine,
                                            const io::Json& settings, const std::filesystem::path& dir,
                                            const EarthquakeRunOptions& options) {
    const study::StudyData d = run_rows(settings_spec(study_file, engine, settings), dir, options);
    const study::EnsembleMeasures e = study::ensemble_measures(d);
    std::vector<SettingsVerdict> out;
    for (const study::SeriesMeasures& m : e.measures) {
        const study::Series& s = d.series[m.series];
        if (s.engine != engine || (e.has_reference && m.series == e.reference)) continue;
        out.push_back({settings_of(s.settings), judge_series(engine, m)});
    }
    return out;
}

namespace {

// The paper's model judged as an engine against the reference on the report's ensemble (run into dir).
std::optional<EarthquakeVerdict> judge_paper_model(const std::string& study_file, const std::filesystem::path& dir,
                                                   const EarthquakeRunOptions& options) {
    const study::StudyData d = run_rows(assumption_sets_spec(study_file), dir, options);
    const study::EnsembleMeasures e = study::ensemble_measures(d);
    for (const study::SeriesMeasures& m : e.measures)
        if (d.series[m.series].set == to_string(AssumptionSet::paper)) {
            EarthquakeVerdict v = judge_series("analytic", m);
            v.engine = "analytic, paper's assumptions";
            return v;
        }
    return std::nullopt;
}

}  // namespace

std::string earthquake_study_file(const std::string& name_or_path, const std::vector<std::string>& engines) {
    if (name_or_path == "none") return "";
    const std::string file = name_or_path == "default" ? shipped_studies_dir() + "/" + kShippedStudy
                             : name_or_path == "full"  ? shipped_studies_dir() + "/" + kShippedFullStudy
                                                       : name_or_path;
    require_judgeable(with_engines(file, engines), file);
    return file;
}

std::string default_earthquake_for_suite(const std::string& suite) { return suite == "full" ? "full" : "default"; }

EarthquakePart run_earthquake_part(const std::string& study_file, const std::vector<std::string>& engines,
                                   const std::filesystem::path& dir, const EarthquakeRunOptions& options) {
    const study::StudySpec spec = with_engines(study_file, engines);
    require_judgeable(spec, study_file);
    const study::Grid grid(spec);
    const study::StudyRunOptions run = study_run_options(options);
    const io::FolderLock lock = study::prepare_study_dir(grid, dir, run);
    study::StudyRunResult result = study::run_study(grid, dir, run);
    study::OutputOptions output;
    output.plots = options.plots;
    output.gnuplot = options.gnuplot;
    const study::StudyData d = study::take_study_data(result, dir);
    const study::EnsembleMeasures e = study::ensemble_measures(d);  // once: the study's outputs and the verdicts read the same
    study::write_study_outputs(dir, output, d, e);

    EarthquakePart part;
    static_cast<StudyPartRun&>(part) = study_part_run(study_file, spec, dir, result);
    // Its own plots beside the study's (a missing gnuplot leaves their scripts and data, as the study's).
    if (options.plots) io::draw_plots(earthquake_plot_scripts(d, e), dir / "plots", options.gnuplot);
    if (e.has_reference) {
        const study::Series& ref = d.series[e.reference];
        part.reference = fmt::format("the analytic model ({})", study::assumptions_text(ref));
    }
    // The ensemble as the file gives it (results.csv's pga column also holds the band's perturbed levels).
    for (const study::PartSpec& p : spec.parts) {
        part.records += p.excitation_axis("file")->levels.size();
        part.levels = std::max(part.levels, p.excitation_axis("pga")->levels.size());
    }
    for (const study::SeriesMeasures& m : e.measures)
        if (e.has_reference && m.series == e.reference) {
            part.reference_median = m.fit.median;
            part.reference_note = study::fit_note(m.fit);
            if (!part.reference_note.empty()) part.reference_median = {kNaN, kNaN, kNaN, m.fit.median.n};
        }
    part.preferred_reference = e.preferred_reference;
    part.band = d.column("perturbation") != std::string::npos;
    for (const std::string& engine : engines) {
        const auto m = std::find_if(e.measures.begin(), e.measures.end(),
                                    [&](const study::SeriesMeasures& x) { return d.series[x.series].engine == engine; });
        if (m != e.measures.end()) {
            part.engines.push_back(verdict_of(d, *m));
            continue;
        }
        EarthquakeVerdict none;  // no row at all: every run failed before measuring
        none.engine = engine;
        none.agreement = none.median_ratio = {kNaN, kNaN, kNaN, 0};
        none.fit_note = "no result on any run";
        none.log_peak.median = none.agreement;
        part.engines.push_back(none);
    }
    io::Json errors = io::Json::array({0.0});  // the reference first: the unchanged model
    for (double error : detection_restitution_errors()) errors.push_back(error);
    const std::vector<SettingsVerdict> stand_ins =
        judge_settings(study_file, "analytic", io::Json{{multibody::kRestitutionErrorKnob, errors}}, dir / "stand-ins", options);
    for (const SettingsVerdict& s : stand_ins) {
        EarthquakeVerdict v = s.verdict;
        v.engine = fmt::format("analytic, restitution {:+g} %", 100.0 * s.settings.value(multibody::kRestitutionErrorKnob, 0.0));
        part.stand_ins.emplace_back(s.settings.value(multibody::kRestitutionErrorKnob, 0.0), v);
    }
    part.detection_limit = detection_limit(part.stand_ins);
    if (options.paper_model) part.paper_model = judge_paper_model(study_file, dir / "paper-model", options);
    return part;
}

namespace {

// One engine's (or stand-in's) verdicts: the keys of before (overturning_agreement, fragility_median_ratio,
// peak_ratio, inside_band) and the paired ones.
io::Json verdict_json(const EarthquakeVerdict& v) {
    io::Json agreement = interval_json(v.agreement), ratio = interval_json(v.median_ratio);
    agreement["pass"] = v.agreement_pass;
    agreement["failed_runs"] = v.failed_runs;
    ratio["pass"] = v.fragility_pass;
    ratio["note"] = v.fit_note;
    ratio["verdict"] = false;  // information: not part of the engine's pass
    ratio["failed_replicates"] = v.ratio_failed;  // resamples without a fit (left out of the interval)
    io::Json peak = interval_json(v.log_peak.median);
    peak["median_ratio"] = io::finite_or_null(std::exp(v.log_peak.median.value));
    peak["runs"] = v.log_peak.values;
    peak["records"] = v.log_peak.records;
    peak["note"] = v.log_peak.reason;  // why its interval is not resolved ("" when it is)
    peak["pass"] = v.peak_pass;
    peak["target"] = kPeakLogRatioTarget;
    peak["band_half_width"] = io::finite_or_null(v.band_half_width);
    return {{"engine", v.engine},
            {"settings", settings_of(v.settings)},  // as run under records, which may differ from the suite's
            {"pass", v.pass},
            {"overturning_agreement", agreement},
            {"overturning_mcnemar", {{"overturned_alone", v.overturned_alone},
                                     {"stood_alone", v.stood_alone},
                                     {"failed_runs", v.failed_paired},
                                     {"p", v.mcnemar_p},
                                     {"pass", v.overturning_pass}}},
            {"peak_log_ratio", peak},
            {"fragility_median_ratio", ratio},
            {"peak_ratio", {{"median", io::finite_or_null(v.peak_ratio.median)},
                            {"q1", io::finite_or_null(v.peak_ratio.q1)},
                            {"q3", io::finite_or_null(v.peak_ratio.q3)},
                            {"n", v.peak_ratio.n}}},
            {"inside_band", {{"inside", v.inside}, {"runs", v.band_runs}, {"outside", v.outside}}}};
}

}  // namespace

io::Json earthquake_json(const EarthquakePart& part) {
    io::Json engines = io::Json::array();
    for (const EarthquakeVerdict& v : part.engines) engines.push_back(verdict_json(v));
    io::Json stand_ins = io::Json::array();
    for (const auto& [error, v] : part.stand_ins) {
        io::Json s = verdict_json(v);
        s["restitution_error"] = error;
        stand_ins.push_back(s);
    }
    return io::Json{{"study", part.study_name},
                {"folder", part.folder.filename().string()},
                {"reference", part.reference},
                {"reference_median_g", interval_json(part.reference_median)},
                {"reference_median_note", part.reference_note},
                {"targets", {{"overturning_agreement_min", kOverturningAgreementTarget},
                             {"fragility_median_within", kFragilityMedianTarget},
                             {"peak_log_ratio_within", kPeakLogRatioTarget},
                             {"mcnemar_alpha", kMcNemarAlpha}}},
                {"records", part.records},
                {"levels", part.levels},
                {"rows", part.rows},
                {"failed_rows", part.failed_rows},
                {"engines", engines},
                {"stand_ins", stand_ins},
                {"detection_limit_restitution_error", io::finite_or_null(part.detection_limit)},
                // Its pass keys are what an engine with these numbers would get: the report shows no verdict.
                {"paper_model", part.paper_model ? verdict_json(*part.paper_model) : io::Json(nullptr)}};
}

}  // namespace vssw::validation

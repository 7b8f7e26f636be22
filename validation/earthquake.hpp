#pragma once
// The report's earthquake part: a small record ensemble (a study file of kind "ensemble" with stripes,
// studies/ensemble-report.toml by default) run by the study machinery for the analytic reference and the report's
// engines into the report's folder (earthquake/: results.csv, fragility.csv, agreement.csv, plots, study.md), and a
// verdict per engine from its ensemble measures (study/ensemble_measures.hpp) against two targets set from
// measurements (docs/earthquakes.md, "In the report"). Single runs under a record are not judged: their
// peaks switch branch for a 1 % change of the scale (the response's own sensitivity); these measures are what the
// engines can be held to.
#include <filesystem>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include "compare/ensemble_statistics.hpp"
#include "study/ensemble_measures.hpp"
#include "io/document.hpp"
#include "io/json.hpp"
#include "validation/study_engines.hpp"

namespace vssw::validation {

// An engine passes under records when both its verdicts pass (binary agreement alone never passes it):
//  - peaks: over the runs where both stand, d = ln(engine peak / reference peak); the median of d lies within
//    +-kPeakLogRatioTarget (a 95 % interval over records is printed beside it, not judged: the records' medians'
//    order statistics, from 6 records; on fewer "not resolved", compare/paired_runs.hpp);
//  - overturning: the exact McNemar test of the discordant runs (b: it overturned alone, c: the reference alone; a
//    run it failed counts on the side of the larger count) at p >= kMcNemarAlpha, and agreement on at least
//    kOverturningAgreementTarget of the runs.
// The fragility median's ratio is information, not a verdict: on 4 records its interval spans +-40 %.
//
// The peaks' margin in ln, on the median. Measured on the report's ensemble (11 runs where both stand;
// docs/earthquakes.md, "Verdicts"), the median ratio: every engine at its defaults 0.965 (Bullet) to 1.008 (Simbody),
// at a quarter of its step 0.995 to 1.006; the analytic stand-in 0.986 at a restitution error of -2 %, 1.011 at +2 %,
// 0.949 at -5 %, 1.179 at +5 %; ODE dt 12 ms 0.806, cfm 1e-5 2.29, MuJoCo dampratio 0.3 0.855. e^-0.045 = 0.956 and
// e^0.045 = 1.046 lie between the sound engines (|d| <= 0.036) and more than twice the restitution target (|d| >=
// 0.052): the margins are thin on this ensemble (0.009 and 0.007 in ln), which the report states.
constexpr double kPeakLogRatioTarget = 0.045;
// The McNemar test's level: below it the engine's overturning disagrees with the reference's in one direction.
constexpr double kMcNemarAlpha = 0.05;
// At least this share of records x levels on which an engine and the reference agree whether the wall overturns
// (the reference's own band flips 1 of 40 runs on 8 records x 5 levels): a cap on the disagreements McNemar, which
// reads only their direction, lets through.
constexpr double kOverturningAgreementTarget = 0.9;
// Information: the engine's fragility median (a lognormal fitted to its stripes) within this fraction of the
// reference's, on the point estimate (the paper's Eq. (19) impact moves the reference's own median by +14 %).
constexpr double kFragilityMedianTarget = 0.10;
// The analytic stand-ins the report runs beside the reference (its detection limit): the reference with every
// impact's velocity ratio changed by these fractions (the analytic backend's restitution_error).
inline const std::vector<double>& detection_restitution_errors() {
    static const std::vector<double> errors = {-0.2, -0.1, -0.05, -0.02, 0.02, 0.05, 0.1, 0.2};
    return errors;
}

struct EarthquakeVerdict {
    std::string engine;
    std::string settings;              // the settings it ran under records ("cfm=1e-05"; "" its defaults)
    compare::Interval agreement{};     // overturning agreement with the reference (Wilson 95 %)
    compare::Interval median_ratio{};  // fragility median / the reference's (paired bootstrap 95 %)
    std::string fit_note;              // why the engine's fragility ratio is not resolved (empty when it is)
    long ratio_failed = 0;             // the ratio's bootstrap resamples without a fit
    compare::Quartiles peak_ratio{};   // its peak / the reference's where both stand
    long failed_runs = 0;              // its runs with no result (each a disagreement where the reference has one)
    long inside = 0, band_runs = 0;    // its peaks inside the reference's sensitivity band
    std::vector<std::string> outside;  // the runs outside it ("file at 0.55 g")
    bool agreement_pass = false, fragility_pass = false;  // fragility_pass: information (not part of `pass`)
    // The paired verdicts.
    compare::RecordMedian log_peak{};  // median ln(its peak / the reference's) where both stand, 95 % over records
    long overturned_alone = 0, stood_alone = 0, failed_paired = 0;  // McNemar's b, c and its failed runs
    double mcnemar_p = 1.0;              // b and c with the failed runs counted on the larger side
    // The band's median half-width in ln: how far the targets' own tolerances move one run's peak (information: a
    // run's scatter, not the median's bias the verdict reads against kPeakLogRatioTarget).
    double band_half_width = NAN;
    bool peak_pass = false, overturning_pass = false;
    bool pass = false;  // peak_pass && overturning_pass
};

// The verdict's rules on the measures of one series against the reference (the report's and the detection test's).
EarthquakeVerdict judge_series(const std::string& engine, const study::SeriesMeasures& m);

struct EarthquakePart : StudyPartRun {  // the study's file, name, folder, rows and time (study_engines.hpp)
    std::string reference;                 // the reference series' label
    bool preferred_reference = true;       // exact / whole-mechanism / unilateral (always, for a judged study)
    bool band = false;                     // the reference ran its perturbed repeats
    std::size_t records = 0, levels = 0;   // the ensemble: records x PGA levels
    compare::Interval reference_median{};  // the reference's fragility median [g] with its bootstrap interval
    std::string reference_note;            // why it is not resolved ("" when it is)
    std::vector<EarthquakeVerdict> engines;  // in the report's engine order
    // The analytic stand-ins (detection_restitution_errors(), in that order) judged as engines, and the smallest
    // restitution error from which on every stand-in fails (NaN: some error up to the largest passes).
    std::vector<std::pair<double, EarthquakeVerdict>> stand_ins;
    double detection_limit = 0.0;
    // The analytic model under the set `paper` measured as an engine against the reference (EarthquakeRunOptions::
    // paper_model): what the paper's assumptions change under records, shown with no verdict.
    std::optional<EarthquakeVerdict> paper_model;
};

// The ensemble study the report runs for `engines`: FILE as given, or "" for none when it is "none"; "default" names
// the shipped studies/ensemble-report.toml (4 records x 4 PGAs), "full" studies/ensemble-report-full.toml (the 26
// shipped records x the same PGAs). InputError, before anything runs, for a file that does not read with
// those engines or that the report cannot judge: one part of one wall, stripes of >= 2 records measuring overturned
// and peak_rotation, one run per engine, the reference (exact, whole-mechanism, unilateral) among its runs.
std::string earthquake_study_file(const std::string& name_or_path, const std::vector<std::string>& engines);
// The ensemble a suite is judged on when --earthquake is not given: "full" for the full suite (a verdict on >= 20
// records), "default" otherwise.
std::string default_earthquake_for_suite(const std::string& suite);

struct EarthquakeRunOptions : PartRunOptions {
    bool paper_model = false;  // also run the analytic model under the set `paper` (EarthquakePart::paper_model)
};

// Runs the study for the analytic reference and `engines` into dir (created; its study outputs written) and judges
// each engine.
EarthquakePart run_earthquake_part(const std::string& study_file, const std::vector<std::string>& engines,
                                   const std::filesystem::path& dir, const EarthquakeRunOptions& options);

// The report's ensemble (study_file) run, without its band, for the analytic reference and `engine` at `settings`
// (a JSON object of a study's [settings.ENGINE]: a value or a list per knob, a series per combination; for
// engine "analytic" the first series is the reference) into dir; every other series of `engine` judged. The detection
// test's and the report's stand-ins' runner.
struct SettingsVerdict {
    io::Json settings;  // the series' knobs {"dt": 0.001, ...}
    EarthquakeVerdict verdict;
};
std::vector<SettingsVerdict> judge_settings(const std::string& study_file, const std::string& engine,
                                            const io::Json& settings, const std::filesystem::path& dir,
                                            const EarthquakeRunOptions& options);

// The part as results.json holds it (`vssw report --help` lists the keys): study, reference, targets, records,
// levels, engines [{engine, settings, pass, overturning_agreement, overturning_mcnemar, peak_log_ratio (lo and
// hi null, note the reason, when not resolved), fragility_median_ratio (information), peak_ratio, inside_band}],
// stand_ins, detection_limit_restitution_error, paper_model (the paper's model as an engine's keys, or null).
io::Json earthquake_json(const EarthquakePart& part);

// One line per engine for the report's standard output: "ODE under records: pass; peaks x 0.988 [0.973, 1.000]
// (target: median within x 1.046^+-1) pass; overturning b/c 0/0, p 1.000, 16/16 (...) pass; fragility median ...
// (information)", then the detection limit.
std::vector<std::string> earthquake_summary_lines(const EarthquakePart& part);

// The report's blocks (validation/earthquake_document.cpp). Under "At a glance": the two ensemble measures as
// columns of the engine x measure matrix (their headers; an engine's two verdict cells, "-" where the part has no
// verdict for it) and a paragraph saying what they are; the per-engine fragility plot among the figures per measure
// (none when it was not drawn); then the section with every number and the other plots.
std::vector<std::string> earthquake_matrix_header();
std::vector<io::DocCell> earthquake_matrix_cells(const EarthquakePart& part, const std::string& engine);
// The paper's model's two cells: the same numbers with no verdict mark ("-" when it did not run).
std::vector<io::DocCell> earthquake_information_cells(const EarthquakePart& part);
std::vector<io::DocBlock> earthquake_glance(const EarthquakePart& part);
std::vector<io::DocBlock> earthquake_figure(const EarthquakePart& part);
std::vector<io::DocBlock> earthquake_section(const EarthquakePart& part);

}  // namespace vssw::validation

#pragma once
// The report's "What the paper's assumptions cost": a study that relaxes the paper's physical assumptions one at a
// time (studies/assumptions-report.toml by default, studies/assumptions-physical.toml with --suite full; the study keys
// of kPhysicalAssumptionKeys, study/spec.hpp), run by the study machinery for the analytic model and the report's
// engines into the report's folder (relaxations/: results.csv, plots with the tornado charts, study.md), and what it
// says: for each relaxation and metric, the change the model gives and the range the engines give, paired run by run
// with the paper's assumption (study/effects.hpp). An engine that cannot express a relaxation refuses it: its runs are
// failed rows with the engine's reason, listed, never a silent paper-assumption run.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "io/document.hpp"
#include "io/json.hpp"
#include "validation/study_engines.hpp"

namespace vssw::validation {

// One relaxation's change of one metric against the paper's assumption (relative; a 0/1 metric: net share that flips).
struct RelaxationEffect {
    std::string parameter, from, to;  // the study key, the paper's level and the relaxed one
    std::string metric;               // the study's metric name
    bool binary = false;
    // A slip (unit b: its paired value is about 0, so a relative change is noise): the relaxed runs' values
    // themselves, in b, in engines_lo and engines_hi, and no model value (the model cannot slide).
    bool absolute = false;
    // The analytic model's median change over its pairs without a warning; NaN where it has none, and for friction
    // (its motion has none: it cannot slide, it only warns where it would).
    double model = 0.0;
    double engines_lo = 0.0, engines_hi = 0.0;  // the smallest and largest over the engines' pairs; NaN without
    long model_pairs = 0, engine_pairs = 0;
};

struct AssumptionsPart : StudyPartRun {  // the study's file, name, folder (relaxations/), rows, time
    std::vector<RelaxationEffect> effects;  // the study's order of parameters and levels, then of metrics
    std::vector<std::string> tornadoes;      // the tornado charts drawn: "../relaxations/plots/<name>" (no extension)
    std::vector<std::string> tornado_titles;
    // "ODE: <reason> (n rows)": the failed rows by engine and reason, the relaxations an engine (or the model) cannot
    // express among them: the statuses do not tell a refusal from a failure to measure.
    std::vector<std::string> refusals;
    // "analytic: <warning> (n rows)": the model's rows outside its validity (it would slide, a pivot would pull);
    // their changes are not the model's (RelaxationEffect::model leaves them out).
    std::vector<std::string> model_warnings;
};

// "default" (studies/assumptions-report.toml), "full" (studies/assumptions-physical.toml), "none" (""), or a study
// file's path; the file is read (InputError naming it) and must vary at least one physical assumption.
std::string assumptions_study_file(const std::string& name_or_path, const std::vector<std::string>& engines);
// What `vssw report` runs when --relaxations is not given: "full" with --suite full, else "default".
std::string default_assumptions_for_suite(const std::string& suite);

// Runs the study for the analytic model and `engines` into dir (created; the study's outputs written).
AssumptionsPart run_assumptions_part(const std::string& study_file, const std::vector<std::string>& engines,
                                     const std::filesystem::path& dir, const PartRunOptions& options);

// The report's section, and its results.json object.
std::vector<io::DocBlock> assumptions_section(const AssumptionsPart& p);
io::Json assumptions_json(const AssumptionsPart& p);
// Summary lines for the terminal: one per relaxation's largest change.
std::vector<std::string> assumptions_summary_lines(const AssumptionsPart& p);

}  // namespace vssw::validation

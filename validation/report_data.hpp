#pragma once
// The machine-readable half of `vssw report`: results.json (everything) and the CSV files. Layout and keys are
// documented in `vssw report --help` and docs/guide/report.md; a key may be added, and one renamed or changing meaning
// bumps kReportFormat.
//
// results.json:
//   vssw {commit, report_format}, date, suite {name, walls [{id, label, kind}], records [{id, label, path, scale}],
//   cases [{id, kind, wall, r, record, dt}]}, reference_assumptions ("mechanism" or "paper"), engines [{name, version,
//   contact_scheme, settings {dt, iterations, knobs}}] (iterations only where the engine's settings set a count: not
//   the analytic model's, ODE's direct solver's, Simbody's ...), targets {metric: relative error}, rows [{case_id,
//   engine, metric, unit, reference, analytic, engine_value, error, target, within_target}], failures [{case_id,
//   engine, message}], model_warnings, summary [{engine, line, within, with_target, not_measured, failures,
//   max_error {metric: {error, case_id}}}], matrix [{engine, metric, worst_error, case_id, target, pass, rows,
//   not_measured, failed}], other_set {engine, assumptions, label, finding, matrix [as matrix, no pass], rows [as
//   rows], failures} (the analytic model under the other set, no verdict; null when it did not run), findings [text],
//   step_study [{engine, case_id, metric, dt [], rel_error [], order}], traces [{case_id, engine, assumption,
//   samples}], earthquake (null when none ran), relaxations (null when none ran), plots {made, note}, wall_time_s,
//   threads. Every NaN is null. "error" is the relative error engine / reference - 1, but for rms_difference the RMS
//   difference over the analytic peak and for overturned the difference.
// metrics.csv:  case_id,engine,metric,unit,reference,analytic,engine_value,error   (one line per row)
// failures.csv: case_id,engine,message
// traces.csv:   case_id,engine,t,theta1_over_alpha1,assumption   (every trace, one line per sample; t to
//               kTraceTimeDigits and theta1/alpha1 to kTraceValueDigits significant digits; assumption: the analytic
//               model's, validation::Trace)
#include <iosfwd>
#include <string>

#include "io/csv.hpp"
#include "io/json.hpp"
#include "validation/report.hpp"

namespace vssw::validation {

// Bumped when a key is renamed or changes meaning (never for an added key). 2: rows' and summary's rel_error became
// error, matrix's worst_rel_error worst_error, metrics.csv's rel_error column error, traces.csv's theta1_over_alpha
// column theta1_over_alpha1, the unit "alpha" "alpha1".
constexpr int kReportFormat = 2;

// traces.csv's significant digits (and the trace plots' data). t: 6 keep 0.1 ms up to 100 s, finer than any trace's
// sampling (1 ms and up). theta1 / alpha1: 4 round a value by at most 5e-4 of itself, which is at most 5e-4 of the
// plot's y range (the range spans every value and zero): 0.2 px of a 420 px plot, below what a plot shows.
constexpr int kTraceTimeDigits = 6;
constexpr int kTraceValueDigits = 4;
// A number with this many significant digits ("" when not finite).
std::string trace_number(double value, int digits);

io::Json results_json(const ReportInput& in);
// An engine's settings as results.json and bench.json write them: {dt, iterations, knobs {name: value}}, iterations
// only when the settings set a count (> 0; 0 is an engine without iterations or its own choice).
io::Json settings_json(const multibody::EngineSettings& s);
void write_metrics_csv(std::ostream& out, const SuiteResults& results);
void write_failures_csv(std::ostream& out, const SuiteResults& results);
void write_traces_csv(std::ostream& out, const SuiteResults& results);

}  // namespace vssw::validation

#pragma once
// The machine-readable half of `vssw report`: results.json (everything) and the CSV files. Layout and keys are
// documented in `vssw report --help` and the README; keys may be added, none renamed.
//
// results.json:
//   vssw {commit, report_format}, date, suite {name, walls [{id, label, kind}], records [{id, label, path, scale}],
//   cases [{id, kind, wall, r, record, dt}]}, engines [{name, version, settings {dt, iterations, knobs}}],
//   targets {metric: relative error}, rows [{case_id, engine, metric, unit, reference, analytic, engine_value,
//   rel_error, target, within_target}], failures [{case_id, engine, message}], summary [{engine, line, within,
//   with_target, not_measured, failures, max_error {metric: {rel_error, case_id}}}], findings [text],
//   step_study [{engine, case_id, metric, dt [], rel_error [], order}], traces [{case_id, engine, samples}],
//   plots {made, note}, wall_time_s, threads. Every NaN is null.
// metrics.csv:  case_id,engine,metric,unit,reference,analytic,engine_value,rel_error   (one line per row)
// failures.csv: case_id,engine,message
// traces.csv:   case_id,engine,t,theta1_over_alpha   (every trace, one line per sample)
#include <iosfwd>
#include <string>

#include "study/csv.hpp"
#include "study/json.hpp"
#include "study/report.hpp"

namespace vssw::study {

// Bumped when a key changes meaning (never for an added key).
constexpr int kReportFormat = 1;

Json results_json(const ReportInput& in);
// An engine's settings as results.json and bench.json write them: {dt, iterations, knobs {name: value}}.
Json settings_json(const multibody::EngineSettings& s);
void write_metrics_csv(std::ostream& out, const compare::SuiteResults& results);
void write_failures_csv(std::ostream& out, const compare::SuiteResults& results);
void write_traces_csv(std::ostream& out, const compare::SuiteResults& results);

}  // namespace vssw::study

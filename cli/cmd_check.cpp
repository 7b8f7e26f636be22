// `vssw check --bounds FILE`: runs only the suite cases and engines a bounds file names, holds every measured value
// against its bound, prints the verdicts, and exits 0 when all hold, 1 when any does not (BoundsViolated), 2 on a
// missing or malformed file.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "validation/bounds_file.hpp"
#include "validation/bounds_violated.hpp"
#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "validation/earthquake_bounds.hpp"
#include "validation/stress_bounds.hpp"
#include "io/json.hpp"
#include "cli/run_budget_option.hpp"
#include "validation/bounds.hpp"
#include "validation/suite.hpp"
#include "validation/suite_file.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {
namespace {

struct CheckOptions {
    std::string bounds;
    std::string data_dir = shipped_data_dir();
    std::string threads_text = "0";  // --threads as typed, checked by parse_bounded_int
    int threads = 0;
    bool json = false;
};

std::string value_text(const validation::BoundVerdict& v) {
    if (!v.value_label.empty()) return v.value_label;  // a stress verdict
    if (!std::isfinite(v.value)) return "-";
    if (v.earthquake) return fmt::format("{:.4g}", v.value);
    return v.engine == "analytic" ? fmt::format("{:.8g}", v.value) : fmt::format("{:+.3e}", v.value);
}

std::string bound_text(const validation::BoundVerdict& v) {
    if (!v.allowed_label.empty()) return v.allowed_label;
    if (v.earthquake)
        return fmt::format("[{}, {}]", std::isfinite(v.lo) ? fmt::format("{:.4g}", v.lo) : "-",
                           std::isfinite(v.hi) ? fmt::format("{:.4g}", v.hi) : "-");
    return v.engine == "analytic" ? fmt::format("[{:.8g}, {:.8g}]", v.lo, v.hi)
                                  : fmt::format("[{:+.3e}, {:+.3e}]", v.lo, v.hi);
}

void print_table(std::ostream& out, const std::vector<validation::BoundVerdict>& verdicts) {
    std::vector<std::vector<std::string>> rows = {{"engine", "case", "metric", "value", "allowed", "verdict"}};
    for (const auto& v : verdicts)
        rows.push_back({v.engine, v.case_id, v.metric, value_text(v), bound_text(v),
                        v.held ? "ok" : (v.note.empty() ? "OUT" : "OUT (" + v.note + ")")});
    std::vector<size_t> width(rows.front().size() - 1, 0);  // the verdict column is last and not padded
    for (const auto& r : rows)
        for (size_t c = 0; c < width.size(); ++c) width[c] = std::max(width[c], r[c].size());
    for (const auto& r : rows) {
        std::string line;
        for (size_t c = 0; c < width.size(); ++c) line += fmt::format("{:<{}}  ", r[c], width[c]);
        out << line << r.back() << '\n';
    }
}

io::Json verdicts_json(const std::vector<validation::BoundVerdict>& verdicts, const validation::SuiteResults& results,
                   const std::string& bounds_path, const std::string& suite_name) {
    io::Json list = io::Json::array();
    for (const auto& v : verdicts) {
        io::Json j;
        j["engine"] = v.engine;
        j["case"] = v.case_id;
        j["metric"] = v.metric;
        if (!v.allowed_label.empty()) {  // a stress verdict: the verdict and the allowed ones
            j["kind"] = "stress";
            j["value"] = v.value_label;
            j["allowed"] = v.allowed_label;
        } else {
            j["kind"] = v.earthquake ? "earthquake" : v.engine == "analytic" ? "drift" : "rel_error";
            j["value"] = io::finite_or_null(v.value);
            j["min"] = io::finite_or_null(v.lo);
            j["max"] = io::finite_or_null(v.hi);
        }
        j["held"] = v.held;
        j["note"] = v.note;
        list.push_back(j);
    }
    io::Json doc;
    doc["bounds"] = bounds_path;
    doc["suite"] = suite_name;
    doc["held"] = std::all_of(verdicts.begin(), verdicts.end(), [](const auto& v) { return v.held; });
    doc["verdicts"] = list;
    doc["wall_time_s"] = results.wall_time_s;
    return doc;
}

// The cases named by engine bounds, each once.
std::vector<std::string> engine_cases_needed(const validation::Bounds& bounds) {
    validation::Bounds engines_only;
    engines_only.engines = bounds.engines;
    return validation::cases_needed(engines_only);
}

// A bound on a metric its case does not measure is a mistake in the file (exit 2), not a bound out (exit 1).
void require_measurable(const validation::Bounds& bounds, const validation::Suite& suite, const std::string& path) {
    auto check = [&](const std::string& case_id, const std::string& metric, const std::string& engine) {
        for (const validation::SuiteCase& c : suite.cases) {
            if (c.id != case_id) continue;
            const auto metrics = validation::metrics_of(c.kind, suite.wall(c.wall_id).scene.is_vssw());
            if (std::find(metrics.begin(), metrics.end(), metric) == metrics.end())
                throw InputError(fmt::format("bounds file {}: case '{}' ({}) has no metric '{}' (it has: {})", path, case_id,
                                             validation::to_string(c.kind), metric, fmt::join(metrics, ", ")));
            if (!c.engine.empty() && engine != c.engine)
                throw InputError(fmt::format("bounds file {}: case '{}' runs for {} only, not for {}", path, case_id, c.engine,
                                             engine));
        }
    };
    const std::vector<std::string> available = multibody::available_engines();
    for (const validation::EngineBound& b : bounds.engines)
        if (std::find(available.begin(), available.end(), b.engine) == available.end())
            throw InputError(fmt::format("bounds file {}: engine '{}' is not in this build (available: {})", path, b.engine,
                                         fmt::join(available, ", ")));
    for (const validation::AnalyticBound& b : bounds.analytic) check(b.case_id, b.metric, "analytic");
    for (const validation::EngineBound& b : bounds.engines)
        for (const std::string& id : b.case_ids) check(id, b.metric, b.engine);
}

void run_check(const CheckOptions& o, std::ostream& out) {
    const validation::Bounds bounds = validation::read_bounds_file(o.bounds);
    const validation::Suite all = validation::read_suite(bounds.suite, o.data_dir);
    validation::RunOptions run;
    run.threads = o.threads;
    run.keep_traces = false;
    // Two runs, so that an engine runs only the cases an engine bound names: the analytic model alone on the other
    // cases, and the engines (with the analytic model, run_suite's reference) on those. Every name is checked
    // before anything runs.
    const std::vector<std::string> engine_ids = engine_cases_needed(bounds);
    std::vector<std::string> analytic_ids;
    for (const std::string& id : validation::cases_needed(bounds))
        if (std::find(engine_ids.begin(), engine_ids.end(), id) == engine_ids.end()) analytic_ids.push_back(id);
    const std::vector<std::string> engines = validation::engines_needed(bounds);
    validation::Suite suite, analytic_suite, engine_suite;
    try {
        suite = validation::select_cases(all, validation::cases_needed(bounds));
        analytic_suite = validation::select_cases(all, analytic_ids);
        engine_suite = validation::select_cases(all, engine_ids);
    } catch (const InputError& e) {
        throw InputError(fmt::format("bounds file {}: {}", o.bounds, e.what()));
    }
    require_measurable(bounds, suite, o.bounds);
    const stress::RunOptions stress_run = validation::plan_stress_bounds(bounds.stress, o.bounds, o.threads);
    validation::plan_earthquake_bounds(bounds.earthquake, o.bounds);
    validation::SuiteResults results;
    for (const auto& [part, part_engines] : {std::pair{&analytic_suite, std::vector<std::string>{}},
                                             std::pair{&engine_suite, engines}}) {
        if (part->cases.empty()) continue;
        const validation::SuiteResults r = validation::run_suite(*part, part_engines, run);
        if (results.engines.size() < r.engines.size()) results.engines = r.engines;
        results.rows.insert(results.rows.end(), r.rows.begin(), r.rows.end());
        results.failures.insert(results.failures.end(), r.failures.begin(), r.failures.end());
        results.wall_time_s += r.wall_time_s;
        results.threads = r.threads;
    }
    std::vector<validation::BoundVerdict> verdicts = validation::evaluate(bounds, results);
    // [[stress]] bounds: the named stress cases in their quick form (a few seconds; docs/guide/stress.md), counted in
    // the check's wall time.
    const auto stress_start = std::chrono::steady_clock::now();
    const auto stress_verdicts = validation::check_stress_bounds(bounds.stress, stress_run);
    results.wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - stress_start).count();
    verdicts.insert(verdicts.end(), stress_verdicts.begin(), stress_verdicts.end());
    // [[earthquake]] bounds: each named record ensemble run once for its engines (validation/earthquake.hpp).
    const auto earthquake_start = std::chrono::steady_clock::now();
    const auto earthquake_verdicts = validation::check_earthquake_bounds(bounds.earthquake, o.threads);
    results.wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - earthquake_start).count();
    verdicts.insert(verdicts.end(), earthquake_verdicts.begin(), earthquake_verdicts.end());
    const auto out_of_bounds = std::count_if(verdicts.begin(), verdicts.end(), [](const auto& v) { return !v.held; });
    if (o.json) {
        out << io::dump_json(verdicts_json(verdicts, results, o.bounds, bounds.suite), 2) << '\n';
    } else {
        out << fmt::format("vssw check: {} ({} cases, engines: analytic{}{}; {:.1f} s on {} threads)\n\n", o.bounds,
                           suite.cases.size(), engines.empty() ? "" : ", ", fmt::join(engines, ", "),
                           results.wall_time_s, results.threads);
        print_table(out, verdicts);
        out << fmt::format("\n{} of {} bounds hold\n", verdicts.size() - static_cast<size_t>(out_of_bounds),
                           verdicts.size());
    }
    if (out_of_bounds > 0)
        throw validation::BoundsViolated(fmt::format("{} of {} bounds do not hold ({})", out_of_bounds, verdicts.size(), o.bounds));
}

}  // namespace

Command add_check_command(CLI::App& root) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = root.add_subcommand(
        "check", "Hold the suite's metrics against a bounds file: exit 0 when all hold, 1 when any does not");
    cmd->add_option("--bounds", o->bounds, "bounds file, TOML (.toml) or JSON (.json); see bounds/default.toml")
        ->required();
    cmd->add_option("--data", o->data_dir, "directory of the ground-motion records (default: the shipped data/)");
    cmd->add_option("--threads", o->threads_text,
                    fmt::format("threads, 0 to {} (default 0: the available cores)", kMaxThreads));
    cmd->add_flag("--json", o->json, "print JSON instead of a table");
    add_run_budget_option(*cmd);
    cmd->footer(
        "Runs only the cases and engines the file names (the analytic model always). An engine bound holds when the "
        "engine's relative error against the analytic model (engine / analytic - 1) lies in [min, max]; an analytic "
        "bound when the analytic model's own value lies within max_drift (relative) of the stored reference. A "
        "metric that could not be measured (the engine failed, no impact) does not hold. Exit codes: 0 all hold, 1 "
        "some do not, 2 bad input (a missing or malformed bounds file, an unknown case, engine or key). [[stress]] "
        "bounds run the named `vssw stress` cases in their quick form and hold each verdict against the allowed "
        "ones. [[earthquake]] bounds (study, engine, measure, min and/or max) run the named record ensemble once "
        "(as `vssw report --earthquake`) and hold an engine's overturning_agreement, fragility_median_ratio, "
        "peak_ratio_median or inside_band (a share) in [min, max].\n"
        "JSON keys: bounds, suite, held, verdicts [{engine, case, metric, kind (drift, rel_error, stress or "
        "earthquake), value, min, max (a stress verdict: value is the verdict, allowed the verdicts allowed, no min "
        "and max; an earthquake one: case is the ensemble, metric the measure, an open end null), held, note}], "
        "wall_time_s.");
    return {cmd, [o](std::ostream& out) {
                o->threads = parse_threads(o->threads_text);
                run_check(*o, out);
            }};
}

}  // namespace vssw::cli

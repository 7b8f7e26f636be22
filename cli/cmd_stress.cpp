// `vssw stress`: the stress set (stress/cases.cpp) on every backend, each case in a child process with a time limit;
// the full set also searches each engine's largest stable step. Exit 0 when no case hung, crashed, gave NaN or
// contradicted the analytic model (ok, refused with a reason, or failed as reported by the backend itself), 3 when
// one did, 2 on bad input.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/stress_output.hpp"
#include "io/json.hpp"
#include "multibody/engine.hpp"
#include "stress/run.hpp"
#include "io/atomic_file.hpp"
#include "io/folder_swap.hpp"

namespace vssw::cli {
namespace {

// --time-limit's range [s]: an hour per case is far past the slowest full case measured (docs/guide/stress.md).
constexpr double kMaxTimeLimit = 3600.0;
using stress::kFullTimeLimit;
using stress::kQuickTimeLimit;

struct StressOptions {
    std::string out_dir;
    bool quick = false;
    bool json = false;
    std::vector<std::string> engines;
    std::vector<std::string> cases;  // --cases: only these (no step search)
    double time_limit = 0.0;  // 0: the default of the set
    std::string threads_text = "0";
};

void run_stress(const StressOptions& o, std::ostream& out) {
    if (!(o.time_limit >= 0.0 && o.time_limit <= kMaxTimeLimit))
        throw InputError(fmt::format("--time-limit must be from 0 to {} s (0: {} s quick, {} s full), got {}",
                                     kMaxTimeLimit, kQuickTimeLimit, kFullTimeLimit, o.time_limit));
    StressReport report;
    report.quick = o.quick;
    report.time_limit_s = o.time_limit > 0.0 ? o.time_limit : (o.quick ? kQuickTimeLimit : kFullTimeLimit);
    report.engines = o.engines.empty() ? multibody::available_engines() : parse_engine_list("--engines", o.engines);
    const int threads = parse_threads(o.threads_text);
    for (const std::string& name : o.cases) (void)stress::require_case(name);  // before --out is created
    // Check the folder can be written before anything runs; the files go into a staging folder that replaces it
    // whole once they are complete (io/folder_swap.hpp).
    io::FolderLock lock;  // held until the results are swapped in
    if (!o.out_dir.empty()) lock = io::check_out_folder(o.out_dir, io::OutKind::stress);
    const auto start = std::chrono::steady_clock::now();
    stress::RunOptions run;
    run.engines = report.engines;
    run.quick = o.quick;
    run.time_limit_s = report.time_limit_s;
    run.threads = threads;
    run.cases = o.cases;
    report.cases = stress::run_cases(run);
    if (!o.quick && o.cases.empty())
        report.stable_steps = stress::find_stable_steps(report.engines, report.time_limit_s, threads);
    report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const io::Json doc = stress_json(report);
    if (!o.out_dir.empty()) {
        io::StagedFolder staged(o.out_dir, io::OutKind::stress);
        staged.create();
        io::write_file(staged.path() / "stress.json", [&](std::ostream& f) { f << io::dump_json(doc, 2) << '\n'; });
        io::write_file(staged.path() / "stress.csv", [&](std::ostream& f) { write_stress_csv(f, report); });
        io::write_file(staged.path() / "stress.md", [&](std::ostream& f) { write_stress_md(f, report); });
        staged.commit();
    }
    if (o.json) out << io::dump_json(doc, 2) << '\n';
    else write_stress_table(out, report);
    std::vector<std::string> unsafe;
    for (const auto& c : report.cases)
        if (stress::is_unsafe(c)) unsafe.push_back(fmt::format("{} on {}: {}", c.name, c.engine, c.reason));
    if (!unsafe.empty())
        throw SimulationFailure(fmt::format("{} of {} stress runs hung, crashed, gave NaN or a wrong answer: {}",
                                            unsafe.size(), report.cases.size(), fmt::join(unsafe, "; ")));
}

}  // namespace

Command add_stress_command(CLI::App& root) {
    auto o = std::make_shared<StressOptions>();
    CLI::App* cmd = root.add_subcommand(
        "stress", "Hard cases on every backend, each in a child process with a time limit: ok, refused or failed");
    cmd->add_option("--out", o->out_dir, "folder for stress.json, stress.csv and stress.md (created if missing)");
    cmd->add_flag("--quick", o->quick, "the quick set (CI): fewer cases, shorter runs, no step search");
    add_list_option(*cmd, "--engines", o->engines, "backends, comma-separated (default: every one compiled in)");
    add_list_option(*cmd, "--cases", o->cases, "only these cases, comma-separated (no step search)");
    cmd->add_option("--time-limit", o->time_limit,
                    fmt::format("seconds per case and backend, up to {} (default, and 0: {} quick, {} full)",
                                kMaxTimeLimit, kQuickTimeLimit, kFullTimeLimit));
    cmd->add_option("--threads", o->threads_text,
                    fmt::format("cases at once, 0 to {} (default 0: the available cores)", kMaxThreads));
    cmd->add_flag("--json", o->json, "print JSON instead of the verdict table");
    cmd->footer(
        "Verdicts: ok (no failure, no NaN, and the case's checks held: docs/guide/stress.md), refused (the backend or "
        "the library refused the input, with its message), failed (reported: the backend's own failure; wrong: a "
        "result contradicting the analytic model; nan; timed_out; crashed). Exit codes: 0 when nothing hung, "
        "crashed, gave NaN or a wrong answer; 3 when something did; 2 bad input.\n"
        "JSON keys: quick, time_limit_s, engines, cases [{name, engine, verdict, failure, reason, time_s}], unsafe, "
        "stable_steps [{engine, wall, default_dt, largest_stable_dt, first_unstable_dt, ...}], case_list, "
        "wall_time_s.");
    return {cmd, [o](std::ostream& out) { run_stress(*o, out); }};
}

}  // namespace vssw::cli

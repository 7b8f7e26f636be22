// `vssw summary`: the project's reference case, the wall of Fig. 6 of the paper, in one report: its closed forms,
// its free vibration from half its slenderness angle, and its response to the Rinaldi record.
#include <memory>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/data_dir.hpp"
#include "cli/commands.hpp"
#include "cli/free_output.hpp"
#include "cli/history_output.hpp"
#include "cli/wall_output.hpp"
#include "io/json.hpp"

namespace vssw::cli {
namespace {

// Release of the free-vibration part: half of alpha1, well inside the range where the paper's kinematics hold
// (so that --assumptions paper gives the paper's figures).
constexpr double kSummaryTheta0 = 0.5;
const char* const kDefaultRecordFile = "NGA_no_1063_RRS228.AT2";  // Northridge 1994, Rinaldi 228, in the shipped data

}  // namespace

Command add_summary_command(CLI::App& root) {
    struct Options {
        std::string record = shipped_data_dir() + "/" + kDefaultRecordFile;
        ModelOptions model;  // a VSSW under the default assumptions unless --assumptions says otherwise
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = root.add_subcommand(
        "summary",
        "The wall of Fig. 6 (height 4 m, thickness 0.4 m, hinge h1/h 0.7, xi 0, density 1800 kg/m^3, "
        "g 9.81 m/s^2): closed forms, free vibration from 0.5 alpha1, response to a record");
    cmd->add_option("--record", o->record, "ground-motion file, used unscaled (default: the shipped Rinaldi record)")
        ->capture_default_str();
    add_assumption_options(*cmd, o->model);
    cmd->footer(
        fmt::format("Units as in 'vssw wall', 'vssw free' and 'vssw history'. The record is used unscaled, with its "
                    "own units; the\n"
                    "run lasts its duration + {} s unless the wall comes to rest or overturns first.",
                    kDefaultExtraTime));
    cmd->add_flag("--json", o->json,
                  "print JSON with the keys wall, free, history (as the wall, free and history "
                  "commands print them)");
    return {cmd, [o](std::ostream& out) {
                const WallOptions wall = fig6_wall();
                const ModelOptions& model = o->model;
                GroundMotionOptions motion;
                motion.record = o->record;

                const WallFigures figures = wall_figures(wall);
                const FreeRun free = run_free(wall, model, FreeRequest{kSummaryTheta0});
                HistoryRun history = prepare_history(wall, model, motion, HistoryRequest{});
                simulate_history(history);

                if (o->json) {
                    const io::Json j = {{"wall", to_json(figures)}, {"free", to_json(free)}, {"history", to_json(history)}};
                    out << io::dump_json(j, 2) << '\n';
                    return;
                }
                out << "vssw summary: the wall of Fig. 6 of Sorrentino, Masiani & Griffith (2008)\n\n";
                print_wall(out, figures);
                out << '\n';
                print_free_summary(out, free, fmt::format("Free vibration from rest at {} alpha1", kSummaryTheta0));
                out << '\n';
                print_history_summary(out, history, "Response to the ground motion, from rest");
            }};
}

}  // namespace vssw::cli

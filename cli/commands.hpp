#pragma once
// The subcommands of `vssw`. Each one adds itself to the root app, binds its options to storage it owns, and
// returns the action to run once the whole command line has parsed; cli.cpp runs the one that was chosen.
#include <functional>
#include <iosfwd>

namespace CLI {
class App;
}

namespace vssw::cli {

struct Command {
    CLI::App* app;                               // the subcommand, to tell which one was chosen
    std::function<void(std::ostream& out)> run;  // throws InputError or SimulationFailure on failure
    // Instead of `run`, for a command that also writes progress or warnings on the error stream (cli.hpp's `err`).
    std::function<void(std::ostream& out, std::ostream& err)> run_with_err = {};
};

Command add_wall_command(CLI::App& root);
Command add_free_command(CLI::App& root);
Command add_history_command(CLI::App& root);
Command add_summary_command(CLI::App& root);
Command add_compare_command(CLI::App& root);
Command add_report_command(CLI::App& root);
Command add_check_command(CLI::App& root);
Command add_study_command(CLI::App& root);
Command add_stress_command(CLI::App& root);
Command add_bench_command(CLI::App& root);
Command add_motions_command(CLI::App& root);
Command add_scene_command(CLI::App& root);

}  // namespace vssw::cli

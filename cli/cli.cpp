#include "cli/cli.hpp"

#include <algorithm>
#include <exception>
#include <new>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/argument_words.hpp"
#include "validation/bounds_violated.hpp"
#include "cli/commands.hpp"
#include "cli/early_output.hpp"
#include "cli/message_line.hpp"
#include "cli/option_values.hpp"
#include "cli/quiet_exit.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/version_text.hpp"
#include "multibody/host/run_budget.hpp"

namespace vssw::cli {
namespace {

int fail(std::ostream& err, const char* kind, const std::string& message, int code) {
    print_message_line(err, kind, message);
    return code;
}

// The command the user named, if any (also after a parse error).
const Command* chosen_command(const std::vector<Command>& commands) {
    for (const Command& command : commands)
        if (command.app->parsed()) return &command;
    return nullptr;
}

std::string joined(const std::vector<std::string>& words, const char* separator = " ") {
    std::string text;
    for (const std::string& w : words) text += (text.empty() ? "" : separator) + w;
    return text;
}

// "wall, free, ..." for messages, from the list of commands (nothing to update when one is added).
std::string command_names(const std::vector<Command>& commands) {
    std::vector<std::string> names;
    for (const Command& command : commands) names.push_back(command.app->get_name());
    return joined(names, ", ");
}

// CLI11 checks required options before unknown ones, so a misspelt "--heigth 4" would be reported as "--height is
// required". Arguments nobody recognised are the likelier mistake: name them first.
std::string parse_error_message(const CLI::ParseError& e, const CLI::App& app, const std::vector<Command>& commands,
                                const Command* command) {
    if (command != nullptr && !command->app->remaining().empty())
        return "unknown option or argument for '" + command->app->get_name() +
               "': " + joined(command->app->remaining());
    if (command == nullptr && !app.remaining().empty())
        return "'" + joined(app.remaining()) + "' is not a command; the commands are " + command_names(commands);
    return e.what();
}

int run_unguarded(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    multibody::RunBudget::set(std::nullopt);  // the default unless this command's --run-budget says otherwise
    CLI::App app{
        "vssw: the rocking of a vertical spanning strip wall (VSSW) and of a parapet wall, after Sorrentino, "
        "Masiani & Griffith (2008)",
        "vssw"};
    app.require_subcommand(0, 1);  // one command at a time; none prints this help
    app.footer(
        "Run 'vssw COMMAND --help' for a command's options, units and defaults. Exit codes: 0 success, 1 a bound "
        "out (vssw check), 2 bad input, 3 simulation failed.");
    // One line per command; `vssw --help` lists them in this order.
    const std::vector<Command> commands = {
        add_wall_command(app),
        add_free_command(app),
        add_history_command(app),
        add_summary_command(app),
        add_compare_command(app),
        add_scene_command(app),
        add_report_command(app),
        add_check_command(app),
        add_study_command(app),
        add_stress_command(app),
        add_bench_command(app),
        add_motions_command(app),
    };
    app.add_flag_callback(
        "--version", [] { throw EarlyOutput(version_text()); },
        "print the version, the commit and each backend's library version, then exit");
    check_argument_words(app, argc, argv);  // before CLI11 reads "-height" as the help
    try {
        app.parse(argc, argv);
    } catch (const EarlyOutput& e) {
        out << e.text;
        return kExitOk;
    } catch (const CLI::CallForHelp&) {
        out << app.help();  // the chosen subcommand's help when one was named
        return kExitOk;
    } catch (const CLI::ParseError& e) {
        const Command* command = chosen_command(commands);
        const std::string help = command != nullptr ? "vssw " + command->app->get_name() + " --help" : "vssw --help";
        return fail(err, "error", parse_error_message(e, app, commands, command) + " (see '" + help + "')", kExitBadInput);
    }
    if (const Command* command = chosen_command(commands)) {
        require_option_values(*command->app);  // also an option the command ignores: NaN is never a valid input
        if (command->run_with_err) command->run_with_err(out, err);
        else command->run(out);
        return kExitOk;
    }
    out << app.help();
    return fail(err, "error", "a command is required: " + command_names(commands), kExitBadInput);
}

}  // namespace

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    try {
        return run_unguarded(argc, argv, out, err);
    } catch (const QuietExit& e) {
        return e.code;
    } catch (const InputError& e) {
        return fail(err, "error", e.what(), kExitBadInput);
    } catch (const validation::BoundsViolated& e) {
        return fail(err, "check failed", e.what(), kExitOutOfBounds);
    } catch (const SimulationFailure& e) {
        return fail(err, "simulation failed", e.what(), kExitSimulationFailed);
    } catch (const std::bad_alloc&) {
        // Not bad input: the machine (or the process's limit, ulimit -v) had no more memory for this run.
        return fail(err, "error", "out of memory: the run needed more than this process may allocate", kExitSimulationFailed);
    } catch (const std::exception& e) {
        return fail(err, "error", e.what(), kExitBadInput);
    } catch (...) {
        return fail(err, "error", "unknown failure", kExitBadInput);
    }
}

}  // namespace vssw::cli

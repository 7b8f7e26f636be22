#pragma once
// Checks of option values that CLI11 would report without naming the value as typed, or not at all.
#include <string>
#include <vector>

#include "multibody/engine.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace vssw::cli {

// --threads of report, check, study and stress: 0 means the available cores. 256 is far above the cores of any machine this runs
// on; each thread runs one engine simulation at a time and holds its trajectory, so the bound also bounds memory.
constexpr int kMaxThreads = 256;
// --iterations of compare (multibody/engine.hpp says why 1000).

// Whole-number option: `text` must be an integer from lo to hi, else InputError
// "<name> must be an integer from <lo> to <hi><meaning>, got <text>" (meaning: e.g. " (0: the available cores)").
int parse_bounded_int(const std::string& name, const std::string& text, int lo, int hi, const std::string& meaning = "");

// --threads as typed (every command that runs cases in parallel): an integer from 0 (the available cores) to
// kMaxThreads, else InputError naming it.
int parse_threads(const std::string& text);

// A list of engines as given to `option` (comma-separated, already split): "all" stands for
// multibody::default_compared_engines() where it appears. Each name must be available in this build and appear once
// (also through "all"): InputError naming every unknown and every repeated name otherwise.
std::vector<std::string> parse_engine_list(const std::string& option, const std::vector<std::string>& names);

// The items of a comma-separated list option as given (`--engine ode,bullet`, or the option repeated), split: each
// must be non-empty and named once, else InputError naming the option and the item ("--engine has an empty item in
// 'ode,,bullet'"). One rule for every list option of every command.
std::vector<std::string> list_items(const std::string& option, const std::vector<std::string>& given);

// A comma-separated list option bound to `target` through list_items. Not CLI11's delimiter: it drops empty items
// without a word ("ode," ran ODE alone) and cannot see a repeated one.
CLI::Option* add_list_option(CLI::App& cmd, const std::string& name, std::vector<std::string>& target,
                             const std::string& help);

// Every value given to `cmd`'s options (and to its chosen subcommand's) is checked as typed: none may be empty
// (CLI11 reads an empty number as 0, or leaves the default: "--xi ''" gave xi 0), and every floating-point one must be
// finite, also one the command accepts and ignores (--hinge for a parapet). InputError "<option> must be a number, got
// an empty value", "<option> must be a finite number, got nan" otherwise. Ranges are checked where the values are used.
void require_option_values(const CLI::App& cmd);
// The message for an empty value of `option`: "<option> must be a number, got an empty value" (a number option), else
// "<option> needs a value, got an empty one".
std::string empty_value_message(const CLI::Option& option);

}  // namespace vssw::cli

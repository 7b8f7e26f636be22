#pragma once
// Checks of option values that CLI11 would report without naming the value as typed, or not at all.
#include <string>

#include "multibody/engine.hpp"
#include <vector>

namespace CLI {
class App;
}

namespace vssw::cli {

// --threads of report, check, study and stress: 0 means the available cores. 256 is far above the cores of any machine this runs
// on; each thread runs one engine simulation at a time and holds its trajectory, so the bound also bounds memory.
constexpr int kMaxThreads = 256;
// --iterations of compare (multibody/engine.hpp says why 1000).
using multibody::kMaxIterations;

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

// Every floating-point option given to `cmd` must be finite, also one the command accepts and ignores (--hinge for a
// parapet): InputError "<option> must be a finite number, got nan" otherwise. Ranges are checked where the values are
// used.
void require_finite_numbers(const CLI::App& cmd);

}  // namespace vssw::cli

#pragma once
// The `vssw` command-line program as a function, so that tests can run any command in-process.
#include <iosfwd>

namespace vssw::cli {

// Exit codes: what a script calling `vssw` can rely on.
constexpr int kExitOk = 0;
constexpr int kExitOutOfBounds = 1;       // vssw check: a metric is out of its bounds
constexpr int kExitBadInput = 2;          // bad option or value, unreadable record, no command given
constexpr int kExitSimulationFailed = 3;  // the integrator gave up (e.g. step size underflow)

// Parses argv (argv[0] is the program name) and runs the chosen command. Results go to `out`; every error is one
// line "vssw: error: <message>" (or "vssw: simulation failed: <message>") on `err`. Never throws.
int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace vssw::cli

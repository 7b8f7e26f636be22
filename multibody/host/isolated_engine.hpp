#pragma once
// An engine library run in a child process of its own, one run at a time (docs/contributing/engines.md "Isolation"): a
// library that aborts (ODE's assertions call abort()), segfaults or never returns costs one failed run, never the program,
// a study's other rows or a Python interpreter that called it. Each run is forked (multibody/host/worker_process.hpp) with
// its CPU budget (run_budget.hpp) and its trajectory comes back through a pipe, to the last bit the one the library gave:
// the results are those of the same run in the caller's process (tests/test_isolated_engine.cpp).
//
// make_engine() gives every engine library's adapter wrapped so; the analytic model, which is this project's own code
// and takes a fraction of a millisecond, runs in the caller's process. What a fork costs: docs/contributing/engines.md, "Isolation".
#include <memory>
#include <string>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// `inner` with simulate() run in a child; every other call goes to `inner` in this process. Since each run has a
// process of its own, the wrapped engine runs concurrently even when `inner` does not (ODE).
std::unique_ptr<Engine> isolated(std::unique_ptr<Engine> inner);

// A trajectory as bytes and back (what the child sends): every field, doubles bit for bit.
void append_trajectory(const Trajectory& t, std::string& out);
Trajectory read_trajectory(std::string_view bytes);

}  // namespace vssw::multibody

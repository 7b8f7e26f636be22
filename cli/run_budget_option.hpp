#pragma once
// --run-budget of every command that runs engine libraries (compare, report, check, study): the CPU time one engine
// run may take before it fails (multibody/host/run_budget.hpp).
namespace CLI {
class App;
}

namespace vssw::cli {

void add_run_budget_option(CLI::App& cmd);

}  // namespace vssw::cli

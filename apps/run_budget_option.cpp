#include "apps/run_budget_option.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "multibody/run_budget.hpp"

namespace vssw::cli {

void add_run_budget_option(CLI::App& cmd) {
    using multibody::RunBudget;
    cmd.add_option_function<double>(
        "--run-budget", [](const double& seconds) { RunBudget::set(seconds); },
        fmt::format("CPU seconds one engine run may take before it fails, {:g} to {:g} (default: {:g} s + {:g} ms per "
                    "step of the run; every engine run is a child process of its own)",
                    RunBudget::kMinSeconds, RunBudget::kMaxSeconds, RunBudget::kBaseSeconds,
                    RunBudget::kSecondsPerStep * 1e3));
}

}  // namespace vssw::cli

#include "cli/run_budget_option.hpp"

#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/host/run_budget.hpp"

namespace vssw::cli {

void add_run_budget_option(CLI::App& cmd) {
    using multibody::RunBudget;
    // Read as text: CLI11 reads an empty number as 0, and "--run-budget ''" was refused as "got 0".
    cmd.add_option_function<std::string>(
        "--run-budget",
        [](const std::string& text) {
            if (text.empty()) throw InputError("--run-budget must be a number, got an empty value");
            char* end = nullptr;
            const double seconds = std::strtod(text.c_str(), &end);
            if (*end != '\0') throw InputError(fmt::format("--run-budget must be a number, got '{}'", text));
            RunBudget::set(seconds);
        },
        fmt::format("CPU seconds one engine run may take before it fails, {:g} to {:g} (default: {:g} s + {:g} ms per "
                    "step of the run; every engine run is a child process of its own)",
                    RunBudget::kMinSeconds, RunBudget::kMaxSeconds, RunBudget::kBaseSeconds,
                    RunBudget::kSecondsPerStep * 1e3));
}

}  // namespace vssw::cli

#pragma once
// The CPU time one engine run may take before it fails (docs/contributing/engines.md "Isolation": a Simbody setting once
// made a run go on forever). Each engine run is a forked child (isolated_engine.hpp) whose CPU time the kernel limits
// (RLIMIT_CPU): past the budget it is stopped and the run fails with a message naming the budget; the program goes on.
//
// The default grows with the run's steps, t_end / dt: kBaseSeconds for setting up and ending a run, plus
// kSecondsPerStep for each step, ten times the slowest engine's measured cost per step (Simbody's rigid route,
// 189 ms per simulated second at its 0.5 ms step: 95 us a step; docs/contributing/engines.md). A Fig. 6 free vibration at
// ODE's 1 ms step (2,000 steps) may take 32 s; a 40 s record at 1 ms, 70 s. `--run-budget SECONDS` replaces the default.
#include <optional>
#include <string>

namespace vssw::multibody {

struct RunBudget {
    static constexpr double kBaseSeconds = 30.0;
    static constexpr double kSecondsPerStep = 1e-3;
    // The range a budget given by the user may take: one second (the kernel counts CPU time in whole seconds) to
    // about eleven days (past that a run is not budgeted but forgotten).
    static constexpr double kMinSeconds = 1.0;
    static constexpr double kMaxSeconds = 1e6;

    // The budget of a run of t_end seconds at step dt: the user's, else the default above.
    static double seconds(double t_end, double dt);
    // How the budget of such a run was chosen, for a failure's message ("32 s of CPU time (the default: 30 s + 1 ms
    // per step of 2000 steps; --run-budget changes it)").
    static std::string describe(double t_end, double dt);

    // The user's budget for every run from now on (--run-budget); nullopt: the default. Throws InputError naming
    // the value outside [kMinSeconds, kMaxSeconds]. Process-wide: each command sets it before it runs anything.
    static void set(std::optional<double> seconds);
    static std::optional<double> given();
};

}  // namespace vssw::multibody

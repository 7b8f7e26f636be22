#include "multibody/host/run_budget.hpp"

#include <atomic>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::multibody {
namespace {

// NaN: no budget given. Read by every pool thread, written by a command before it runs anything.
std::atomic<double> g_given{std::numeric_limits<double>::quiet_NaN()};

double default_seconds(double t_end, double dt) {
    const double steps = dt > 0.0 ? t_end / dt : 0.0;
    return RunBudget::kBaseSeconds + RunBudget::kSecondsPerStep * steps;
}

}  // namespace

double RunBudget::seconds(double t_end, double dt) {
    const std::optional<double> g = given();
    return g ? *g : default_seconds(t_end, dt);
}

std::string RunBudget::describe(double t_end, double dt) {
    if (const std::optional<double> g = given()) return fmt::format("{:g} s of CPU time (--run-budget)", *g);
    return fmt::format("{:.0f} s of CPU time (the default: {:g} s + {:g} ms per step of {:.0f} steps; --run-budget "
                       "changes it)",
                       default_seconds(t_end, dt), kBaseSeconds, kSecondsPerStep * 1e3, dt > 0.0 ? t_end / dt : 0.0);
}

void RunBudget::set(std::optional<double> seconds) {
    if (seconds)
        require(std::isfinite(*seconds) && *seconds >= kMinSeconds && *seconds <= kMaxSeconds, "--run-budget",
                fmt::format("a number of seconds from {:g} to {:g}", kMinSeconds, kMaxSeconds), *seconds);
    g_given.store(seconds ? *seconds : std::numeric_limits<double>::quiet_NaN());
}

std::optional<double> RunBudget::given() {
    const double v = g_given.load();
    if (std::isnan(v)) return std::nullopt;
    return v;
}

}  // namespace vssw::multibody

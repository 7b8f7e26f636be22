// A study's tasks report their CPU by engine (study::StudyRunOptions::task_cpu, read by bench/suite_profile.cpp to
// split a report's time by part and engine): each task once, under its run's engine, with the CPU of the engine runs'
// children its thread waited for.
#include <sys/resource.h>

#include <gtest/gtest.h>

#include <map>
#include <mutex>
#include <string>

#include "study/grid.hpp"
#include "study/runner.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"

namespace {

using namespace vssw;

// CPU of the children this process has waited for [s].
double children_cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

TEST(StudyTaskCpu, EachTaskIsCountedOnceUnderItsEngineWithItsChildrensCpu) {
    if (!vssw::testing::engine_available("ode")) GTEST_SKIP() << "ODE's plugin is not built";
    // CPU time is counted in scheduler ticks (4 ms at 250 Hz): a few lost per child, four children.
    constexpr double kAccountingSlackS = 0.02;
    const vssw::testing::TempDir dir;
    // ODE at a fine step, so that its four runs cost many ticks of CPU in their children.
    const study::Grid grid(vssw::testing::study_of(
        dir, "engines = [\"analytic\", \"ode\"]\nmetrics = [\"period\"]\n[wall]\nheight = 4\n"
             "thickness = [0.3, 0.4]\nhinge = 0.7\n[excitation]\nkind = \"free\"\ntheta0 = [0.3, 0.6]\n"
             "[settings.ode]\ndt = 5e-5\n"));
    std::mutex mutex;
    std::map<std::string, int> tasks;
    std::map<std::string, double> cpu;
    study::StudyRunOptions o;
    o.threads = 2;
    o.task_cpu = [&](const std::string& engine, double cpu_s) {
        const std::lock_guard<std::mutex> lock(mutex);
        ++tasks[engine];
        cpu[engine] += cpu_s;
    };
    const auto lock = study::prepare_study_dir(grid, dir / "out", o);  // held for the run, as the program does
    const double children_before = children_cpu_seconds();
    study::run_study(grid, dir / "out", o);
    const double children = children_cpu_seconds() - children_before;
    EXPECT_EQ(tasks, (std::map<std::string, int>{{"analytic", 4}, {"ode", 4}}));
    // The analytic runs fork nothing: every child is an ODE run, whose CPU its task holds.
    EXPECT_GE(cpu["ode"], children - kAccountingSlackS) << "children " << children << " s";
    EXPECT_GT(children, 4 * kAccountingSlackS) << "the runs must cost more than the slack for the check to mean anything";
}

}  // namespace

// Worker processes (multibody/host/worker_process.hpp): work run in a child gives the caller the very bytes it would have
// made in its own process (ODE's runs and a study's results.csv are identical with and without them), each way a
// child can fail comes back as the error it is, and a worker neither outlives its parent nor keeps its parent's signal
// handlers (analytic/child_fork.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "analytic/child_fork.hpp"
#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "validation/suite.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/child_process.hpp"
#include "multibody/host/worker_process.hpp"
#include "study/measure.hpp"
#include "validation/suite_file.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"
#include "tests/temp_files.hpp"

namespace {

using namespace vssw;
using vssw::testing::engine_available;
using multibody::EngineFailure;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }


// Bytes a text or rounded copy would change: a NUL, -0, a subnormal, a NaN with a payload, 0.1 + 0.2.
std::string awkward_bytes() {
    std::string out("a\0b", 3);
    double payload_nan;
    const std::uint64_t bits = 0x7ff8000000001234ULL;
    std::memcpy(&payload_nan, &bits, sizeof bits);
    for (const double x : {-0.0, std::numeric_limits<double>::denorm_min(), payload_nan, 0.1 + 0.2})
        out.append(reinterpret_cast<const char*>(&x), sizeof x);
    return out;
}

// What a worker's work does: append the awkward bytes, throw each kind of error, or die.
enum class How { returns, engine_failure, input_error, other_error, aborts, exits };

std::string run_in_worker(How how) {
    return std::string(multibody::run_in_worker_process(
        [how](std::string& out) {
            switch (how) {
                case How::returns:
                    out += awkward_bytes();
                    return;
                case How::engine_failure:
                    throw EngineFailure("scripted: NaN at t = 1.5 s");
                case How::input_error:
                    throw InputError("scripted setting x must be > 0, got -1");
                case How::other_error:
                    throw std::logic_error("scripted: a bug");
                case How::aborts:
                    std::abort();
                case How::exits:
                    ::_exit(3);
            }
        },
        "scripted"));
}

// The message the caller gets for an error of type E thrown by run_in_worker(how) (empty: none, or another type).
template <class E>
std::string message_of(How how) {
    try {
        (void)run_in_worker(how);
    } catch (const E& e) {
        return e.what();
    } catch (...) {
    }
    return "";
}

// A forked engine run spends its CPU in its child, which the parent thread's CPU clock does not see: the thread that
// reaps the child counts its CPU (reaped_children_cpu_seconds, which a suite's task adds to its thread's CPU), and
// another thread does not.
TEST(ChildFork, TheThreadThatReapsAChildCountsItsCpu) {
    constexpr double kChildCpuS = 0.2;          // what the child spends: many of the kernel's accounting ticks
    constexpr double kAccountingSlackS = 0.02;  // CPU time is counted in scheduler ticks (4 ms at 250 Hz): a few lost
    const double before = vssw::reaped_children_cpu_seconds();
    const pid_t pid = vssw::fork_child();
    ASSERT_GE(pid, 0);
    if (pid == 0) {  // the child's CPU clock starts at 0 (fork)
        timespec now{};
        do {
            clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
        } while (static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec) < kChildCpuS);
        _exit(0);
    }
    ASSERT_EQ(vssw::wait_child(pid), 0);
    EXPECT_GE(vssw::reaped_children_cpu_seconds() - before, kChildCpuS - kAccountingSlackS);
    double other_thread = -1.0;
    std::thread([&] { other_thread = vssw::reaped_children_cpu_seconds(); }).join();
    EXPECT_EQ(other_thread, 0.0);
}

TEST(WorkerProcess, ReturnsTheWorksBytesExactly) { EXPECT_EQ(run_in_worker(How::returns), awkward_bytes()); }

TEST(WorkerProcess, ErrorsComeBackWithTheirTypeAndMessage) {
    EXPECT_EQ(message_of<EngineFailure>(How::engine_failure), "scripted: NaN at t = 1.5 s");
    EXPECT_EQ(message_of<InputError>(How::input_error), "scripted setting x must be > 0, got -1");
    const std::string other = message_of<std::runtime_error>(How::other_error);
    EXPECT_EQ(other, "scripted: a bug");
    EXPECT_EQ(message_of<EngineFailure>(How::other_error), "") << "a bug is not the engine failing";
}

TEST(WorkerProcess, AChildThatDiesIsAnEngineFailureSayingHow) {
    const std::string aborted = message_of<EngineFailure>(How::aborts);
    EXPECT_NE(aborted.find("scripted"), std::string::npos) << aborted;
    EXPECT_NE(aborted.find("signal 6"), std::string::npos) << aborted;
    const std::string exited = message_of<EngineFailure>(How::exits);
    EXPECT_NE(exited.find("exited with code 3"), std::string::npos) << exited;
}

// A handler that only sets a flag, as Python's SIGINT handler does.
volatile sig_atomic_t g_flagged = 0;
void set_flag(int) { g_flagged = 1; }

// A worker takes the default action of a signal its parent handles: SIGINT ends it (and is an interruption, not a
// failed run), whatever handler the parent has. With the parent's flag-only handler the work would go on and return.
TEST(WorkerProcess, AWorkerTakesTheDefaultActionOfTheSignalsItsParentHandles) {
    struct sigaction flag_only {}, previous {};
    flag_only.sa_handler = set_flag;
    sigemptyset(&flag_only.sa_mask);
    ASSERT_EQ(::sigaction(SIGINT, &flag_only, &previous), 0);
    try {
        (void)multibody::run_in_worker_process([](std::string&) { ::raise(SIGINT); }, "scripted");
        ADD_FAILURE() << "the worker went on after SIGINT";
    } catch (const multibody::RunInterrupted& e) {
        EXPECT_NE(std::string(e.what()).find("scripted: the run was interrupted by signal 2"), std::string::npos)
            << e.what();
    }
    ::sigaction(SIGINT, &previous, nullptr);
    EXPECT_EQ(g_flagged, 0) << "the parent's handler ran";
}

// How the state letter of a process reads in /proc ('Z': ended, not reaped yet); ' ' when it is gone.
char process_state(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    const std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const std::size_t close = text.rfind(')');
    return close == std::string::npos || close + 2 >= text.size() ? ' ' : text[close + 2];
}
bool ended(pid_t pid) { return process_state(pid) == ' ' || process_state(pid) == 'Z'; }

// Polled, not timed: a generous bound for a loaded machine, reached only when the promise is broken.
constexpr int kPolls = 3000, kPollMicroseconds = 10000;  // 30 s

// Work for a worker that tells its pid in `file` (a worker keeps no descriptor of its parent's but its answer pipe)
// and then waits for ever.
std::function<void(std::string&)> tell_pid_and_wait(const std::string& file) {
    return [file](std::string&) {
        std::ofstream(file + ".part") << ::getpid();
        std::rename((file + ".part").c_str(), file.c_str());
        for (;;) ::pause();
    };
}
// The pid the worker told in `file`; 0 when it never did.
pid_t told_pid(const std::string& file) {
    for (int i = 0; i < kPolls; ++i, ::usleep(kPollMicroseconds)) {
        pid_t pid = 0;
        if (std::ifstream(file) >> pid) return pid;
    }
    return 0;
}

// A parent killed by SIGKILL (it cannot clean up) leaves no worker running: the worker dies with it.
TEST(WorkerProcess, AWorkerDiesWithItsParentEvenWhenTheParentIsKilled) {
    const vssw::testing::TempDir dir;
    const std::string file = (dir / "worker.pid").string();
    const pid_t parent = ::fork();
    ASSERT_GE(parent, 0);
    if (parent == 0) {  // the worker's parent
        try {
            (void)multibody::run_in_worker_process(tell_pid_and_wait(file), "scripted");
        } catch (...) {
        }
        ::_exit(0);
    }
    const pid_t worker = told_pid(file);
    ::kill(parent, SIGKILL);
    ::waitpid(parent, nullptr, 0);
    ASSERT_NE(worker, 0) << "the worker never started";
    for (int i = 0; i < kPolls && !ended(worker); ++i) ::usleep(kPollMicroseconds);
    const bool gone = ended(worker);
    if (!gone) ::kill(worker, SIGKILL);
    EXPECT_TRUE(gone) << "the worker " << worker << " outlived its parent";
}

// While interruption is on (the Python module's Ctrl-C), a worker being waited for is stopped and no new one starts:
// the caller gets RunInterrupted, not a failed run.
TEST(WorkerProcess, InterruptionStopsTheRunningWorkerAndStartsNoOther) {
    const vssw::testing::TempDir dir;
    const std::string file = (dir / "worker.pid").string();
    bool interrupted = false;
    std::thread waiter([&] {
        try {
            (void)multibody::run_in_worker_process(tell_pid_and_wait(file), "scripted");
        } catch (const multibody::RunInterrupted&) {
            interrupted = true;
        }
    });
    const pid_t worker = told_pid(file);
    multibody::interrupt_children(true);
    waiter.join();
    EXPECT_NE(worker, 0);
    EXPECT_TRUE(interrupted);
    EXPECT_TRUE(ended(worker));
    EXPECT_THROW(run_in_worker(How::returns), multibody::RunInterrupted);
    multibody::interrupt_children(false);
    EXPECT_EQ(run_in_worker(How::returns), awkward_bytes());
}

// theta1 of every sample as its raw bytes: what the comparison below needs, bit for bit.
std::string theta1_bytes(const multibody::Trajectory& t) {
    std::string out;
    for (const multibody::TrajectorySample& x : t.samples)
        out.append(reinterpret_cast<const char*>(&x.theta1), sizeof x.theta1);
    return out;
}

TEST(WorkerProcess, OdeGivesTheSameRunInAChild) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const auto ode = multibody::make_engine_in_process("ode");
    ASSERT_FALSE(ode->runs_concurrently());
    const multibody::WallScene wall = multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7));
    multibody::Excitation ex;
    ex.theta0 = 0.5 * wall.alpha();
    ex.t_end = 2.0;
    auto in_child = [&](const multibody::EngineSettings& s) {
        return std::string(multibody::run_in_worker_process(
            [&](std::string& out) { out += theta1_bytes(ode->simulate(wall, ex, s)); }, "ode"));
    };
    for (const double quickstep : {0.0, 1.0}) {  // quickstep draws on ODE's random generator, seeded per run
        multibody::EngineSettings s = ode->default_settings();
        s.knobs["quickstep"] = quickstep;
        const multibody::Trajectory here = ode->simulate(wall, ex, s);
        ASSERT_GT(here.samples.size(), 100u);
        EXPECT_EQ(theta1_bytes(here), in_child(s)) << "quickstep " << quickstep;
    }
    multibody::EngineSettings bad = ode->default_settings();
    bad.knobs["no_such_knob"] = 1.0;
    EXPECT_THROW((void)in_child(bad), InputError);
}

// A study of ODE and the analytic model: results.csv is the same file on one thread and on two (each ODE run in a
// child of its own either way, side by side on two).
TEST(WorkerProcess, AnOdeStudysResultsAreTheSameFileOnOneAndTwoThreads) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const vssw::testing::TempDir dir;
    const study::Grid grid(vssw::testing::study_of(
        dir, "metrics = [\"threshold_g\", \"period\", \"restitution\"]\nengines = [\"analytic\", \"ode\"]\n"
             "[wall]\nheight = 4.88\nthickness = [0.356, 0.2]\nhinge = 0.5\n"
             "[excitation]\nkind = \"free\"\ntheta0 = [0.2, 0.5]\n"));
    (void)vssw::testing::run_into(grid, dir / "one", 1);
    (void)vssw::testing::run_into(grid, dir / "two", 2);
    const std::string one = vssw::testing::read_file(dir / "one" / study::kResultsCsv);
    EXPECT_NE(one.find(",ode,"), std::string::npos) << "ODE's rows are in it";
    EXPECT_EQ(one, vssw::testing::read_file(dir / "two" / study::kResultsCsv));
}

// The validation suite runs ODE in its own process, its tasks taking turns on two threads (no worker processes there:
// docs/contributing/engines.md, "ODE"): its rows, failures and traces are those of one thread.
TEST(WorkerProcess, OdesSuiteRowsAreTheSameOnOneAndTwoThreads) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const validation::Suite s = validation::select_cases(validation::read_suite("default", VSSW_DATA_DIR), {"fig6-pw", "fig6-vssw/r0.5"});
    validation::RunOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const validation::SuiteResults a = validation::run_suite(s, {"ode"}, one);
    const validation::SuiteResults b = validation::run_suite(s, {"ode"}, two);
    ASSERT_EQ(b.threads, 2);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    bool has_ode = false;
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        const validation::MetricRow &x = a.rows[i], &y = b.rows[i];
        has_ode = has_ode || x.engine == "ode";
        EXPECT_EQ(x.case_id + x.engine + x.metric, y.case_id + y.engine + y.metric);
        EXPECT_TRUE(same_bits(x.engine_value, y.engine_value)) << x.case_id << " " << x.engine << " " << x.metric;
    }
    EXPECT_TRUE(has_ode);
    EXPECT_EQ(a.failures.size(), b.failures.size());
    ASSERT_EQ(a.traces.size(), b.traces.size());
    for (std::size_t i = 0; i < a.traces.size(); ++i) EXPECT_EQ(a.traces[i].theta1_over_alpha1, b.traces[i].theta1_over_alpha1) << i;
}

}  // namespace

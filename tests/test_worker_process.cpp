// Worker processes (multibody/worker_process.hpp): work run in a child gives the caller the very bytes it would have
// made in its own process (ODE's runs and a study's results.csv are identical with and without them), and each way a
// child can fail comes back as the error it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unistd.h>

#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "compare/suite.hpp"
#include "multibody/engine.hpp"
#include "multibody/worker_process.hpp"
#include "study/measure.hpp"
#include "study/suite_file.hpp"
#include "study/worker_task.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"

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

// An engine that says how it may run, for the rule below (never simulated).
class DeclaredEngine final : public multibody::Engine {
public:
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    explicit DeclaredEngine(bool concurrent) : concurrent_(concurrent) {}
    std::string name() const override { return "declared"; }
    std::string version() const override { return "1"; }
    multibody::EngineSettings default_settings() const override { return {}; }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    multibody::Trajectory simulate(const multibody::WallScene&, const multibody::Excitation&,
                                   const multibody::EngineSettings&) const override {
        throw EngineFailure("not simulated here");
    }
    void check_settings(const multibody::EngineSettings&) const override {}
    bool runs_concurrently() const override { return concurrent_; }
    bool runs_in_worker_process() const override { return true; }

private:
    bool concurrent_;
};

TEST(WorkerProcess, OnlyANonReentrantEngineOnSeveralThreadsIsSentToWorkers) {
    ::unsetenv("VSSW_WORKER_PROCESSES");
    const DeclaredEngine exclusive(false), concurrent(true);
    EXPECT_FALSE(multibody::runs_in_worker_processes(exclusive, 1)) << "one thread: nothing forks";
    EXPECT_FALSE(multibody::runs_in_worker_processes(concurrent, 2)) << "it runs on threads already";
    EXPECT_TRUE(multibody::runs_in_worker_processes(exclusive, 2));
    ::setenv("VSSW_WORKER_PROCESSES", "0", 1);
    EXPECT_FALSE(multibody::runs_in_worker_processes(exclusive, 2)) << "turned off";
    ::setenv("VSSW_WORKER_PROCESSES", "yes", 1);
    try {
        (void)multibody::runs_in_worker_processes(exclusive, 2);
        ADD_FAILURE() << "'yes' accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'yes'"), std::string::npos) << e.what();
    }
    ::unsetenv("VSSW_WORKER_PROCESSES");
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
    const auto ode = multibody::make_engine("ode");
    ASSERT_FALSE(ode->runs_concurrently());
    ASSERT_TRUE(ode->runs_in_worker_process());
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

// A study of ODE and the analytic model: results.csv is the same file on one thread (ODE in this process), on two
// (ODE in worker processes) and on two with worker processes off (ODE's runs taking turns).
TEST(WorkerProcess, AnOdeStudysResultsAreTheSameFileOnOneAndTwoThreads) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const vssw::testing::TempDir dir;
    const study::Grid grid(vssw::testing::study_of(
        dir, "metrics = [\"threshold_g\", \"period\", \"restitution\"]\nengines = [\"analytic\", \"ode\"]\n"
             "[wall]\nheight = 4.88\nthickness = [0.356, 0.2]\nhinge = 0.5\n"
             "[excitation]\nkind = \"free\"\ntheta0 = [0.2, 0.5]\n"));
    ::unsetenv("VSSW_WORKER_PROCESSES");
    (void)vssw::testing::run_into(grid, dir / "one", 1);
    (void)vssw::testing::run_into(grid, dir / "two", 2);
    ::setenv("VSSW_WORKER_PROCESSES", "0", 1);
    (void)vssw::testing::run_into(grid, dir / "off", 2);
    // The two-thread run reads the switch (so "two" above ran ODE in workers): a bad value is refused there.
    ::setenv("VSSW_WORKER_PROCESSES", "yes", 1);
    EXPECT_THROW((void)vssw::testing::run_into(grid, dir / "bad", 2), InputError);
    ::unsetenv("VSSW_WORKER_PROCESSES");
    const std::string one = vssw::testing::read_file(dir / "one" / study::kResultsCsv);
    EXPECT_NE(one.find(",ode,"), std::string::npos) << "ODE's rows are in it";
    EXPECT_EQ(one, vssw::testing::read_file(dir / "two" / study::kResultsCsv));
    EXPECT_EQ(one, vssw::testing::read_file(dir / "off" / study::kResultsCsv));
}

// A study task whose worker dies (a crash inside an engine's library) becomes its rows, failed with the reason; a
// task that runs gives its own text. (The runner's on_death: study::failed_task, below.)
TEST(WorkerProcess, AStudyTaskWhoseWorkerDiesGivesTheTextOfItsDeath) {
    const auto on_death = [](const std::string& why) { return "failed rows: " + why; };
    EXPECT_EQ(study::run_task_in_worker([] { return std::string("rows"); }, "test", on_death), "rows");
    const std::string died = study::run_task_in_worker(
        []() -> std::string {
            std::abort();
        },
        "scripted engine", on_death);
    EXPECT_EQ(died.rfind("failed rows: scripted engine", 0), 0u) << died;
    EXPECT_NE(died.find("signal 6"), std::string::npos) << died;
    // An error the task throws is not a death: it comes back as itself (measure() keeps a run's failures as rows).
    EXPECT_THROW((void)study::run_task_in_worker([]() -> std::string { throw InputError("bad case"); }, "test",
                                                 on_death),
                 InputError);
}

// The rows a dead task leaves are the rows the task would have given: the same metrics, each failed with the reason.
TEST(WorkerProcess, AFailedTaskHasTheRowsOfTheTaskThatRuns) {
    const vssw::testing::TempDir dir;
    // The closed form is the analytic model's own metric: an engine's run (ODE, when built) has no row for it.
    const std::string engines = engine_available("ode") ? "[\"analytic\", \"ode\"]" : "[\"analytic\"]";
    const study::Grid grid(vssw::testing::study_of(
        dir, "metrics = [\"threshold_g\", \"period\", \"restitution\", \"threshold_closed_form_g\", "
             "\"peak_rotation\"]\nengines = " + engines + "\n[wall]\nheight = 4.88\nthickness = 0.356\nhinge = 0.5\n"
             "[excitation]\nkind = \"free\"\ntheta0 = 0.3\n"));
    const study::CaseSpec c = grid.make_case(grid.shard_case_ids(1, 1).front());
    for (std::size_t run = 0; run < grid.runs().size(); ++run) {
        const auto engine = multibody::make_engine(grid.runs()[run].engine);
        const std::vector<study::Measurement> measured = study::measure(grid, c, run, *engine);
        const std::vector<study::Measurement> failed = study::failed_task(grid, c, run, false, "died\nby signal 11");
        ASSERT_EQ(failed.size(), measured.size());
        ASSERT_FALSE(failed.empty());
        for (std::size_t i = 0; i < failed.size(); ++i) {
            EXPECT_EQ(failed[i].metric, measured[i].metric);
            EXPECT_EQ(failed[i].status, "failed: died by signal 11");  // one line, as every failed row
            EXPECT_TRUE(std::isnan(failed[i].value));
        }
        const std::vector<study::Measurement> threshold = study::failed_task(grid, c, run, true, "died");
        ASSERT_EQ(threshold.size(), 1u);
        EXPECT_EQ(grid.spec().metrics[threshold[0].metric], "threshold_g");
    }
}

// The validation suite runs ODE in its own process, its tasks taking turns on two threads (no worker processes there:
// docs/engines.md, "ODE"): its rows, failures and traces are those of one thread.
TEST(WorkerProcess, OdesSuiteRowsAreTheSameOnOneAndTwoThreads) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    ::unsetenv("VSSW_WORKER_PROCESSES");
    const compare::Suite s = compare::select_cases(study::read_suite("default", VSSW_DATA_DIR), {"fig6-pw", "fig6-vssw/r0.5"});
    compare::RunOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const compare::SuiteResults a = compare::run_suite(s, {"ode"}, one);
    const compare::SuiteResults b = compare::run_suite(s, {"ode"}, two);
    ASSERT_EQ(b.threads, 2);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    bool has_ode = false;
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        const compare::MetricRow &x = a.rows[i], &y = b.rows[i];
        has_ode = has_ode || x.engine == "ode";
        EXPECT_EQ(x.case_id + x.engine + x.metric, y.case_id + y.engine + y.metric);
        EXPECT_TRUE(same_bits(x.engine_value, y.engine_value)) << x.case_id << " " << x.engine << " " << x.metric;
    }
    EXPECT_TRUE(has_ode);
    EXPECT_EQ(a.failures.size(), b.failures.size());
    ASSERT_EQ(a.traces.size(), b.traces.size());
    for (std::size_t i = 0; i < a.traces.size(); ++i) EXPECT_EQ(a.traces[i].theta1_over_alpha, b.traces[i].theta1_over_alpha) << i;
}

}  // namespace

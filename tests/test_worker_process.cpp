// Worker processes (multibody/worker_process.hpp): a run in a child gives the caller the very numbers of the same run
// in its own process (the trajectory's bytes round trip exactly; ODE's runs and a study's results.csv are identical
// with and without them), and each way a child can fail comes back as the error it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "compare/suite.hpp"
#include "compare/task_pool.hpp"
#include "multibody/engine.hpp"
#include "multibody/trajectory_bytes.hpp"
#include "multibody/worker_process.hpp"
#include "study/suite_file.hpp"
#include "tests/study_fixtures.hpp"

namespace {

using namespace vssw;
using multibody::EngineFailure;
using multibody::Trajectory;
using multibody::TrajectorySample;

bool built(const std::string& name) {
    const auto names = multibody::available_engines();
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same(const Trajectory& a, const Trajectory& b) {
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
        const TrajectorySample &x = a.samples[i], &y = b.samples[i];
        for (const auto f : {&TrajectorySample::t, &TrajectorySample::theta1, &TrajectorySample::theta1_dot,
                             &TrajectorySample::theta2, &TrajectorySample::top_dy, &TrajectorySample::kinetic,
                             &TrajectorySample::potential})
            ASSERT_TRUE(same_bits(x.*f, y.*f)) << "sample " << i << ": " << x.*f << " against " << y.*f;
        ASSERT_EQ(x.contacts, y.contacts) << "sample " << i;
    }
    EXPECT_EQ(a.overturned, b.overturned);
    EXPECT_EQ(a.at_rest_at_end, b.at_rest_at_end);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(a.warnings, b.warnings);
    ASSERT_EQ(a.located.has_value(), b.located.has_value());
    if (a.located) {
        const multibody::LocatedEvents &x = *a.located, &y = *b.located;
        EXPECT_TRUE(same_bits(x.max_abs_theta1, y.max_abs_theta1));
        EXPECT_TRUE(same_bits(x.t_max_abs_theta1, y.t_max_abs_theta1));
        ASSERT_EQ(x.t_overturn.has_value(), y.t_overturn.has_value());
        if (x.t_overturn) {
            EXPECT_TRUE(same_bits(*x.t_overturn, *y.t_overturn));
        }
        EXPECT_TRUE(same_bits(x.energy_balance_error, y.energy_balance_error));
        EXPECT_EQ(x.supports_computed, y.supports_computed);
        ASSERT_EQ(x.roller_tension_at.has_value(), y.roller_tension_at.has_value());
        if (x.roller_tension_at) {
            EXPECT_TRUE(same_bits(*x.roller_tension_at, *y.roller_tension_at));
        }
    }
}

// Values a text or rounded copy would change: -0, a subnormal, a NaN with a payload, infinities, 0.1 + 0.2.
Trajectory awkward_trajectory() {
    Trajectory t;
    double payload_nan;
    const std::uint64_t bits = 0x7ff8000000001234ULL;
    std::memcpy(&payload_nan, &bits, sizeof bits);
    t.samples.push_back({0.0, -0.0, std::numeric_limits<double>::denorm_min(), payload_nan,
                         std::numeric_limits<double>::infinity(), 0.1 + 0.2, -1e308, 3});
    t.samples.push_back({1e-4, 1.0 / 3.0, -std::numeric_limits<double>::infinity(), 2.0, -7.5e-9, 0.0, 1.0, 0});
    t.overturned = true;
    t.at_rest_at_end = false;
    t.steps = 1234567890123L;
    t.warnings = {"the roller pulls at t = 1.2 s", "", std::string("a\0b", 3)};
    multibody::LocatedEvents e;
    e.max_abs_theta1 = 0.123456789012345678;
    e.t_max_abs_theta1 = 0.7;
    e.t_overturn = 2.5;
    e.energy_balance_error = 1e-15;
    e.supports_computed = true;  // roller_tension_at left unset: an optional both ways
    t.located = e;
    return t;
}

TEST(TrajectoryBytes, ARoundTripKeepsEveryBit) {
    const Trajectory t = awkward_trajectory();
    expect_same(t, multibody::trajectory_from_bytes(multibody::to_bytes(t)));
    Trajectory plain;  // no samples, no located events
    plain.steps = 3;
    expect_same(plain, multibody::trajectory_from_bytes(multibody::to_bytes(plain)));
}

TEST(TrajectoryBytes, ShortOrOverlongBytesAreRefused) {
    const std::string bytes = multibody::to_bytes(awkward_trajectory());
    for (const std::size_t cut : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1})
        EXPECT_THROW((void)multibody::trajectory_from_bytes(std::string_view(bytes).substr(0, cut)),
                     std::runtime_error)
            << "cut at " << cut;
    EXPECT_THROW((void)multibody::trajectory_from_bytes(bytes + "x"), std::runtime_error);
}

// A test engine whose run does what `how` says: return the awkward trajectory, throw each kind of error, or die.
enum class How { returns, engine_failure, input_error, other_error, aborts, exits };

class ScriptedEngine final : public multibody::Engine {
public:
    explicit ScriptedEngine(How how, bool concurrent = false) : how_(how), concurrent_(concurrent) {}
    std::string name() const override { return "scripted"; }
    std::string version() const override { return "1"; }
    multibody::EngineSettings default_settings() const override { return {}; }
    Trajectory simulate(const multibody::WallScene&, const multibody::Excitation&,
                        const multibody::EngineSettings&) const override {
        switch (how_) {
            case How::returns:
                return awkward_trajectory();
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
        return {};
    }
    void check_settings(const multibody::EngineSettings&) const override {}
    bool runs_concurrently() const override { return concurrent_; }
    bool runs_in_worker_process() const override { return true; }

private:
    How how_;
    bool concurrent_;
};

Trajectory run_in_worker(How how) {
    const ScriptedEngine inner(how);
    const multibody::WorkerProcessEngine worker(inner);
    return worker.simulate(multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7)), {}, {});
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

TEST(WorkerProcess, ReturnsTheRunsTrajectoryExactly) { expect_same(awkward_trajectory(), run_in_worker(How::returns)); }

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

TEST(WorkerProcess, OnlyANonReentrantEngineOnSeveralThreadsIsWrapped) {
    ::unsetenv("VSSW_WORKER_PROCESSES");
    const ScriptedEngine exclusive(How::returns), concurrent(How::returns, /*concurrent=*/true);
    EXPECT_EQ(multibody::worker_process_engine_for(exclusive, 1), nullptr) << "one thread: nothing forks";
    EXPECT_EQ(multibody::worker_process_engine_for(concurrent, 2), nullptr) << "it runs on threads already";
    const auto w = multibody::worker_process_engine_for(exclusive, 2);
    ASSERT_NE(w, nullptr);
    EXPECT_TRUE(w->runs_concurrently());
    EXPECT_EQ(w->name(), "scripted");
    ::setenv("VSSW_WORKER_PROCESSES", "0", 1);
    EXPECT_EQ(multibody::worker_process_engine_for(exclusive, 2), nullptr) << "turned off";
    ::setenv("VSSW_WORKER_PROCESSES", "yes", 1);
    try {
        (void)multibody::worker_process_engine_for(exclusive, 2);
        ADD_FAILURE() << "'yes' accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'yes'"), std::string::npos) << e.what();
    }
    ::unsetenv("VSSW_WORKER_PROCESSES");
}

TEST(WorkerProcess, OdeGivesTheSameRunInAChild) {
    if (!built("ode")) GTEST_SKIP() << "ODE is not built";
    const auto ode = multibody::make_engine("ode");
    ASSERT_FALSE(ode->runs_concurrently());
    ASSERT_TRUE(ode->runs_in_worker_process());
    const multibody::WorkerProcessEngine worker(*ode);
    const multibody::WallScene wall = multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7));
    multibody::Excitation ex;
    ex.theta0 = 0.5 * wall.alpha();
    ex.t_end = 2.0;
    for (const double quickstep : {0.0, 1.0}) {  // quickstep draws on ODE's random generator, seeded per run
        multibody::EngineSettings s = ode->default_settings();
        s.knobs["quickstep"] = quickstep;
        const Trajectory here = ode->simulate(wall, ex, s);
        ASSERT_GT(here.samples.size(), 100u);
        expect_same(here, worker.simulate(wall, ex, s));
    }
    multibody::EngineSettings bad = ode->default_settings();
    bad.knobs["no_such_knob"] = 1.0;
    EXPECT_THROW((void)worker.simulate(wall, ex, bad), InputError);
}

// A study of ODE and the analytic model: results.csv is the same file on one thread (ODE in this process), on two
// (ODE in worker processes) and on two with worker processes off (ODE's runs taking turns).
TEST(WorkerProcess, AnOdeStudysResultsAreTheSameFileOnOneAndTwoThreads) {
    if (!built("ode")) GTEST_SKIP() << "ODE is not built";
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
    ::unsetenv("VSSW_WORKER_PROCESSES");
    const std::string one = vssw::testing::read_file(dir / "one" / study::kResultsCsv);
    EXPECT_NE(one.find(",ode,"), std::string::npos) << "ODE's rows are in it";
    EXPECT_EQ(one, vssw::testing::read_file(dir / "two" / study::kResultsCsv));
    EXPECT_EQ(one, vssw::testing::read_file(dir / "off" / study::kResultsCsv));
}

// The validation suite runs ODE's simulations in worker processes on two threads (a fork per run): its rows, failures and
// traces are those of one thread, where ODE runs in the process.
TEST(WorkerProcess, OdesSuiteRowsAreTheSameOnOneAndTwoThreads) {
    if (!built("ode")) GTEST_SKIP() << "ODE is not built";
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

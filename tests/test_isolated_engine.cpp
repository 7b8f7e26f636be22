// Engine runs in child processes of their own (multibody/host/isolated_engine.hpp), with a CPU budget
// (multibody/host/run_budget.hpp); knobs refused outside their documented ranges (SettingDescription::lo/hi); a step that
// cannot resolve the wall or the ground motion refused (multibody/kit/step_resolution.hpp).
// docs/contributing/engines.md "Isolation": an ODE setting aborted the process (and a Python interpreter), a Simbody
// setting hung forever, and a step of 1000 s gave "ok, peak 0".
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/wall.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/isolated_engine.hpp"
#include "multibody/host/run_budget.hpp"
#include "multibody/kit/step_resolution.hpp"
#include "study/grid.hpp"
#include "study/measure.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"
#include "tests/temp_files.hpp"

namespace {

using namespace vssw;
using multibody::EngineFailure;
using multibody::Excitation;
using multibody::Trajectory;
using multibody::WallScene;
using vssw::testing::engine_available;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

WallScene fig6() { return WallScene::of(make_vssw(4.0, 0.4, 0.7)); }

Excitation free_vibration(double t_end = 0.6) {
    Excitation ex;
    ex.theta0 = 0.5 * fig6().alpha();
    ex.t_end = t_end;
    ex.stop_at_rest = false;
    return ex;
}

// What a scripted engine does in simulate().
enum class How { returns, aborts, segfaults, spins, throws_failure, throws_input };

class ScriptedEngine final : public multibody::Engine {
public:
    explicit ScriptedEngine(How how) : how_(how) {}
    std::string name() const override { return "scripted"; }
    std::string version() const override { return "1"; }
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    multibody::EngineSettings default_settings() const override { return {}; }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    void check_settings(const multibody::EngineSettings&) const override {}
    Trajectory simulate(const WallScene&, const Excitation&, const multibody::EngineSettings&) const override {
        switch (how_) {
            case How::returns:
                return awkward();
            case How::aborts:
                std::abort();
            case How::segfaults:
                ::raise(SIGSEGV);
                break;
            case How::spins:
                for (volatile unsigned long i = 0;; i = i + 1) {
                }
            case How::throws_failure:
                throw EngineFailure("scripted: NaN at t = 1.5 s");
            case How::throws_input:
                throw InputError("scripted setting x must be > 0, got -1");
        }
        return {};
    }
    // A trajectory whose bytes a text or rounded copy would change: -0, a subnormal, a NaN, 0.1 + 0.2; every
    // optional field set.
    static Trajectory awkward() {
        Trajectory t;
        t.samples.push_back({0.1 + 0.2, -0.0, std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::quiet_NaN(), 1e-300, 2.5, -3.5, 4});
        t.samples.push_back({1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 0});
        t.overturned = true;
        t.steps = 123456789;
        t.warnings = {"first warning", std::string("with a NUL \0 inside", 20)};
        multibody::LocatedEvents e;
        e.max_abs_theta1 = 0.25;
        e.t_overturn = 1.75;
        e.roller_tension_at = 0.5;
        e.supports_computed = true;
        t.located = e;
        return t;
    }

private:
    How how_;
};

std::string failure_of(How how) {
    const auto engine = multibody::isolated(std::make_unique<ScriptedEngine>(how));
    try {
        (void)engine->simulate(fig6(), free_vibration(), {});
    } catch (const EngineFailure& e) {
        return e.what();
    }
    return "no EngineFailure";
}

TEST(IsolatedEngine, ATrajectoryComesBackBitForBit) {
    const Trajectory want = ScriptedEngine::awkward();
    const auto engine = multibody::isolated(std::make_unique<ScriptedEngine>(How::returns));
    const Trajectory got = engine->simulate(fig6(), free_vibration(), {});
    ASSERT_EQ(got.samples.size(), want.samples.size());
    for (std::size_t i = 0; i < want.samples.size(); ++i) {
        const auto &a = got.samples[i], &b = want.samples[i];
        for (const auto& [x, y] : {std::pair{a.t, b.t}, {a.theta1, b.theta1}, {a.theta1_dot, b.theta1_dot},
                                   {a.theta2, b.theta2}, {a.top_dy, b.top_dy}, {a.kinetic, b.kinetic},
                                   {a.potential, b.potential}})
            EXPECT_TRUE(same_bits(x, y)) << i;
        EXPECT_EQ(a.contacts, b.contacts);
    }
    EXPECT_EQ(got.overturned, want.overturned);
    EXPECT_EQ(got.at_rest_at_end, want.at_rest_at_end);
    EXPECT_EQ(got.steps, want.steps);
    EXPECT_EQ(got.warnings, want.warnings);
    ASSERT_TRUE(got.located.has_value());
    EXPECT_EQ(got.located->max_abs_theta1, 0.25);
    EXPECT_EQ(got.located->t_overturn, std::optional<double>(1.75));
    EXPECT_EQ(got.located->roller_tension_at, std::optional<double>(0.5));
    EXPECT_TRUE(got.located->supports_computed);
}

TEST(IsolatedEngine, ALibraryThatAbortsOrCrashesFailsTheRunNotTheProcess) {
    const std::string aborted = failure_of(How::aborts);
    EXPECT_NE(aborted.find("scripted"), std::string::npos) << aborted;
    EXPECT_NE(aborted.find("signal 6"), std::string::npos) << aborted;
    const std::string crashed = failure_of(How::segfaults);
    EXPECT_NE(crashed.find("signal 11"), std::string::npos) << crashed;
}

// An engine library that crashes mid-run (isolated: a child of its own) gives the study's rows for that run, each
// failed naming the signal, where the run would have given its values; the study goes on.
TEST(IsolatedEngine, ACrashedRunGivesAStudyFailedRowsNamingTheSignal) {
    const vssw::testing::TempDir dir;
    const study::Grid grid(vssw::testing::study_of(
        dir, "metrics = [\"period\", \"restitution\", \"peak_rotation\"]\nengines = [\"analytic\"]\n"
             "[wall]\nheight = 4.88\nthickness = 0.356\nhinge = 0.5\n[excitation]\nkind = \"free\"\ntheta0 = 0.3\n"));
    const study::CaseSpec c = grid.make_case(grid.shard_case_ids(1, 1).front());
    const auto crashing = multibody::isolated(std::make_unique<ScriptedEngine>(How::aborts));
    const std::vector<study::Measurement> rows = study::measure(grid, c, 0, *crashing);
    ASSERT_FALSE(rows.empty());
    for (const study::Measurement& m : rows) {
        EXPECT_TRUE(std::isnan(m.value));
        EXPECT_EQ(m.status.rfind("failed: ", 0), 0u) << m.status;
        EXPECT_NE(m.status.find("signal 6"), std::string::npos) << m.status;
    }
}

TEST(IsolatedEngine, ErrorsComeBackAsTheirOwnType) {
    EXPECT_EQ(failure_of(How::throws_failure), "scripted: NaN at t = 1.5 s");
    const auto engine = multibody::isolated(std::make_unique<ScriptedEngine>(How::throws_input));
    EXPECT_THROW((void)engine->simulate(fig6(), free_vibration(), {}), InputError);
}

TEST(IsolatedEngine, ARunThatNeverEndsFailsAtItsBudgetNamingIt) {
    // The smallest budget a user may give (the kernel counts whole seconds); the run spins on the CPU.
    multibody::RunBudget::set(multibody::RunBudget::kMinSeconds);
    const std::string why = failure_of(How::spins);
    multibody::RunBudget::set(std::nullopt);
    // "passed its budget": ended by the kernel's CPU limit; the wall-clock safety net says "stopped after".
    EXPECT_NE(why.find("passed its budget of 1 s of CPU time (--run-budget)"), std::string::npos) << why;
}

TEST(RunBudget, TheDefaultGrowsWithTheStepsAndAGivenOneIsChecked) {
    multibody::RunBudget::set(std::nullopt);
    // 30 s + 1 ms for each of a 2 s run's 2,000 steps at 1 ms (docs/guide/program.md's figure); twice the steps, 2 s
    // more.
    EXPECT_DOUBLE_EQ(multibody::RunBudget::seconds(2.0, 1e-3), 32.0);
    EXPECT_DOUBLE_EQ(multibody::RunBudget::seconds(4.0, 1e-3), 34.0);
    EXPECT_NE(multibody::RunBudget::describe(2.0, 1e-3).find("--run-budget"), std::string::npos);
    for (const double bad : {0.0, 0.5, -1.0, 2e6, std::numeric_limits<double>::infinity()})
        EXPECT_THROW(multibody::RunBudget::set(bad), InputError) << bad;
    multibody::RunBudget::set(60.0);
    EXPECT_EQ(multibody::RunBudget::seconds(2.0, 1e-3), 60.0);
    multibody::RunBudget::set(std::nullopt);
}

// Each engine library's run through make_engine happens in another process: the ground motion, called by the engine,
// writes its process id into a file.
TEST(IsolatedEngine, EveryEngineLibraryRunsInAChildAndTheAnalyticModelHere) {
    const vssw::testing::TempDir dir;
    for (const std::string& name : multibody::available_engines()) {
        SCOPED_TRACE(name);
        const std::string file = (dir / (name + ".pid")).string();
        Excitation ex = free_vibration(0.2);
        ex.horizontal = GroundMotion::analytic(
            [file](double) {
                std::ofstream(file) << ::getpid();
                return 0.0;
            },
            0.2, {0.0, 0.2}, AnalyticShape{0.0, {}}, "pid probe");
        const auto engine = multibody::make_engine(name);
        (void)engine->simulate(fig6(), ex, engine->default_settings());
        long pid = 0;
        std::ifstream(file) >> pid;
        ASSERT_NE(pid, 0) << "the ground motion was never evaluated";
        if (name == "analytic") EXPECT_EQ(pid, ::getpid());
        else EXPECT_NE(pid, ::getpid());
    }
}

// The isolated run is the in-process run to the last bit (every engine library, the Fig. 6 free vibration).
TEST(IsolatedEngine, ResultsAreThoseOfTheRunInThisProcess) {
    for (const std::string& name : multibody::available_engines()) {
        if (name == "analytic") continue;
        SCOPED_TRACE(name);
        const auto isolated = multibody::make_engine(name);
        const auto here = multibody::make_engine_in_process(name);
        const Trajectory a = isolated->simulate(fig6(), free_vibration(), isolated->default_settings());
        const Trajectory b = here->simulate(fig6(), free_vibration(), here->default_settings());
        ASSERT_EQ(a.samples.size(), b.samples.size());
        ASSERT_FALSE(a.samples.empty());
        for (std::size_t i = 0; i < a.samples.size(); ++i) {
            ASSERT_TRUE(same_bits(a.samples[i].theta1, b.samples[i].theta1)) << i;
            ASSERT_TRUE(same_bits(a.samples[i].theta1_dot, b.samples[i].theta1_dot)) << i;
        }
        EXPECT_EQ(a.steps, b.steps);
    }
}

// Every knob of every engine outside its documented range is refused as bad input naming the value, before the
// library sees it (the defaults, inside, are accepted: SettingDescriptions.EveryKnobDescribedIsAcceptedAndNoOtherIs).
TEST(SettingRanges, AKnobOutsideItsRangeIsRefusedNamingIt) {
    for (const std::string& name : multibody::available_engines()) {
        const auto engine = multibody::make_engine(name);
        for (const multibody::SettingDescription& d : engine->setting_descriptions()) {
            if (!multibody::is_knob(d.name)) continue;
            SCOPED_TRACE(name + " " + d.name);
            ASSERT_LE(d.lo, d.hi);
            for (const double outside : {d.hi * 2.0 + 1.0, d.lo - std::abs(d.lo) - 1.0, 1e308, -1e308}) {
                if (outside >= d.lo && outside <= d.hi) continue;  // an unbounded end
                multibody::EngineSettings s = engine->default_settings();
                s.knobs[d.name] = outside;
                try {
                    engine->check_settings(s);
                    ADD_FAILURE() << outside << " accepted";
                } catch (const InputError& e) {
                    EXPECT_NE(std::string(e.what()).find(d.name), std::string::npos) << e.what();
                    EXPECT_NE(std::string(e.what()).find("documented range"), std::string::npos) << e.what();
                }
            }
        }
    }
}

TEST(SettingRanges, EveryKnobOfAnEngineLibraryHasARange) {
    // An unbounded end is allowed only where the library is known to take it (ODE's max_correcting_vel = inf, no
    // cap): every other knob of an engine library is bounded on both sides.
    for (const std::string& name : multibody::available_engines()) {
        if (name == "analytic") continue;
        for (const multibody::SettingDescription& d : multibody::make_engine(name)->setting_descriptions()) {
            if (!multibody::is_knob(d.name) || d.name == "max_correcting_vel") continue;
            EXPECT_TRUE(std::isfinite(d.lo) && std::isfinite(d.hi)) << name << " " << d.name;
        }
    }
}

TEST(StepResolution, AStepCoarserThanThePulseOrTheWallIsRefusedNamingBoth) {
    const WallScene scene = fig6();
    Excitation ex;
    ex.horizontal = sine_pulse(0.5 * 9.81, 0.5);
    ex.t_end = 3.0;
    // The sine's quarter period is its shortest stretch: 0.125 s, so steps up to 0.0625 s pass.
    EXPECT_DOUBLE_EQ(multibody::excitation_time_scale(ex.horizontal), 0.125);
    EXPECT_NO_THROW(multibody::require_step_resolves("ode", scene, ex, 1e-3));
    for (const double dt : {0.07, 0.5, 1000.0}) {
        try {
            multibody::require_step_resolves("ode", scene, ex, dt);
            ADD_FAILURE() << dt << " accepted";
        } catch (const InputError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("dt = "), std::string::npos) << m;
            EXPECT_NE(m.find("for the wall"), std::string::npos) << m;
            EXPECT_NE(m.find("for the ground motion"), std::string::npos) << m;
        }
    }
    // A Housner block: theta1'_r lifts its centre by R (1 - cos alpha) from rest, I0 = 4/3 m R^2, so alpha /
    // theta1'_r = alpha / sqrt(3 g (1 - cos alpha) / (2 R)), 1 / p (1 + alpha^2 / 24 + ...), p = sqrt(3 g / 4 R).
    const ParapetGeometry p = make_parapet(4.0, 0.4);
    const double R = 0.5 * std::hypot(4.0, 0.4);
    constexpr double kRounding = 1e-12;  // a closed form against the model's energy: rounding only
    EXPECT_NEAR(multibody::wall_time_scale(WallScene::of(p)),
                p.alpha / std::sqrt(3.0 * p.g * (1.0 - std::cos(p.alpha)) / (2.0 * R)), kRounding);
}

// A record's time scale is its content's, not its sampling's: a 1 Hz sine sampled every 0.5 ms (a shake table's
// 2 kHz) and every 10 ms has the same, a quarter period (to the end effects of counting 19 sign changes in 10
// cycles: 10 / 38 s against 0.25 s), so ODE's 1 ms step passes on both and a 0.2 s step on neither.
TEST(StepResolution, ARecordsTimeScaleIsItsContentsNotItsSampling) {
    constexpr double kPi = 3.14159265358979323846;
    constexpr double kEndEffects = 0.06;  // one sign change of 19 missing at the record's ends
    const auto sine_record = [&](double dt) {
        std::vector<double> t, a;
        for (int i = 0; i * dt <= 10.0 + 1e-12; ++i) {
            t.push_back(i * dt);
            a.push_back(std::sin(2.0 * kPi * (i * dt + 0.1)));  // a phase: no sample lands on a zero
        }
        return GroundMotion::sampled(t, a, "sine");
    };
    for (const double dt : {5e-4, 1e-2}) {
        SCOPED_TRACE(dt);
        Excitation ex;
        ex.horizontal = sine_record(dt);
        ex.t_end = 12.0;
        EXPECT_NEAR(multibody::excitation_time_scale(ex.horizontal), 0.25, 0.25 * kEndEffects);
        EXPECT_NO_THROW(multibody::require_step_resolves("ode", fig6(), ex, 1e-3));
        EXPECT_THROW(multibody::require_step_resolves("ode", fig6(), ex, 0.2), InputError);
        // A reporting interval (Simbody's compliant route) is held to the wall's rule alone.
        EXPECT_NO_THROW(multibody::require_step_resolves("simbody", fig6(), ex, 0.03, false));
    }
}

TEST(StepResolution, EveryEngineRefusesAStepLongerThanTheRunNeeds) {
    Excitation ex;
    ex.horizontal = sine_pulse(0.5 * 9.81, 0.5);
    ex.t_end = 3.0;
    for (const std::string& name : multibody::available_engines()) {
        if (name == "analytic") continue;  // its dt is only the sampling: its integrator steps on its own
        SCOPED_TRACE(name);
        const auto engine = multibody::make_engine(name);
        multibody::EngineSettings s = engine->default_settings();
        s.dt = 0.5;
        EXPECT_THROW((void)engine->simulate(fig6(), ex, s), InputError);
    }
}

}  // namespace

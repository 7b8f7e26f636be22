// The stress runner (multibody/host/child_process.hpp's run_in_child, as run.hpp uses it; run.hpp, judge.hpp): one bad
// case cannot take a run down, and each way a child can end has its verdict. The verdicts of the stress set itself
// are asserted through the program (tests/cli/stress.sh).
#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "multibody/engine.hpp"
#include "multibody/host/child_process.hpp"
#include "stress/case.hpp"
#include "stress/judge.hpp"
#include "stress/run.hpp"
#include "vssw_engine_facts.hpp"  // each engine's contact ends (generated: cmake/engines.cmake)

namespace vssw::stress {
namespace {

using multibody::ChildEnd;
using multibody::ChildResult;
using multibody::run_in_child;

// A time limit the quick children below end well inside even on a loaded machine (they return at once).
constexpr double kGenerousLimit = 60.0;
// The limit of the case that sleeps: short, so the test is quick; the sleep is 100 times longer, so only the kill
// can end it in time.
constexpr double kShortLimit = 0.5;
constexpr unsigned kSleepSeconds = 50;

TEST(StressRunner, ReturnsTheChildsAnswer) {
    const ChildResult r = run_in_child([] { return std::string("ok\tnone\tfine"); }, kGenerousLimit);
    EXPECT_EQ(r.end, ChildEnd::completed);
    EXPECT_EQ(r.output, "ok\tnone\tfine");
}

TEST(StressRunner, AnAnswerLongerThanThePipeBufferArrivesWhole) {
    const std::string big(1 << 20, 'x');  // 1 MiB: 16 times a Linux pipe's buffer
    const ChildResult r = run_in_child([&] { return big; }, kGenerousLimit);
    ASSERT_EQ(r.end, ChildEnd::completed);
    EXPECT_EQ(r.output.size(), big.size());
}

TEST(StressRunner, ACaseThatSleepsPastTheLimitTimesOut) {
    const ChildResult r = run_in_child(
        [] {
            ::sleep(kSleepSeconds);
            return std::string("late");
        },
        kShortLimit);
    EXPECT_EQ(r.end, ChildEnd::timed_out);
    const CaseResult v = result_of(r, "sleeper", "none");
    EXPECT_EQ(v.verdict, Verdict::failed);
    EXPECT_EQ(v.failure, Failure::timed_out);
    EXPECT_NE(v.reason.find("timed out"), std::string::npos) << v.reason;
    EXPECT_TRUE(is_unsafe(v));
}

TEST(StressRunner, ACaseThatAbortsIsACrashNamingTheSignal) {
    const ChildResult r = run_in_child(
        []() -> std::string {
            std::abort();
        },
        kGenerousLimit);
    EXPECT_EQ(r.end, ChildEnd::crashed);
    EXPECT_EQ(r.signal, SIGABRT);
    const CaseResult v = result_of(r, "aborter", "none");
    EXPECT_EQ(v.failure, Failure::crashed);
    EXPECT_NE(v.reason.find("crashed (signal " + std::to_string(SIGABRT)), std::string::npos) << v.reason;
}

TEST(StressRunner, ASegfaultIsACrash) {
    const ChildResult r = run_in_child(
        []() -> std::string {
            // The default action, as in a normal build: under ASan (scripts/setup.sh asan) its handler would catch the
            // signal, print a report and exit with 1, which is an exit, not a crash.
            std::signal(SIGSEGV, SIG_DFL);
            std::raise(SIGSEGV);
            return "survived";
        },
        kGenerousLimit);
    EXPECT_EQ(r.end, ChildEnd::crashed);
    EXPECT_EQ(r.signal, SIGSEGV);
}

TEST(StressRunner, AnExceptionIsAReportedFailureWithItsMessage) {
    const ChildResult r = run_in_child([]() -> std::string { throw std::runtime_error("engine blew up at 1 s"); },
                                       kGenerousLimit);
    EXPECT_EQ(r.end, ChildEnd::threw);
    const CaseResult v = result_of(r, "thrower", "none");
    EXPECT_EQ(v.failure, Failure::reported);
    EXPECT_EQ(v.reason, "engine blew up at 1 s");
    EXPECT_FALSE(is_unsafe(v));
}

TEST(StressRunner, ALibraryCallingExitIsNotAnAnswer) {
    const ChildResult r = run_in_child([]() -> std::string { ::_exit(7); }, kGenerousLimit);
    EXPECT_EQ(r.end, ChildEnd::exited);
    EXPECT_EQ(r.exit_code, 7);
    EXPECT_TRUE(is_unsafe(result_of(r, "exiter", "none")));
}

TEST(StressRunner, SeveralThreadsEachGetTheirOwnChild) {
    std::string a, b;
    std::thread ta([&] { a = run_in_child([] { return std::string("a"); }, kGenerousLimit).output; });
    std::thread tb([&] { b = run_in_child([] { return std::string("b"); }, kGenerousLimit).output; });
    ta.join();
    tb.join();
    EXPECT_EQ(a, "a");
    EXPECT_EQ(b, "b");
}

TEST(StressVerdicts, EncodeAndDecodeAgree) {
    const CaseResult r{"x", "e", Verdict::failed, Failure::nan, "NaN in the output at t = 1.0 s", 0.0};
    const CaseResult back = decode(encode(r));
    EXPECT_EQ(back.verdict, Verdict::failed);
    EXPECT_EQ(back.failure, Failure::nan);
    EXPECT_EQ(back.reason, r.reason);
}

TEST(StressCases, NamesAreUniqueAndTheQuickSetIsAProperSubset) {
    std::set<std::string> names;
    int quick = 0;
    for (const Case& c : all_cases()) {
        EXPECT_TRUE(names.insert(c.name).second) << c.name;
        EXPECT_FALSE(c.what.empty()) << c.name;
        quick += c.quick ? 1 : 0;
    }
    EXPECT_GT(quick, 0);
    EXPECT_LT(quick, static_cast<int>(all_cases().size()));
}

TEST(StressCases, ABackendWithoutTheKnobRefusesWithAReason) {
    const CaseResult r = judge(*find_case("contact-soft"), "analytic", true);
    EXPECT_EQ(r.verdict, Verdict::refused);
    EXPECT_NE(r.reason.find("no contact stiffness"), std::string::npos) << r.reason;
}

// The knobs a CONTACT_SOFT or CONTACT_STIFF fact names ("erp=0.2 cfm=1e-5") against the engine's own settings: each
// must be one of its knobs, and its value inside the knob's range. One line per problem.
std::vector<std::string> contact_end_problems(const std::string& words,
                                              const std::vector<multibody::SettingDescription>& settings) {
    std::vector<std::string> problems;
    std::istringstream in(words);
    for (std::string word; in >> word;) {
        const std::size_t eq = word.find('=');
        const std::string name = word.substr(0, eq);
        const auto d = std::find_if(settings.begin(), settings.end(),
                                    [&](const multibody::SettingDescription& s) { return s.name == name; });
        if (d == settings.end() || !multibody::is_knob(name)) {
            problems.push_back(name + " is not a knob of the engine");
            continue;
        }
        const double value = std::stod(word.substr(eq + 1));
        if (!(value >= d->lo && value <= d->hi)) problems.push_back(word + " is outside " + multibody::range_text(*d));
    }
    return problems;
}

TEST(StressCases, ContactEndsNameKnobsOfTheEngineInsideTheirRanges) {
    int checked = 0;
    for (const EngineFacts& e : kEngineFacts) {
        if (!e.built || (std::string(e.contact_soft).empty() && std::string(e.contact_stiff).empty())) continue;
        const std::vector<multibody::SettingDescription> settings = multibody::make_engine(e.name)->setting_descriptions();
        for (const char* words : {e.contact_soft, e.contact_stiff}) {
            EXPECT_FALSE(std::string(words).empty()) << e.name << ": both ends or neither";
            EXPECT_EQ(contact_end_problems(words, settings), std::vector<std::string>{}) << e.name << ": " << words;
            ++checked;
        }
    }
    EXPECT_GT(checked, 0) << "no engine of this build has a contact knob: the check ran on nothing";
    // Must fail: a misspelt knob and a value past ODE's range (erp in [0, 1]) are named.
    for (const EngineFacts& e : kEngineFacts)
        if (e.built && std::string(e.name) == "ode") {
            const auto settings = multibody::make_engine("ode")->setting_descriptions();
            EXPECT_EQ(contact_end_problems("erpx=1 erp=2", settings).size(), 2u);
        }
}

TEST(StressCases, TheAnalyticModelBelowItsThresholdDoesNotLift) {
    // Eq. (12) x (1 - 1e-9): the rest threshold is exact for the analytic model, so it must stay on its base.
    const CaseResult r = judge(*find_case("pulse-threshold-1e-9"), "analytic", true);
    EXPECT_EQ(r.verdict, Verdict::ok) << r.reason;
}

// Where the analytic model's own assumptions fail (the squat wall's roller would have to pull), the checks against
// its answer are void, but the case's own bounds still hold: a bound the run breaks fails it.
TEST(StressCases, AVoidAnalyticAnswerLeavesTheCasesOwnBoundsInForce) {
    const Case& squat = *find_case("squat-t/h0.5");
    const CaseResult as_is = judge(squat, "analytic", true);
    EXPECT_EQ(as_is.verdict, Verdict::ok) << as_is.reason;
    EXPECT_NE(as_is.reason.find("not held against the analytic model"), std::string::npos) << as_is.reason;

    constexpr double kNoRocking = 1e-9;  // [rad] a bound the squat wall's rocking run must break
    Case bounded = squat;
    // (stress::Setup in full: inside a TEST body, plain Setup names gtest's misspelling trap.)
    bounded.setup = [inner = squat.setup, bound = kNoRocking](const std::string& e,
                                                              const multibody::EngineSettings& d,
                                                              bool quick) -> stress::Setup {
        stress::Setup s = inner(e, d, quick);
        s.max_theta = bound;
        return s;
    };
    const CaseResult r = judge(bounded, "analytic", true);
    EXPECT_EQ(r.verdict, Verdict::failed) << r.reason;
    EXPECT_EQ(r.failure, Failure::wrong);
    EXPECT_NE(r.reason.find("max |theta1|"), std::string::npos) << r.reason;
}

TEST(StressCases, AnUnknownCaseOrEngineIsRefusedBeforeAnythingRuns) {
    RunOptions o;
    o.engines = {"analytic"};
    o.cases = {"no-such-case"};
    EXPECT_THROW(run_cases(o), std::runtime_error);
    o.cases = {};
    o.engines = {"no-such-engine"};
    EXPECT_THROW(run_cases(o), std::runtime_error);
}

}  // namespace
}  // namespace vssw::stress

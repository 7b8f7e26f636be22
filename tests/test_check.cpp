// `vssw check`: the bounds file (TOML and JSON, one schema, every malformation a message naming it), bounds held
// against results (inside, outside, not measured, engine failed), and the command end to end on the analytic model
// (exit 0 when the stored values hold, 1 when one does not, 2 on a bad file).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "validation/bounds_file.hpp"
#include "cli/cli.hpp"
#include "validation/bounds.hpp"
#include "tests/cli_runner.hpp"
#include "tests/engine_available.hpp"
#include "tests/temp_files.hpp"

namespace {

using vssw::InputError;
using vssw::validation::parse_bounds;
using vssw::validation::Bounds;
using vssw::validation::BoundVerdict;
using vssw::validation::SuiteResults;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const char* const kToml = R"(
suite = "default"

[[analytic]]
case = "fig6-vssw"
metric = "threshold_g"
reference = 0.25
max_drift = 1e-6

[[engine]]
engine = "ode"
cases = ["fig6-vssw", "fig6-pw"]
metric = "period"
max_error = 0.005

[[engine]]
engine = "bullet"
cases = ["fig6-vssw/r0.5"]
metric = "restitution"
error = [-0.16, -0.10]
)";

const char* const kJson = R"({
  "suite": "default",
  "analytic": [{"case": "fig6-vssw", "metric": "threshold_g", "reference": 0.25, "max_drift": 1e-6}],
  "engine": [
    {"engine": "ode", "cases": ["fig6-vssw", "fig6-pw"], "metric": "period", "max_error": 0.005},
    {"engine": "bullet", "cases": ["fig6-vssw/r0.5"], "metric": "restitution", "error": [-0.16, -0.10]}
  ]
})";

// The message of the InputError the text raises ("" if it parses).
std::string error_of(const std::string& text, const std::string& format = "toml") {
    try {
        parse_bounds(text, format, "b." + format);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(BoundsFile, TomlAndJsonSayTheSame) {
    for (const auto& [text, format] : {std::pair{kToml, "toml"}, std::pair{kJson, "json"}}) {
        const Bounds b = parse_bounds(text, format, "b");
        EXPECT_EQ(b.suite, "default");
        ASSERT_EQ(b.analytic.size(), 1u);
        EXPECT_EQ(b.analytic[0].case_id, "fig6-vssw");
        EXPECT_EQ(b.analytic[0].reference, 0.25);
        EXPECT_EQ(b.analytic[0].max_drift, 1e-6);
        ASSERT_EQ(b.engines.size(), 2u);
        EXPECT_EQ(b.engines[0].case_ids, (std::vector<std::string>{"fig6-vssw", "fig6-pw"}));
        EXPECT_EQ(b.engines[0].min_error, -0.005);  // max_error x means [-x, x]
        EXPECT_EQ(b.engines[0].max_error, 0.005);
        EXPECT_EQ(b.engines[1].min_error, -0.16);
        EXPECT_EQ(b.engines[1].max_error, -0.10);
    }
}

TEST(BoundsFile, CasesAndEnginesNeededAreListedOnce) {
    const Bounds b = parse_bounds(kToml, "toml", "b");
    EXPECT_EQ(vssw::validation::cases_needed(b), (std::vector<std::string>{"fig6-vssw", "fig6-pw", "fig6-vssw/r0.5"}));
    EXPECT_EQ(vssw::validation::engines_needed(b), (std::vector<std::string>{"ode", "bullet"}));
}

// The start of an ODE engine bound on case "a", for the entries below that differ only in their last keys.
const std::string kOdeBound = "[[engine]]\nengine = \"ode\"\ncases = [\"a\"]\nmetric = \"period\"\n";

// The text is refused with a message holding `fragment` (the message is printed when it does not).
void expect_refused(const std::string& text, const std::string& fragment, const std::string& format = "toml") {
    const std::string message = error_of(text, format);
    EXPECT_NE(message.find(fragment), std::string::npos) << "message: '" << message << "'";
}

TEST(BoundsFile, EachMalformationIsNamed) {
    expect_refused("suite = \"default\"\n" + kOdeBound + "max_eror = 0.1\n", "unknown key 'max_eror'");
    expect_refused("[[analytic]]\ncase = \"a\"\nmetric = \"period\"\nmax_drift = 1e-6\n", "'reference' is missing");
    expect_refused(kOdeBound + "max_error = -0.1\n", "'max_error' must be >= 0, got -0.1");
    expect_refused(kOdeBound + "error = [0.1, -0.1]\n", "min > max");
    expect_refused("[[analytic]]\ncase = \"a\"\nmetric = \"p\"\nreference = nan\nmax_drift = 1e-6\n",
                   "'reference' must be a finite number");
    expect_refused("[[engine]]\nengine = \"ode\"\ncases = []\nmetric = \"period\"\nmax_error = 0.1\n", "non-empty list");
    expect_refused(kOdeBound, "exactly one of");
    expect_refused("suite = \"default\"\n", "no bounds");
    expect_refused("[[engine]\n", "TOML syntax error at line 1");
    expect_refused("{\"engine\": [", "JSON syntax error", "json");
    expect_refused("{\"bounds\": []}", "unknown key 'bounds'", "json");
    // A key given twice would silently loosen the bound in JSON (TOML refuses it itself).
    expect_refused("{\"analytic\": [{\"case\": \"a\", \"metric\": \"period\", \"reference\": 1, "
                   "\"max_drift\": 1e-6, \"max_drift\": 5}]}",
                   "key 'max_drift' given twice", "json");
    expect_refused("[[engine]]\nengine = \"analytic\"\ncases = [\"a\"]\nmetric = \"period\"\nmax_error = 0.1\n",
                   "the reference");
    expect_refused("[[engine]]\nengine = \"ode\"\ncases = [\"a\", \"a\"]\nmetric = \"period\"\nmax_error = 0.1\n",
                   "names a case twice");
    const std::string quake = "[[earthquake]]\nengine = \"ode\"\n";
    expect_refused(quake + "measure = \"peak\"\nmin = 0.9\n", "measure 'peak' is not one of");
    expect_refused(quake + "measure = \"overturning_agreement\"\n", "give 'min', 'max' or both");
    expect_refused(quake + "measure = \"overturning_agreement\"\nmin = 1\nmax = 0.5\n", "min 1 is above max 0.5");
    expect_refused("[[earthquake]]\nengine = \"analytic\"\nmeasure = \"inside_band\"\nmin = 0\n", "the reference");
    expect_refused(quake + "measure = \"inside_band\"\nmin = 0\nstudy = 3\n", "'study'");
}

// Found by the fuzz harness (tests/fuzz/fuzz_bounds_file.cpp): a JSON value nested a million deep crashed the
// reader (stack overflow in nlohmann's recursive dump() quoting it in the message). Now refused like TOML's nesting
// beyond toml++'s limit, before anything quotes it.
TEST(BoundsFile, DeepNestingIsRefusedNotACrash) {
    constexpr std::size_t kDepth = 1000000;  // some 2 MB: deep enough to overflow an 8 MB stack when recursed
    const std::string deep = std::string(kDepth, '[') + std::string(kDepth, ']');
    expect_refused("{\"suite\": " + deep + "}", "nested deeper than 256 levels", "json");
    expect_refused("{\"analytic\": [{\"case\": " + deep + "}]}", "nested deeper than 256 levels", "json");
    expect_refused("suite = " + deep + "\n", "TOML syntax error", "toml");
}

// Found by the fuzz harness under UBSan: toml++ 3.3 reaches TOML_UNREACHABLE (undefined behaviour) on U+0237
// ("\xC8\xB7" in UTF-8) at the start of a line. TOML bounds files are now refused unless ASCII, naming the line.
TEST(BoundsFile, NonAsciiTomlIsRefusedBeforeTomlppSeesIt) {
    expect_refused("\xC8\xB7\n", "line 1: a non-ASCII character (byte 0xC8)");
    expect_refused("suite = \"default\"  # theta \xCE\xB8\n", "line 1: a non-ASCII character (byte 0xCE)");
    // JSON goes through nlohmann::json, which reads UTF-8 correctly: a non-ASCII case id is kept.
    const Bounds b = parse_bounds("{\"analytic\": [{\"case\": \"\xCE\xB8\", \"metric\": \"period\", "
                                  "\"reference\": 1, \"max_drift\": 0}]}",
                                  "json", "b.json");
    EXPECT_EQ(b.analytic.at(0).case_id, "\xCE\xB8");
}

TEST(BoundsFile, AMissingFileOrAnUnknownFormatIsNamed) {
    try {
        vssw::validation::read_bounds_file("/nonexistent/bounds.toml");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/bounds.toml"), std::string::npos) << e.what();
    }
    EXPECT_THROW(vssw::validation::read_bounds_file("bounds.yaml"), InputError);
}

// Results as a run would leave them, built by hand so every branch of evaluate() is reached.
SuiteResults hand_made_results() {
    SuiteResults r;
    r.suite = "default";
    r.rows.push_back({"fig6-vssw", "analytic", "threshold_g", 0.25, 0.2500001, 0.0, "analytic model", "g"});
    r.rows.push_back({"fig6-vssw", "ode", "period", 3.0, 3.003, 1e-3, "analytic model", "s"});
    r.rows.push_back({"fig6-pw", "ode", "period", 3.0, 3.03, 1e-2, "analytic model", "s"});
    r.rows.push_back({"fig6-vssw/r0.5", "bullet", "restitution", 0.95, kNaN, kNaN, "analytic model", ""});
    r.failures.push_back({"fig6-vssw/r0.5", "bullet", "Bullet: the wall slid 0.01 m at t = 1 s"});
    return r;
}

TEST(Bounds, AValueIsHeldAgainstItsIntervalAndAnythingUnmeasuredFails) {
    const std::vector<BoundVerdict> v = vssw::validation::evaluate(parse_bounds(kToml, "toml", "b"), hand_made_results());
    ASSERT_EQ(v.size(), 4u);
    EXPECT_TRUE(v[0].held) << "analytic drift 4e-7 within 1e-6";
    EXPECT_TRUE(v[1].held) << "ode period error 1e-3 within 5e-3";
    EXPECT_FALSE(v[2].held) << "ode period error 1e-2 outside 5e-3";
    EXPECT_TRUE(v[2].note.empty());
    EXPECT_FALSE(v[3].held) << "a failed engine run holds no bound";
    EXPECT_NE(v[3].note.find("slid 0.01 m"), std::string::npos) << v[3].note;
}

TEST(Bounds, AnAnalyticDriftPastTheStoredValueFails) {
    SuiteResults r = hand_made_results();
    r.rows[0].engine_value = 0.25 * (1.0 + 2e-6);  // twice the allowed drift
    const std::vector<BoundVerdict> v = vssw::validation::evaluate(parse_bounds(kToml, "toml", "b"), r);
    EXPECT_FALSE(v[0].held);
}

TEST(Bounds, AZeroReferenceBoundsTheValueItself) {
    const Bounds b = parse_bounds("[[analytic]]\ncase = \"h\"\nmetric = \"overturned\"\nreference = 0\nmax_drift = 0.5\n",
                                  "toml", "b");
    SuiteResults r;
    r.rows.push_back({"h", "analytic", "overturned", 0.0, 0.0, 0.0, "analytic model", ""});
    EXPECT_TRUE(vssw::validation::evaluate(b, r)[0].held);
    r.rows[0].engine_value = 1.0;  // it fell
    EXPECT_FALSE(vssw::validation::evaluate(b, r)[0].held);
}

// The command end to end, on the analytic model only (fast): the Fig. 6 VSSW's threshold against Eq. (12)'s
// closed form, which the bisection reaches to its 1e-4 bracket.
using vssw::testing::CliResult;
using vssw::testing::run_cli;

// In a folder of its own (mkdtemp): the tests run in parallel processes, and a fixed /tmp name once let one test
// overwrite or remove another's bounds file mid-run.
CliResult run_check(const std::string& bounds_text, const std::string& extension = ".toml") {
    const vssw::testing::TempDir dir("check_bounds");
    const std::string path = (dir / ("bounds" + extension)).string();
    std::ofstream(path) << bounds_text;
    return run_cli({"check", "--bounds", path});
}

std::string fig6_threshold_bound(double reference, double max_drift) {
    std::ostringstream s;
    s.precision(17);
    s << "[[analytic]]\ncase = \"fig6-vssw\"\nmetric = \"threshold_g\"\nreference = " << reference
      << "\nmax_drift = " << max_drift << "\n";
    return s.str();
}

// The bisection's bracket is 1e-4 of the threshold; its mid-point is within half of that of the true value.
constexpr double kBisectionDrift = 1e-4;

TEST(CheckCommand, HoldsWhenTheCoreMatchesItsReferenceAndFailsWithOneWhenItDoesNot) {
    const double eq12 = vssw::eq12_threshold(vssw::make_vssw(4.0, 0.4, 0.7)) / 9.81;  // in g
    const CliResult ok = run_check(fig6_threshold_bound(eq12, kBisectionDrift));
    EXPECT_EQ(ok.code, 0) << ok.out << ok.err;
    EXPECT_NE(ok.out.find("1 of 1 bounds hold"), std::string::npos) << ok.out;

    const CliResult off = run_check(fig6_threshold_bound(eq12 * 1.01, kBisectionDrift));  // a stored value 1 % off
    EXPECT_EQ(off.code, 1) << off.out << off.err;
    EXPECT_NE(off.out.find("OUT"), std::string::npos) << off.out;
    EXPECT_NE(off.err.find("1 of 1 bounds do not hold"), std::string::npos) << off.err;
}

TEST(CheckCommand, ABadFileExitsWithTwoAndNamesTheProblem) {
    const CliResult missing = run_cli({"check", "--bounds", "/nonexistent/b.toml"});
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("/nonexistent/b.toml"), std::string::npos) << missing.err;

    const CliResult unknown_case = run_check(
        "[[engine]]\nengine = \"ode\"\ncases = [\"no-such-wall\"]\nmetric = \"period\"\nmax_error = 0.1\n");
    EXPECT_EQ(unknown_case.code, 2);
    EXPECT_NE(unknown_case.err.find("no-such-wall"), std::string::npos) << unknown_case.err;

    const CliResult wrong_metric = run_check(
        "[[analytic]]\ncase = \"fig6-pw/r0.5\"\nmetric = \"perod\"\nreference = 1\nmax_drift = 0.1\n");
    EXPECT_EQ(wrong_metric.code, 2) << "a metric the case does not measure is a mistake, not a bound out";
    EXPECT_NE(wrong_metric.err.find("no metric 'perod'"), std::string::npos) << wrong_metric.err;

    const CliResult unknown_engine = run_check(
        "[[engine]]\nengine = \"havok\"\ncases = [\"fig6-pw/r0.5\"]\nmetric = \"period\"\nmax_error = 0.1\n");
    EXPECT_EQ(unknown_engine.code, 2);
    EXPECT_NE(unknown_engine.err.find("havok"), std::string::npos) << unknown_engine.err;

    const CliResult no_study = run_check(
        "[[earthquake]]\nstudy = \"/nonexistent/e.toml\"\nengine = \"ode\"\nmeasure = \"inside_band\"\nmin = 0\n");
    EXPECT_EQ(no_study.code, 2);
    EXPECT_NE(no_study.err.find("/nonexistent/e.toml"), std::string::npos) << no_study.err;
}

// An earthquake bound holds the engine's measure on the named ensemble: ODE agrees with the reference on every run of
// the report's ensemble (docs/earthquakes.md), so an agreement of at least 0.9 holds and one above 1 cannot.
TEST(CheckCommand, AnEarthquakeBoundHoldsTheEnsemblesMeasure) {
    if (!vssw::testing::engine_available("ode")) GTEST_SKIP() << "ODE not in this build";
    const std::string bound = "[[earthquake]]\nengine = \"ode\"\nmeasure = \"overturning_agreement\"\n";
    const CliResult held = run_check(bound + "min = 0.9\n");
    EXPECT_EQ(held.code, 0) << held.out << held.err;
    EXPECT_NE(held.out.find("ensemble-report"), std::string::npos) << held.out;
    const CliResult out_of = run_check(bound + "min = 1.01\n");
    EXPECT_EQ(out_of.code, 1) << out_of.out << out_of.err;
    EXPECT_NE(out_of.out.find("OUT"), std::string::npos) << out_of.out;
}

}  // namespace

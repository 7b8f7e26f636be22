// One meaning per name in the program's JSON: a key `alpha` holds the whole wall's slenderness atan(b/h) (as a
// study's `alpha` column and Python's Simulation.alpha), a key `alpha1` the lower block's angle atan(b/h1) that
// rotations are measured in. The angles are computed here from the wall's dimensions, not by the program.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "tests/cli_runner.hpp"
#include "tests/engine_available.hpp"
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

using Json = nlohmann::json;
using vssw::testing::CliResult;
using vssw::testing::run_cli;

// Rounding of a few double operations between atan here and the program's angle (JSON keeps 17 digits).
constexpr double kRoundoff = 1e-12;

// The wall of Fig. 6: full height 4 m, thickness 0.4 m, hinge 0.7, so b = 0.2, h = 2, h1 = 0.7 h = 1.4.
const std::vector<std::string> kFig6 = {"--height", "4", "--thickness", "0.4", "--hinge", "0.7"};
const double kWallAlpha = std::atan(0.2 / 2.0);   // atan(b/h)
const double kLowerAlpha = std::atan(0.2 / 1.4);  // atan(b/h1)

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

Json run_json(const std::vector<std::string>& args) {
    const CliResult r = run_cli(args + std::vector<std::string>{"--json"});
    EXPECT_EQ(r.code, 0) << r.err;
    return Json::parse(r.out);
}

// Every `alpha` and `alpha1` in `j` (top level and one level down) holds its one meaning; `alpha1` must be there.
void expect_one_meaning(const Json& j, const std::string& what) {
    ASSERT_TRUE(j.contains("alpha1")) << what;
    EXPECT_NEAR(j["alpha1"].get<double>(), kLowerAlpha, kRoundoff) << what << ": alpha1 is atan(b/h1)";
    for (const auto& [key, value] : j.items()) {
        if (key == "alpha") {
            EXPECT_NEAR(value.get<double>(), kWallAlpha, kRoundoff) << what << ": alpha is atan(b/h)";
        }
        if (value.is_object() && value.contains("alpha")) {
            EXPECT_NEAR(value["alpha"].get<double>(), kWallAlpha, kRoundoff) << what << "." << key;
        }
    }
}

TEST(CliNames, TheCheckRefusesTheOldNamingAndASwappedAngle) {
    // `vssw free --json` as it was: the lower block's angle written as alpha, no alpha1.
    static const Json old_free = {{"alpha", kLowerAlpha}, {"theta0", 0.5}};
    EXPECT_FATAL_FAILURE(expect_one_meaning(old_free, "old free"), "old free");
    static const Json both_lower = {{"alpha1", kLowerAlpha}, {"alpha", kLowerAlpha}};
    EXPECT_NONFATAL_FAILURE(expect_one_meaning(both_lower, "top"), "alpha is atan(b/h)");
    static const Json nested_lower = {{"alpha1", kLowerAlpha}, {"parapet", {{"alpha", kLowerAlpha}}}};
    EXPECT_NONFATAL_FAILURE(expect_one_meaning(nested_lower, "nested"), "nested.parapet");
    static const Json swapped = {{"alpha1", kWallAlpha}};
    EXPECT_NONFATAL_FAILURE(expect_one_meaning(swapped, "swapped"), "alpha1 is atan(b/h1)");
}

TEST(CliNames, WallKeysAlphaAndAlpha1HoldTheWallsAndTheLowerBlocksAngles) {
    const Json j = run_json(std::vector<std::string>{"wall"} + kFig6);
    expect_one_meaning(j, "wall");
    ASSERT_TRUE(j["parapet"].contains("alpha"));  // the parapet of the same size: its one block is the whole wall
}

TEST(CliNames, FreeAndHistoryWriteTheLowerBlocksAngleAsAlpha1) {
    const Json free = run_json(std::vector<std::string>{"free", "--theta0", "0.5"} + kFig6);
    expect_one_meaning(free, "free");
    const Json history = run_json(
        std::vector<std::string>{"history", "--pulse", "sine", "--amplitude", "0.5", "--pulse-period", "0.5"} + kFig6);
    expect_one_meaning(history, "history");
    // The peak is in alpha1's units, and its key says so.
    ASSERT_TRUE(history.contains("max_theta_over_alpha1"));
    EXPECT_NEAR(history["max_theta_over_alpha1"].get<double>() * kLowerAlpha, history["max_theta"].get<double>(),
                kRoundoff);
}

TEST(CliNames, AnEnginesRunWritesTheLowerBlocksAngleAsAlpha1) {
    if (!vssw::testing::engine_available("mujoco")) GTEST_SKIP() << "MuJoCo is not compiled in";
    const Json j = run_json(std::vector<std::string>{"free", "--engine", "mujoco", "--theta0", "0.5"} + kFig6);
    expect_one_meaning(j, "free --engine mujoco");
    EXPECT_TRUE(j.contains("max_theta_over_alpha1"));
}

// An engine's name is read in any letter case (make_engine, canonical_engine), so "Analytic" is the analytic model:
// run as such, not handed to the engine path (which ran it as a rigid-body engine, with other numbers and exit 0).
TEST(CliNames, TheAnalyticModelIsNamedInAnyLetterCase) {
    const std::vector<std::string> free = std::vector<std::string>{"free", "--theta0", "0.5"} + kFig6;
    EXPECT_EQ(run_json(free + std::vector<std::string>{"--engine", "Analytic"}), run_json(free));
    const std::vector<std::string> history =
        std::vector<std::string>{"history", "--pulse", "sine", "--amplitude", "0.5", "--pulse-period", "0.5"} + kFig6;
    EXPECT_EQ(run_json(history + std::vector<std::string>{"--engine", "ANALYTIC"}), run_json(history));
    const CliResult scene = run_cli(std::vector<std::string>{"scene", "--engine", "Analytic", "--out", "-"} + kFig6);
    EXPECT_EQ(scene.code, 2);
    EXPECT_NE(scene.err.find("the analytic model is no engine library"), std::string::npos) << scene.err;
}

}  // namespace

// What the program says about itself: `vssw --version` and `vssw compare --list-settings` (text and JSON), checked
// against the backends' own answers (Engine::version(), Engine::setting_descriptions()).
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "multibody/engine.hpp"
#include "tests/cli_runner.hpp"
#include "tests/engine_available.hpp"

namespace {

using Json = nlohmann::json;
using vssw::testing::run_cli;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CliVersion, NamesTheProgramAndEveryBackendWithItsLibraryVersion) {
    const auto r = run_cli({"--version"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("vssw " VSSW_VERSION, 0), 0u) << r.out;
    for (const std::string& name : vssw::multibody::available_engines())
        EXPECT_TRUE(contains(r.out, vssw::multibody::make_engine(name)->version())) << name << "\n" << r.out;
    for (const std::string& name : vssw::multibody::missing_engines()) EXPECT_TRUE(contains(r.out, name)) << r.out;
}

TEST(CliListSettings, ListsEveryDescribedSettingWithoutAWall) {
    for (const std::string& name : vssw::multibody::available_engines()) {
        SCOPED_TRACE(name);
        const auto r = run_cli({"compare", "--engine", name, "--list-settings"});
        ASSERT_EQ(r.code, 0) << r.err;
        for (const auto& d : vssw::multibody::make_engine(name)->setting_descriptions()) {
            const std::string flag = d.name == "dt" ? "--dt" : d.name == "iterations" ? "--iterations" : "--set " + d.name + "=";
            EXPECT_TRUE(contains(r.out, flag)) << flag;
            EXPECT_TRUE(contains(r.out, d.meaning)) << d.meaning;
        }
    }
}

TEST(CliListSettings, JsonCarriesEachSettingsDefaultUnitAndMeaning) {
    const auto r = run_cli({"compare", "--engine", "analytic", "--list-settings", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const Json listing = Json::parse(r.out);
    ASSERT_EQ(listing.size(), 1u);
    EXPECT_EQ(listing[0]["engine"], "analytic");
    const auto described = vssw::multibody::make_engine("analytic")->setting_descriptions();
    ASSERT_EQ(listing[0]["settings"].size(), described.size());
    for (std::size_t i = 0; i < described.size(); ++i) {
        const Json& s = listing[0]["settings"][i];
        EXPECT_EQ(s["name"], described[i].name);
        EXPECT_EQ(s["default"], described[i].default_value);
        EXPECT_EQ(s["unit"], described[i].unit);
        EXPECT_EQ(s["meaning"], described[i].meaning);
    }
}

// A setting for one kind of wall (refused for the other: require_settings_fit_wall) is marked so in both listings.
TEST(CliListSettings, ASettingForOneKindOfWallSaysWhich) {
    const Json listing = Json::parse(run_cli({"compare", "--list-settings", "--json"}).out);
    const std::string text = run_cli({"compare", "--list-settings"}).out;
    int marked = 0;
    for (const Json& engine : listing) {
        const auto described = vssw::multibody::make_engine(engine["engine"])->setting_descriptions();
        ASSERT_EQ(engine["settings"].size(), described.size());
        for (std::size_t i = 0; i < described.size(); ++i) {
            const auto& d = described[i];
            const std::string walls = d.vssw_only ? "vssw" : d.parapet_only ? "parapet" : "any";
            EXPECT_EQ(engine["settings"][i]["walls"], walls) << d.name;
            if (walls == "any") continue;
            ++marked;
            const std::string line = d.meaning + (d.vssw_only ? " (VSSW only)" : " (parapet only)");
            EXPECT_TRUE(contains(text, line)) << line;
        }
    }
    if (vssw::testing::engine_available("box2d")) {
        EXPECT_GE(marked, 2);  // its roller and its skin at least
    }
}

TEST(CliListSettings, WithoutAnEngineListsEveryBackendCompiledIn) {
    const auto r = run_cli({"compare", "--list-settings", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(Json::parse(r.out).size(), vssw::multibody::available_engines().size());
}

TEST(CliListSettings, AnUnknownEngineIsBadInputNamingIt) {
    const auto r = run_cli({"compare", "--engine", "nosuch", "--list-settings"});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "nosuch")) << r.err;
}

TEST(CliListSettings, TheCompareHelpCarriesTheSameListing) {
    const auto help = run_cli({"compare", "--help"});
    const auto listing = run_cli({"compare", "--list-settings"});
    ASSERT_EQ(help.code, 0);
    ASSERT_EQ(listing.code, 0);
    EXPECT_TRUE(contains(help.out, listing.out)) << help.out;
}

}  // namespace

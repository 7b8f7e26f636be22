// The engines' versions recorded beside their plugins when they are built (multibody/host/plugin_versions.hpp): what
// the opened plugin says, read by `vssw --version` without opening any plugin, and read only for the plugin and the
// build it was written for: a record that is not the plugin's is passed over, and the plugin opened as before.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "multibody/engine.hpp"
#include "multibody/host/plugin_file_check.hpp"
#include "multibody/host/plugin_loader.hpp"
#include "multibody/host/plugin_versions.hpp"
#include "multibody/host/registry.hpp"
#include "tests/cli_runner.hpp"
#include "tests/engine_available.hpp"
#include "tests/mapped_files.hpp"
#include "tests/temp_files.hpp"

namespace {

using namespace vssw;
using vssw::testing::mapped_files;
using vssw::testing::run_cli;
namespace fs = std::filesystem;

using vssw::testing::contains;
using vssw::testing::read_file;

// `text` with its first `from` replaced by `to` (which the test must find: a test that edits nothing proves nothing).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("no '" + from + "' in the record");
    return text.replace(at, from.size(), to);
}

class PluginVersionsTest : public ::testing::Test {
protected:
    void TearDown() override { ::unsetenv("VSSW_PLUGIN_PATH"); }
};

TEST(PluginVersions, EachRecordedVersionIsWhatTheOpenedPluginSays) {
    for (const std::string& name : multibody::available_engines()) {
        if (multibody::engine_plugin_file(name).empty()) continue;  // the analytic model, built in
        const auto recorded = multibody::recorded_engine_version(name);
        ASSERT_TRUE(recorded) << name << ": no record beside its plugin";
        EXPECT_EQ(recorded->version, multibody::make_engine_in_process(name)->version()) << name;
        EXPECT_EQ(recorded->plugin_path, multibody::engine_plugin_path(name)) << name;
    }
}

TEST(PluginVersions, TheVersionOpensNoPlugin) {
    if (contains(mapped_files(), "vssw_engine_")) GTEST_SKIP() << "a plugin is open already (run this test alone)";
    const auto r = run_cli({"--version"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(contains(mapped_files(), "vssw_engine_"));
    for (const std::string& name : multibody::available_engines()) {
        if (const auto recorded = multibody::recorded_engine_version(name)) {
            EXPECT_TRUE(contains(r.out, recorded->version)) << name << "\n" << r.out;
        }
    }
}

// A record is read for the plugin whose build-id it names and this program's build only: anything else (no record, a
// plugin replaced under its record, a record of another build, a line it does not know) reads as no record.
TEST_F(PluginVersionsTest, ARecordIsReadOnlyForItsOwnPluginAndBuild) {
    const vssw::testing::TempDir dir;
    const std::string plugin = (dir / "vssw_engine_x.so").string();
    const fs::path fixtures = VSSW_FIXTURE_PLUGIN_DIR;
    fs::copy_file(fixtures / "vssw_fixture.so", plugin);
    EXPECT_EQ(multibody::plugin_versions_file(plugin), (dir / "vssw_engine_x.versions").string());
    EXPECT_TRUE(multibody::recorded_versions(plugin).empty());
    const std::string text = multibody::plugin_versions_text(plugin, {{"x", "X 1.0 (a test)"}, {"y", "Y 2"}});
    const auto write = [&](const std::string& record) { std::ofstream(multibody::plugin_versions_file(plugin)) << record; };
    write(text);
    EXPECT_EQ(multibody::recorded_versions(plugin), (std::map<std::string, std::string>{{"x", "X 1.0 (a test)"}, {"y", "Y 2"}}));
    const std::string id = multibody::plugin_build_note(plugin);
    ASSERT_EQ(id.size(), 40u) << "a SHA-1 build-id, as -Wl,--build-id writes";
    write(replaced(text, id, std::string(id.size(), '0')));
    EXPECT_TRUE(multibody::recorded_versions(plugin).empty()) << "another plugin's record";
    write(replaced(text, multibody::program_build_id(), "another build"));
    EXPECT_TRUE(multibody::recorded_versions(plugin).empty()) << "another build's record";
    write(text + "colour\tred\n");
    EXPECT_TRUE(multibody::recorded_versions(plugin).empty()) << "a line it does not know";
    write(replaced(text, "vssw plugin versions 1", "vssw plugin versions 2"));
    EXPECT_TRUE(multibody::recorded_versions(plugin).empty()) << "another layout";
    write(text);
    fs::copy_file(fixtures / "vssw_fixture_other_abi.so", plugin, fs::copy_options::overwrite_existing);
    EXPECT_TRUE(multibody::recorded_versions(plugin).empty()) << "a plugin replaced under its record";
}

TEST_F(PluginVersionsTest, WhatARecordCannotHoldIsRefused) {
    const vssw::testing::TempDir dir;
    const std::string plugin = (dir / "vssw_engine_x.so").string();
    fs::copy_file(fs::path(VSSW_FIXTURE_PLUGIN_DIR) / "vssw_fixture.so", plugin);
    EXPECT_THROW((void)multibody::plugin_versions_text(plugin, {{"x", "X\t1"}}), std::runtime_error);
    EXPECT_THROW((void)multibody::plugin_versions_text(plugin, {{"x", "X\n1"}}), std::runtime_error);
    std::ofstream(dir / "text.so") << "not a library\n";
    EXPECT_THROW((void)multibody::plugin_versions_text((dir / "text.so").string(), {{"x", "X 1"}}),
                 std::runtime_error);
}

// Through the program: the version printed is the record's while the record is the plugin's, and the opened plugin's
// own once it is not. ODE's plugin and its record copied into a folder searched first.
TEST_F(PluginVersionsTest, TheProgramPrintsTheRecordOnlyWhileItIsThePlugins) {
    if (!vssw::testing::engine_available("ode") || contains(mapped_files(), "vssw_engine_ode.so"))
        GTEST_SKIP() << "ODE not built, or its plugin is open already (run this test alone)";
    const std::string built = multibody::engine_plugin_path("ode");
    const std::string real = multibody::recorded_engine_version("ode").value().version;
    const vssw::testing::TempDir dir;
    const std::string plugin = (dir / "vssw_engine_ode.so").string();
    fs::copy_file(built, plugin);
    const std::string text = read_file(multibody::plugin_versions_file(built));
    std::ofstream(multibody::plugin_versions_file(plugin)) << replaced(text, real, "ODE as recorded");
    ::setenv("VSSW_PLUGIN_PATH", dir.path.c_str(), 1);
    const auto recorded = run_cli({"--version"});
    EXPECT_TRUE(contains(recorded.out, "ode            ODE as recorded\n")) << recorded.out;
    EXPECT_TRUE(contains(recorded.out, plugin)) << recorded.out;
    const std::string id = multibody::plugin_build_note(plugin);
    std::ofstream(multibody::plugin_versions_file(plugin))
        << replaced(replaced(text, real, "ODE as recorded"), id, std::string(id.size(), '0'));
    const auto opened = run_cli({"--version"});
    EXPECT_TRUE(contains(opened.out, "ode            " + real + "\n")) << opened.out;
    EXPECT_FALSE(contains(opened.out, "ODE as recorded")) << opened.out;
}

}  // namespace

// The engines as plugins (multibody/host/plugin_loader.hpp, multibody/engine_plugin.hpp): found without set-up from the
// build tree, opened only when a run needs one, refused with a clear message when missing, broken (cut short, not a
// file, no description) or of another build, and
// their exceptions caught by type across the module boundary.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "multibody/host/contact_schemes.hpp"
#include "multibody/engine.hpp"
#include "multibody/engine_plugin.hpp"
#include "multibody/host/isolated_engine.hpp"
#include "multibody/host/plugin_file_check.hpp"
#include "multibody/host/plugin_loader.hpp"
#include "multibody/host/registry.hpp"
#include "tests/cli_runner.hpp"
#include "tests/engine_available.hpp"
#include "tests/mapped_files.hpp"
#include "tests/temp_files.hpp"
#include "vssw_engine_facts.hpp"  // each engine's LIBRARY (generated: cmake/engines.cmake)

namespace {

using namespace vssw;
using multibody::EngineFailure;
using vssw::testing::mapped_files;
using vssw::testing::run_cli;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The engine libraries (each engine folder's LIBRARY fact) but `except`'s, by the starts of their shared objects' names.
std::vector<std::string> engine_libraries(const std::string& except = "") {
    std::vector<std::string> libraries;
    for (const EngineFacts& e : kEngineFacts)
        if (*e.library && e.library != except &&
            std::find(libraries.begin(), libraries.end(), e.library) == libraries.end())
            libraries.push_back(e.library);
    return libraries;
}

// The engine libraries, MPI and the plugins, by the names of their shared objects.
const std::vector<std::string> kEngineLibraries = [] {
    std::vector<std::string> libraries = engine_libraries();
    for (const char* other : {"libmpi", "vssw_engine_", "vssw_mpi"}) libraries.push_back(other);
    return libraries;
}();

// The fixture plugins (plugin_fixture.cpp), opened from their folder through VSSW_PLUGIN_PATH.
class FixturePlugin : public ::testing::Test {
protected:
    void SetUp() override { ::setenv("VSSW_PLUGIN_PATH", VSSW_FIXTURE_PLUGIN_DIR, 1); }
    void TearDown() override { ::unsetenv("VSSW_PLUGIN_PATH"); }

    static const multibody::EnginePlugin& open(const std::string& stem) {
        const multibody::OpenedPlugin p =
            multibody::open_plugin(multibody::plugin_file(stem), multibody::kEnginePluginEntry, "the fixture");
        const auto& plugin =
            multibody::plugin_description<multibody::EnginePlugin>(p, "the fixture", multibody::kEnginePluginEntry);
        multibody::check_plugin_build(p, "the fixture", plugin.abi, multibody::kEnginePluginAbi, plugin.build_id);
        return plugin;
    }
    static std::unique_ptr<multibody::Engine> engine(const std::string& name) {
        const multibody::EnginePlugin& plugin = open("vssw_fixture");
        for (std::size_t i = 0; i < plugin.engine_count; ++i)
            if (name == plugin.engines[i].name) return plugin.engines[i].make();
        throw std::logic_error("no fixture engine " + name);
    }
    static void run(const multibody::Engine& e) {
        (void)e.simulate(multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7)), {}, {});
    }
};

TEST(Plugins, ListingTheEnginesOpensNoPlugin) {
    if (contains(mapped_files(), "vssw_engine_")) GTEST_SKIP() << "a plugin is open already (run this test alone)";
    for (const std::string& name : multibody::available_engines()) {
        (void)multibody::engine_display_name(name);
        (void)multibody::engine_plugin_file(name);
    }
    (void)multibody::missing_engines();
    (void)multibody::default_compared_engines();
    EXPECT_FALSE(contains(mapped_files(), "vssw_engine_"));
}

// The purpose of the plugins: a command that runs no engine loads no engine library, nor MPI.
TEST(Plugins, AnAnalyticCommandLoadsNoEngineLibraryAndAnEngineOnlyItsOwn) {
    if (contains(mapped_files(), "vssw_engine_")) GTEST_SKIP() << "a plugin is open already (run this test alone)";
    const auto free = run_cli({"free", "--height", "4", "--thickness", "0.4", "--hinge", "0.7", "--theta0", "0.5"});
    ASSERT_EQ(free.code, 0) << free.err;
    const auto wall = run_cli({"wall", "--height", "4", "--thickness", "0.4", "--hinge", "0.7"});
    ASSERT_EQ(wall.code, 0) << wall.err;
    std::string maps = mapped_files();
    for (const std::string& library : kEngineLibraries) EXPECT_FALSE(contains(maps, library)) << library;
    if (!vssw::testing::engine_available("ode")) return;
    const auto ode = run_cli({"compare", "--engine", "ode", "--height", "4", "--thickness", "0.4", "--hinge", "0.7"});
    ASSERT_EQ(ode.code, 0) << ode.err;
    maps = mapped_files();
    EXPECT_TRUE(contains(maps, "vssw_engine_ode.so"));
    EXPECT_TRUE(contains(maps, "libode.so"));
    std::vector<std::string> others = engine_libraries("libode.so");
    others.push_back("libmpi");
    ASSERT_GE(others.size(), 2u);
    for (const std::string& library : others) EXPECT_FALSE(contains(maps, library)) << library;
}

TEST(Plugins, DisplayNamesAreTheAdapters) {
    for (const std::string& name : multibody::available_engines())
        EXPECT_EQ(multibody::engine_display_name(name), multibody::make_engine_in_process(name)->display_name())
            << name;
}

// Every backend this project knows has a contact scheme (the report groups the engines by it): an engine added
// without one would be listed as "other".
TEST(ContactSchemes, EveryKnownEngineHasOneAndTheReportOrderGroupsThem) {
    std::vector<std::string> all = multibody::available_engines();
    for (const std::string& e : multibody::missing_engines()) all.push_back(e);
    for (const std::string& e : all) EXPECT_NE(multibody::contact_scheme(e).key, "other") << e;
    EXPECT_EQ(multibody::contact_scheme("no-such-engine").key, "other");
    // Siconos and Simbody are each a scheme of their own; ODE and Bullet share one, kept in the order given.
    const std::vector<std::string> ordered = multibody::ordered_by_scheme({"simbody", "ode", "siconos", "bullet"});
    EXPECT_EQ(ordered, (std::vector<std::string>{"ode", "bullet", "siconos", "simbody"}));
    EXPECT_EQ(multibody::contact_scheme("ode").key, multibody::contact_scheme("bullet").key);
    EXPECT_NE(multibody::contact_scheme("siconos").key, multibody::contact_scheme("bullet").key);
}

// Tests, programs and the Python module of a build tree use that build's plugins without any set-up.
TEST(Plugins, TheBuildTreesProgramsFindTheBuildsPlugins) {
    ::unsetenv("VSSW_PLUGIN_PATH");
    const std::vector<std::string> folders = multibody::plugin_folders();
    ASSERT_EQ(folders.size(), 1u);
    EXPECT_EQ(folders[0], VSSW_PLUGIN_OUTPUT_DIR);
    for (const std::string& name : multibody::available_engines()) {
        const std::string file = multibody::engine_plugin_file(name);
        if (file.empty()) continue;  // the analytic model, built in
        EXPECT_EQ(multibody::engine_plugin_path(name), std::string(VSSW_PLUGIN_OUTPUT_DIR) + "/" + file);
    }
}

TEST(Plugins, ThePluginPathIsSearchedFirst) {
    ::setenv("VSSW_PLUGIN_PATH", "/nowhere/a::/nowhere/b", 1);
    const std::vector<std::string> folders = multibody::plugin_folders();
    ::unsetenv("VSSW_PLUGIN_PATH");
    ASSERT_EQ(folders.size(), 3u);
    EXPECT_EQ(folders[0], "/nowhere/a");
    EXPECT_EQ(folders[1], "/nowhere/b");
    EXPECT_EQ(folders[2], VSSW_PLUGIN_OUTPUT_DIR);
}

TEST(Plugins, AMissingPluginIsBadInputNamingWhatNeedsItAndWhereItLooked) {
    try {
        (void)multibody::open_plugin("vssw_engine_nosuch.so", multibody::kEnginePluginEntry, "engine 'nosuch'");
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(contains(what, "engine 'nosuch'")) << what;
        EXPECT_TRUE(contains(what, "vssw_engine_nosuch.so was not found")) << what;
        EXPECT_TRUE(contains(what, VSSW_PLUGIN_OUTPUT_DIR)) << what;
        EXPECT_TRUE(contains(what, "VSSW_PLUGIN_PATH")) << what;
    }
}

TEST_F(FixturePlugin, AFileThatIsNotALoadableLibraryIsRefusedWithTheLinkersReason) {
    const vssw::testing::TempDir dir;
    std::ofstream(dir / "vssw_engine_broken.so") << "not a shared object\n";
    ::setenv("VSSW_PLUGIN_PATH", dir.path.c_str(), 1);
    try {
        (void)multibody::open_plugin("vssw_engine_broken.so", multibody::kEnginePluginEntry, "engine 'broken'");
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "engine 'broken'")) << e.what();
        EXPECT_TRUE(contains(e.what(), "could not be loaded")) << e.what();
    }
}

// A copy of `from` cut to `length` bytes, as `to`.
void copy_cut(const std::filesystem::path& from, const std::filesystem::path& to, std::uintmax_t length) {
    std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(to, length);
}

std::filesystem::path fixture_file(const std::string& stem) {
    return std::filesystem::path(VSSW_FIXTURE_PLUGIN_DIR) / multibody::plugin_file(stem);
}

// A copy or install that stopped part-way: dlopen would map the missing pages and the first touch would kill the
// process (SIGBUS). Refused before dlopen, at every length that cuts a loadable segment; the whole file passes.
TEST_F(FixturePlugin, ACutShortPluginIsRefusedBeforeItIsOpened) {
    const vssw::testing::TempDir dir;
    const std::filesystem::path whole = fixture_file("vssw_fixture");
    const std::uintmax_t size = std::filesystem::file_size(whole);
    copy_cut(whole, dir / "whole.so", size);
    EXPECT_EQ(multibody::plugin_file_problem((dir / "whole.so").string()), "");
    ::setenv("VSSW_PLUGIN_PATH", dir.path.c_str(), 1);
    for (const std::uintmax_t length : {std::uintmax_t{1000}, std::uintmax_t{4096}, size / 2}) {
        copy_cut(whole, dir / "vssw_engine_cut.so", length);
        try {
            (void)multibody::open_plugin("vssw_engine_cut.so", multibody::kEnginePluginEntry, "engine 'cut'");
            ADD_FAILURE() << "no InputError at " << length << " bytes";
        } catch (const InputError& e) {
            const std::string path = (dir / "vssw_engine_cut.so").string();
            EXPECT_TRUE(contains(e.what(), path + " could not be loaded: the file is cut short")) << e.what();
            EXPECT_TRUE(contains(e.what(), "it has " + std::to_string(length) + " bytes")) << e.what();
        }
    }
    EXPECT_FALSE(contains(mapped_files(), "vssw_engine_cut.so"));
}

// A name in a folder searched first that is not a plugin file is an error naming it: never a reason to run on the
// plugin of the same name in a later folder.
TEST_F(FixturePlugin, ANameThatIsNotAFileIsAnErrorNotAReasonToLookFurther) {
    const vssw::testing::TempDir pointed("pointed"), later("later");
    const std::string file = "vssw_engine_pointed.so";
    std::filesystem::copy_file(fixture_file("vssw_fixture"), later / file);
    ::setenv("VSSW_PLUGIN_PATH", (pointed.path.string() + ":" + later.path.string()).c_str(), 1);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"dangling", "it is a symbolic link to /nowhere/" + file + ", which does not exist"},
        {"loop", "it is a loop of symbolic links"},
        {"directory", "it is a directory"},
        {"device", "it is not a regular file"}};
    for (const auto& [kind, why] : cases) {
        std::filesystem::remove_all(pointed / file);
        if (kind == "dangling") std::filesystem::create_symlink("/nowhere/" + file, pointed / file);
        if (kind == "loop") std::filesystem::create_symlink(pointed / file, pointed / file);
        if (kind == "directory") std::filesystem::create_directory(pointed / file);
        if (kind == "device") std::filesystem::create_symlink("/dev/zero", pointed / file);
        try {
            (void)multibody::open_plugin(file, multibody::kEnginePluginEntry, "engine 'pointed'");
            ADD_FAILURE() << kind << ": opened " << (later / file).string();
        } catch (const InputError& e) {
            EXPECT_TRUE(contains(e.what(), (pointed / file).string() + " could not be loaded: " + why)) << e.what();
        }
    }
    // The case the check must pass: nothing of that name in the first folder, the later one's is used.
    std::filesystem::remove_all(pointed / file);
    EXPECT_EQ(multibody::find_plugin(file), (later / file).string());
}

TEST_F(FixturePlugin, APluginWithoutADescriptionIsRefused) {
    try {
        (void)open("vssw_fixture_no_description");
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "vssw_fixture_no_description.so is broken: its entry point "
                                       "vssw_engine_plugin_v1 gave no description"))
            << e.what();
    }
}

// The same through the registry and the program, as an engine's plugin: exit 2 with one line, never a crash, and the
// version still printed, saying why. Each case as the plugin of another engine (a plugin is opened once per process,
// by its file name), all in the folder searched first.
TEST_F(FixturePlugin, ABrokenEnginePluginIsBadInputInTheProgram) {
    struct Broken {
        std::string engine, copied_from, why;
        bool cut_in_half;
    };
    const std::string built = VSSW_PLUGIN_OUTPUT_DIR;
    const std::vector<Broken> cases = {
        {"ode", fixture_file("vssw_fixture_no_description").string(), "gave no description", false},
        {"bullet", fixture_file("vssw_fixture_no_engines").string(), "its description lists 3 engines it does not give",
         false},
        {"box2d", built + "/vssw_engine_box2d.so", "the file is cut short", true}};
    const std::string maps = mapped_files();
    const vssw::testing::TempDir dir;
    ::setenv("VSSW_PLUGIN_PATH", dir.path.c_str(), 1);
    for (const Broken& c : cases) {
        const std::string file = "vssw_engine_" + c.engine + ".so";
        if (!vssw::testing::engine_available(c.engine) || contains(maps, file))
            GTEST_SKIP() << c.engine << " not built, or its plugin is open already (run this test alone)";
        const std::uintmax_t whole = std::filesystem::file_size(c.copied_from);
        copy_cut(c.copied_from, dir / file, c.cut_in_half ? whole / 2 : whole);
    }
    for (const Broken& c : cases) {
        const auto compare =
            run_cli({"compare", "--engine", c.engine, "--height", "4", "--thickness", "0.4", "--hinge", "0.7"});
        EXPECT_EQ(compare.code, 2) << compare.err;
        EXPECT_EQ(compare.err.rfind("vssw: error: engine '" + c.engine + "': ", 0), 0u) << compare.err;
        EXPECT_EQ(std::count(compare.err.begin(), compare.err.end(), '\n'), 1) << compare.err;
        EXPECT_TRUE(contains(compare.err, c.why)) << compare.err;
    }
    const auto version = run_cli({"--version"});
    EXPECT_EQ(version.code, 0) << version.err;
    for (const Broken& c : cases) {
        EXPECT_TRUE(contains(version.out, "not available: engine '" + c.engine + "': ")) << version.out;
        EXPECT_TRUE(contains(version.out, c.why)) << version.out;
    }
}

TEST_F(FixturePlugin, ALibraryWithoutTheEntryPointIsRefused) {
    try {
        (void)multibody::open_plugin("vssw_fixture.so", "vssw_engine_plugin_v999", "the fixture");
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "is not a vssw plugin of this version")) << e.what();
    }
}

TEST_F(FixturePlugin, APluginOfAnotherBuildIsRefusedSayingSo) {
    try {
        (void)open("vssw_fixture_other_build");
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "is from another build (another build of vssw;")) << e.what();
        EXPECT_TRUE(contains(e.what(), multibody::program_build_id())) << e.what();
    }
}

TEST_F(FixturePlugin, APluginOfAnotherInterfaceVersionIsRefusedSayingSo) {
    try {
        (void)open("vssw_fixture_other_abi");
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "has interface version 999")) << e.what();
    }
}

// Each plugin holds its own copy of the exception types (its symbols are hidden): the program still catches them by
// type, in its own process and from a worker child (the isolation every engine run goes through).
TEST_F(FixturePlugin, ExceptionsThrownInAPluginAreCaughtByTypeInTheProgram) {
    EXPECT_THROW(engine("input_error")->check_settings({}), InputError);
    EXPECT_THROW(run(*engine("input_error")), InputError);
    EXPECT_THROW(run(*engine("engine_failure")), EngineFailure);
    try {
        run(*engine("runtime_error"));
        FAIL() << "no exception";
    } catch (const InputError&) {
        FAIL() << "a std::runtime_error caught as an InputError";
    } catch (const EngineFailure&) {
        FAIL() << "a std::runtime_error caught as an EngineFailure";
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(contains(e.what(), "a std::runtime_error from a plugin")) << e.what();
    }
    EXPECT_THROW(run(*multibody::isolated(engine("input_error"))), InputError);
    EXPECT_THROW(run(*multibody::isolated(engine("engine_failure"))), EngineFailure);
    EXPECT_THROW(run(*multibody::isolated(engine("runtime_error"))), std::runtime_error);
}

// The same for the real plugins: a setting an adapter refuses is an InputError thrown inside its plugin.
TEST(Plugins, AnAdaptersRefusalIsAnInputErrorInTheProgram) {
    for (const std::string& name : multibody::available_engines()) {
        if (name == "analytic") continue;
        multibody::EngineSettings settings;
        settings.knobs["no_such_setting"] = 1.0;
        EXPECT_THROW(multibody::make_engine_in_process(name)->check_settings(settings), InputError) << name;
        EXPECT_THROW(multibody::make_engine(name)->check_settings(settings), InputError) << name;
    }
}

}  // namespace

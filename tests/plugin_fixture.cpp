// An engine plugin for the loader's tests (test_plugins.cpp), built as the real ones are (cmake/plugins.cmake: every
// symbol hidden but the entry point) and five times over (tests/CMakeLists.txt): as this build's, as another build's
// (VSSW_FIXTURE_BUILD_ID), with another interface version (VSSW_FIXTURE_ABI), and broken: no description
// (VSSW_FIXTURE_NO_DESCRIPTION) or engines counted but not listed (VSSW_FIXTURE_NO_ENGINES). Its engines throw, from inside the
// plugin, each kind of exception the program catches by type: the tests check that the program still does.
#include <stdexcept>

#include "analytic/error.hpp"
#include "multibody/engine_plugin.hpp"

namespace {

using namespace vssw::multibody;

enum class Throws { input_error, engine_failure, runtime_error };

template <Throws kind>
class ThrowingEngine final : public Engine {
public:
    std::string name() const override { return "fixture"; }
    std::string version() const override { return "fixture 1"; }
    EngineSettings default_settings() const override { return {}; }
    std::vector<SettingDescription> setting_descriptions() const override { return {}; }
    Trajectory simulate(const WallScene&, const Excitation&, const EngineSettings&) const override { fail(); }
    void check_settings(const EngineSettings&) const override { fail(); }
    double cost_per_simulated_second() const override { return 1e-3; }

private:
    [[noreturn]] static void fail() {
        if constexpr (kind == Throws::input_error) throw vssw::InputError("fixture: an InputError from a plugin");
        if constexpr (kind == Throws::engine_failure) throw EngineFailure("fixture: an EngineFailure from a plugin");
        throw std::runtime_error("fixture: a std::runtime_error from a plugin");
    }
};

template <Throws kind>
std::unique_ptr<Engine> make() {
    return std::make_unique<ThrowingEngine<kind>>();
}

}  // namespace

#if defined(VSSW_FIXTURE_NO_DESCRIPTION)
// A broken plugin: its entry point gives no description.
extern "C" __attribute__((visibility("default"))) const EnginePlugin* vssw_engine_plugin_v1() { return nullptr; }
#elif defined(VSSW_FIXTURE_NO_ENGINES)
// A broken plugin: its description counts engines it does not list.
extern "C" __attribute__((visibility("default"))) const EnginePlugin* vssw_engine_plugin_v1() {
    static const EnginePlugin plugin{kEnginePluginAbi, VSSW_BUILD_ID, nullptr, 3};
    return &plugin;
}
#elif defined(VSSW_FIXTURE_BUILD_ID) || defined(VSSW_FIXTURE_ABI)
#ifndef VSSW_FIXTURE_BUILD_ID
#define VSSW_FIXTURE_BUILD_ID VSSW_BUILD_ID
#endif
#ifndef VSSW_FIXTURE_ABI
#define VSSW_FIXTURE_ABI kEnginePluginAbi
#endif
extern "C" __attribute__((visibility("default"))) const EnginePlugin* vssw_engine_plugin_v1() {
    static const PluginEngine engines[] = {{"input_error", &make<Throws::input_error>}};
    static const EnginePlugin plugin{VSSW_FIXTURE_ABI, VSSW_FIXTURE_BUILD_ID, engines, std::size(engines)};
    return &plugin;
}
#else
VSSW_ENGINE_PLUGIN({"input_error", &make<Throws::input_error>}, {"engine_failure", &make<Throws::engine_failure>},
                   {"runtime_error", &make<Throws::runtime_error>})
#endif

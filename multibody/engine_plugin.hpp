#pragma once
// What an engine plugin exports (docs/architecture.md, "Plugins"; docs/contributing/engines.md, "Adding an engine").
// Each engine library's adapter is a shared module of its own (vssw_engine_<plugin>.so), opened by the program only
// when a run needs that engine (registry.cpp, plugin_loader.hpp), so that a process that runs none (vssw free, vssw
// wall, the analytic model) does not load Simbody, Siconos, Bullet, ODE and the dozens of libraries they bring.
//
// The plugin exports one symbol, kEnginePluginEntry, with C linkage (its name is not mangled, so dlsym finds it by
// name), returning the description below. The types it hands over (Engine, WallScene, EngineSettings, ...) are C++
// classes of this build: host and plugin must come from the same build, which `abi` and `build_id` check before
// anything else in the description is read. Every plugin defines its entry point with VSSW_ENGINE_PLUGIN:
//
//     VSSW_ENGINE_PLUGIN({"bullet", &vssw::multibody::make_bullet_engine})
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>

#include "multibody/engine.hpp"
#include "vssw_build_id.hpp"  // VSSW_BUILD_ID, this build's identity (written by the top CMakeLists.txt)

namespace vssw::multibody {

// The layout of EnginePlugin below. Raise it (and the 1 in the entry point's name) when that layout changes: a plugin
// of another layout is then refused by its number, before its fields are read. Changes to the C++ types the plugin
// hands over are caught by build_id instead.
inline constexpr std::uint32_t kEnginePluginAbi = 1;
inline constexpr const char* kEnginePluginEntry = "vssw_engine_plugin_v1";

// One backend of a plugin: the name `--engine` takes and the adapter's factory (the one make_engine_in_process calls).
struct PluginEngine {
    const char* name;
    std::unique_ptr<Engine> (*make)();
};

struct EnginePlugin {
    // First, and never moved: the loader reads these two before anything else.
    std::uint32_t abi;     // kEnginePluginAbi of the plugin's build
    const char* build_id;  // VSSW_BUILD_ID of the plugin's build; must equal the program's
    const PluginEngine* engines;
    std::size_t engine_count;
};

}  // namespace vssw::multibody

// The entry point, exported with default visibility (plugins are built with every other symbol hidden).
#define VSSW_ENGINE_PLUGIN(...)                                                                                        \
    extern "C" __attribute__((visibility("default"))) const ::vssw::multibody::EnginePlugin* vssw_engine_plugin_v1() { \
        static const ::vssw::multibody::PluginEngine engines[] = {__VA_ARGS__};                                       \
        static const ::vssw::multibody::EnginePlugin plugin{::vssw::multibody::kEnginePluginAbi, VSSW_BUILD_ID,       \
                                                            engines, std::size(engines)};                              \
        return &plugin;                                                                                                \
    }

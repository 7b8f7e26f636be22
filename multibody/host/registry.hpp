#pragma once
// Where the engines' adapters live (beyond engine.hpp's make_engine and available_engines): every engine but the
// analytic model is a plugin of its own, opened when a run needs it (engine_plugin.hpp, plugin_loader.hpp).
#include <optional>
#include <string>

namespace vssw::multibody {

// The plugin file of an engine this build has ("vssw_engine_simbody.so" for simbody and simbody-rigid); "" for the
// analytic model, which is built in. Opens nothing.
std::string engine_plugin_file(const std::string& name);

// Where that plugin was opened from, opening it if it is not yet (vssw --version). Throws InputError as
// make_engine_in_process does when it cannot be found or opened.
std::string engine_plugin_path(const std::string& name);

// An engine's version as recorded when its plugin was built (plugin_versions.hpp), and where that plugin is: read
// without opening it. nullopt for the analytic model and when the plugin is not found, is unfit to open
// (plugin_file_check.hpp) or has no record that is its own: then only opening it (make_engine_in_process) says its
// version, or why it has none.
struct RecordedVersion {
    std::string version, plugin_path;
};
std::optional<RecordedVersion> recorded_engine_version(const std::string& name);

}  // namespace vssw::multibody

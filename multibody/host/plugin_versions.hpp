#pragma once
// Each engine plugin's engine versions, recorded when the plugin is built, so that `vssw --version` names them without
// opening the plugins (opening every engine's plugin loads some 60 shared objects: docs/architecture.md, "Plugins").
// The build runs record_plugin_versions.cpp on each plugin it links, which opens it as a run would and writes what its
// adapters' version() says into a text file beside it (vssw_engine_ode.versions beside vssw_engine_ode.so), installed
// with it. The record names the plugin by the GNU build-id its linker wrote (plugin_file_check.hpp), and this program's
// build by VSSW_BUILD_ID: a plugin rebuilt, replaced or copied from elsewhere without its record, or a record of
// another build, is not the plugin's, and the caller opens the plugin instead (registry.hpp, recorded_engine_version).
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vssw::multibody {

// The record's file for the plugin at `plugin_path`: the same name with ".versions" for ".so".
std::string plugin_versions_file(const std::string& plugin_path);

// The record's text for the plugin at `plugin_path` whose engines say `versions` ({name, version}, in order): its
// build-id, this program's VSSW_BUILD_ID and one line per engine. Throws std::runtime_error when the plugin has no
// build-id, or a name or version holds a tab or a line break (the record's separators).
std::string plugin_versions_text(const std::string& plugin_path,
                                 const std::vector<std::pair<std::string, std::string>>& versions);

// The versions recorded for the plugin at `plugin_path`, by engine name; empty when there is no record, it cannot be
// read, or it is not this plugin's (another build-id) or not this program's build's.
std::map<std::string, std::string> recorded_versions(const std::string& plugin_path);

}  // namespace vssw::multibody

#pragma once
// Finding and opening the program's plugins: the engine adapters (engine_plugin.hpp, opened by registry.cpp) and the
// MPI module (study/mpi.cpp). How they are found and why each is opened in a namespace of its own:
// docs/architecture.md, "Plugins".
//
// The folders searched, in order:
//  1. each folder of the environment variable VSSW_PLUGIN_PATH (separated by ':'), when set: a user's own build of a
//     plugin, or plugins kept elsewhere;
//  2. beside the binary that holds this code (the vssw program, a test program, or the Python module `vssw._core`,
//     located with dladdr, so that each finds its own plugins whatever started it):
//     - in the build tree that built it: the build's plugins/ folder (build/plugins), so that the programs, tests and
//       Python module of a build run on that build's plugins without any set-up;
//     - anywhere else (installed): <prefix>/lib/vssw/plugins, found from <prefix>/bin (the installed layout,
//       GNUInstallDirs), then the plugins folder under the install prefix configured at build time (the installed
//       Python module, which lives under Python's own folders).
// The first folder holding the file is used: a plugin found there that cannot be loaded or comes from another build is
// an error, not a reason to look further (the user would otherwise run on a plugin other than the one they pointed to).
#include <cstdint>
#include <string>
#include <vector>

namespace vssw::multibody {

// The folders above, in search order, each once.
std::vector<std::string> plugin_folders();

// "vssw_engine_ode.so" for "vssw_engine_ode": the file a plugin target builds (CMake's MODULE libraries, no "lib").
std::string plugin_file(const std::string& stem);

// The path of `file` in the first of plugin_folders() that holds a name `file` of any kind (a dangling symbolic link,
// a directory: open_plugin says what is wrong with it); "" when none does. Opens nothing.
std::string find_plugin(const std::string& file);

// A plugin opened: where it was found and its entry point.
struct OpenedPlugin {
    std::string path;
    void* entry = nullptr;
};

// Finds `file` in plugin_folders(), opens it with dlopen(RTLD_NOW | RTLD_LOCAL) and returns the address of its entry
// point `entry`, once per process (a later call returns what the first one found). `what` names what needs the plugin
// in messages ("engine 'ode'", "MPI"). Throws InputError naming `what` and the file: not found (with the folders
// searched), not a regular file, cut short (a loadable segment past its end: checked before dlopen, which would map
// it and crash on first touch; plugin_file_check.hpp), not loadable (the dynamic linker's reason: a library it needs
// is missing, say), or without `entry` (not a plugin of this interface). A plugin is never closed: the engines it makes and the code they run must outlive every
// caller. Safe to call from several threads, and in a forked child of a multi-threaded process (a fork waits for a
// plugin being opened to be open).
OpenedPlugin open_plugin(const std::string& file, const char* entry, const std::string& what);

// What the plugin's entry point returns (its description, a static of the plugin's), or an InputError naming `what`
// and the plugin when it returns none. `entry` is the entry point's name, for the message.
template <class Description>
const Description& plugin_description(const OpenedPlugin& plugin, const std::string& what, const char* entry);
[[noreturn]] void refuse_missing_description(const OpenedPlugin& plugin, const std::string& what, const char* entry);

// Throws InputError naming `what` and the plugin's path unless the plugin's layout number and build identity are this
// program's: a plugin of another build hands over C++ types whose layout may differ from the program's.
void check_plugin_build(const OpenedPlugin& plugin, const std::string& what, std::uint32_t plugin_abi,
                        std::uint32_t program_abi, const char* plugin_build_id);

// VSSW_BUILD_ID of this program's build ("vssw X.Y.Z, GNU 12.2.0, Release, build 3f0c...").
const char* program_build_id();

template <class Description>
const Description& plugin_description(const OpenedPlugin& plugin, const std::string& what, const char* entry) {
    const Description* description = reinterpret_cast<const Description* (*)()>(plugin.entry)();
    if (!description) refuse_missing_description(plugin, what, entry);
    return *description;
}

}  // namespace vssw::multibody

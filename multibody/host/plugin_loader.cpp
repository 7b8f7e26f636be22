#include "multibody/host/plugin_loader.hpp"

#include <dlfcn.h>
#include <link.h>
#include <pthread.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/host/plugin_file_check.hpp"
#include "vssw_build_id.hpp"  // VSSW_BUILD_ID (the top CMakeLists.txt)

// Fixed at build time (multibody/CMakeLists.txt): the build tree, its plugins folder, the installed plugins folder
// relative to the installed program's folder, and the same folder under the configured install prefix.
#if !defined(VSSW_PLUGIN_BUILD_TREE) || !defined(VSSW_PLUGIN_BUILD_DIR) || !defined(VSSW_PLUGIN_DIR_FROM_BINDIR) || \
    !defined(VSSW_PLUGIN_INSTALL_DIR)
#error "the plugin folders are defined by multibody/CMakeLists.txt"
#endif

namespace vssw::multibody {
namespace {

namespace fs = std::filesystem;

// Any object of this library: dladdr on its address names the binary (program or shared module) that holds it.
const char g_located_by_address = 0;

// The binary holding this code: the program itself, or the shared module it is linked into (the Python module).
fs::path holding_binary() {
    Dl_info info{};
    link_map* map = nullptr;
    if (::dladdr1(&g_located_by_address, &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) != 0 && map &&
        map->l_name && *map->l_name) {
        std::error_code ec;
        const fs::path module = fs::absolute(map->l_name, ec);
        if (!ec) return module;
    }
    // The main program: the dynamic linker's name for it is empty (or argv[0], which need not be a path).
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : program;
}

bool is_within(const fs::path& inner, const fs::path& outer) {
    std::error_code ec1, ec2;
    const fs::path a = fs::weakly_canonical(inner, ec1), b = fs::weakly_canonical(outer, ec2);
    if (ec1 || ec2 || b.empty()) return false;
    // Component by component: /work/build2 is not within /work/build.
    return std::mismatch(b.begin(), b.end(), a.begin(), a.end()).first == b.end();
}

// Opening a plugin takes this lock, and so does fork (held from the fork's start to its end in parent and child): a
// child forked while another thread opens a plugin would otherwise hold a copy of the lock that nobody releases, and
// the worker children of stress/ open plugins themselves (stress/run.cpp).
std::mutex g_opening;
void hold_across_fork() {
    static std::once_flag once;
    std::call_once(once, [] {
        (void)::pthread_atfork([] { g_opening.lock(); }, [] { g_opening.unlock(); }, [] { g_opening.unlock(); });
    });
}

}  // namespace

std::vector<std::string> plugin_folders() {
    std::vector<std::string> folders;
    const auto add = [&](const fs::path& folder) {
        const std::string f = folder.lexically_normal().string();
        if (!f.empty() && std::find(folders.begin(), folders.end(), f) == folders.end()) folders.push_back(f);
    };
    if (const char* path = std::getenv("VSSW_PLUGIN_PATH")) {
        const std::string list = path;
        for (std::size_t start = 0; start <= list.size();) {
            const std::size_t end = std::min(list.find(':', start), list.size());
            if (end > start) add(fs::absolute(list.substr(start, end - start)));
            start = end + 1;
        }
    }
    const fs::path holder = holding_binary();
    if (!holder.empty() && is_within(holder, VSSW_PLUGIN_BUILD_TREE)) {
        add(VSSW_PLUGIN_BUILD_DIR);
    } else {
        if (!holder.empty()) add(holder.parent_path() / VSSW_PLUGIN_DIR_FROM_BINDIR);
        add(VSSW_PLUGIN_INSTALL_DIR);
    }
    return folders;
}

std::string plugin_file(const std::string& stem) { return stem + ".so"; }

std::string find_plugin(const std::string& file) {
    for (const std::string& folder : plugin_folders()) {
        const fs::path candidate = fs::path(folder) / file;
        // Any name there, whatever it is (a dangling symbolic link, a directory): not a reason to look further.
        struct stat entry {};
        if (::lstat(candidate.c_str(), &entry) == 0 || (errno != ENOENT && errno != ENOTDIR)) return candidate.string();
    }
    return "";
}

OpenedPlugin open_plugin(const std::string& file, const char* entry, const std::string& what) {
    hold_across_fork();
    const std::lock_guard<std::mutex> lock(g_opening);
    static std::map<std::string, OpenedPlugin> opened;  // by file and entry point: each plugin opened once
    const std::string key = file + '\n' + entry;
    if (const auto it = opened.find(key); it != opened.end()) return it->second;
    OpenedPlugin plugin;
    plugin.path = find_plugin(file);
    if (plugin.path.empty())
        throw InputError(fmt::format("{}: its plugin {} was not found (looked in {}; the environment variable "
                                     "VSSW_PLUGIN_PATH names more folders to look in first)",
                                     what, file, fmt::join(plugin_folders(), ", ")));
    // Before dlopen, which would map a cut-short file's missing pages (SIGBUS on first touch, in this process).
    if (const std::string why = plugin_file_problem(plugin.path); !why.empty())
        throw InputError(fmt::format("{}: its plugin {} could not be loaded: {} (plugins in later folders are not "
                                     "looked at: mend or remove it)",
                                     what, plugin.path, why));
    // RTLD_NOW: a library the plugin needs that is missing or lacks a symbol is reported here, by name, not as a crash
    // in the middle of a run. RTLD_LOCAL: the plugin's symbols and its engine library's stay out of the global
    // namespace, so that no other plugin or library binds to them (docs/architecture.md, "Plugins").
    void* handle = ::dlopen(plugin.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = ::dlerror();
        throw InputError(fmt::format("{}: its plugin {} could not be loaded: {}", what, plugin.path,
                                     why ? why : "no reason given"));
    }
    plugin.entry = ::dlsym(handle, entry);
    if (!plugin.entry)
        throw InputError(fmt::format("{}: {} is not a vssw plugin of this version (it has no entry point {})", what,
                                     plugin.path, entry));
    opened.emplace(key, plugin);
    return plugin;
}

void refuse_missing_description(const OpenedPlugin& plugin, const std::string& what, const char* entry) {
    throw InputError(fmt::format("{}: the plugin {} is broken: its entry point {} gave no description", what,
                                 plugin.path, entry));
}

void check_plugin_build(const OpenedPlugin& plugin, const std::string& what, std::uint32_t plugin_abi,
                        std::uint32_t program_abi, const char* plugin_build_id) {
    if (plugin_abi != program_abi)
        throw InputError(fmt::format("{}: the plugin {} has interface version {}, this program {}: use the plugins "
                                     "built with this program",
                                     what, plugin.path, plugin_abi, program_abi));
    const std::string built_by = plugin_build_id ? plugin_build_id : "";
    if (built_by != program_build_id())
        throw InputError(fmt::format("{}: the plugin {} is from another build ({}; this program: {}): use the plugins "
                                     "built with this program (rebuild, or install them together)",
                                     what, plugin.path, built_by, program_build_id()));
}

const char* program_build_id() { return VSSW_BUILD_ID; }

}  // namespace vssw::multibody

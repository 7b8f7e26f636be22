#include "cli/version_text.hpp"

#include <exception>
#include <vector>

#include <fmt/format.h>

#include "cli/build_commit.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/registry.hpp"
#include "study/mpi.hpp"

namespace vssw::cli {

std::string version_text() {
    const std::string commit = build_commit();
    std::string text = fmt::format("vssw {} ({})\n", VSSW_VERSION,
                                   commit.empty() ? "built outside a git checkout" : "commit " + commit);
    // Each engine's version as recorded beside its plugin when the plugin was built, read without opening it; where
    // that record is missing or not the plugin's, from its adapter, which opens the plugin: a plugin that cannot be
    // opened is said in its place (the version stays printable whatever is missing).
    text += "backends in this build:\n";
    std::vector<std::string> plugin_lines;
    for (const std::string& name : multibody::available_engines()) {
        std::string version, where;
        try {
            if (const auto recorded = multibody::recorded_engine_version(name)) {
                version = recorded->version;
                where = recorded->plugin_path;
            } else {
                version = multibody::make_engine_in_process(name)->version();
                where = multibody::engine_plugin_path(name);
            }
        } catch (const std::exception& e) {
            version = fmt::format("not available: {}", e.what());
        }
        text += fmt::format("  {:<14} {}\n", name, version);
        if (!where.empty()) plugin_lines.push_back(fmt::format("  {:<14} {}\n", name, where));
    }
    const std::vector<std::string> missing = multibody::missing_engines();
    if (!missing.empty())
        text += fmt::format("not in this build (not found at configure time): {}\n", fmt::join(missing, ", "));
    // Where the plugins were found (multibody/host/plugin_loader.hpp); MPI's is only looked for, not opened (that would
    // load libmpi).
    if (study::mpi_built()) {
        const std::string mpi = study::mpi_module_path();
        plugin_lines.push_back(fmt::format("  {:<14} {}\n", "MPI", mpi.empty() ? "vssw_mpi.so not found" : mpi));
    }
    if (!plugin_lines.empty()) {
        text += "plugins (each opened only when a run needs it):\n";
        for (const std::string& line : plugin_lines) text += line;
    }
    return text;
}

}  // namespace vssw::cli

// record_plugin_versions FOLDER PLUGIN: run by the build on each engine plugin it links (multibody/CMakeLists.txt),
// it opens FOLDER/PLUGIN as a run would, asks each of its engines' adapters for its version and writes them beside
// it (plugin_versions.hpp), so that `vssw --version` reads them without opening the plugin. A plugin that cannot be
// opened fails the build here, saying why, rather than every later `vssw --version`.
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "multibody/engine.hpp"
#include "multibody/host/plugin_loader.hpp"
#include "multibody/host/plugin_versions.hpp"
#include "multibody/host/registry.hpp"

namespace {

namespace fs = std::filesystem;
using namespace vssw::multibody;

void record(const std::string& folder, const std::string& file) {
    // That folder first, whatever the environment names, so that the plugin opened is the one just built.
    ::setenv("VSSW_PLUGIN_PATH", folder.c_str(), 1);
    const std::string path = find_plugin(file);
    if (path != (fs::path(folder) / file).string()) throw std::runtime_error(file + " not found in " + folder);
    std::vector<std::pair<std::string, std::string>> versions;
    for (const std::string& name : available_engines())
        if (engine_plugin_file(name) == file) versions.emplace_back(name, make_engine_in_process(name)->version());
    if (versions.empty()) throw std::runtime_error(file + " holds none of this build's engines");
    // Written aside and renamed over the record, so that a failed write leaves no half record.
    // The text first: a version it refuses (a tab or a line break in it) leaves no file at all.
    const std::string text = plugin_versions_text(path, versions);
    const std::string target = plugin_versions_file(path), aside = target + ".part";
    std::ofstream out(aside);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("could not write " + aside);
    fs::rename(aside, target);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: record_plugin_versions FOLDER PLUGIN\n";
        return 2;
    }
    try {
        record(argv[1], argv[2]);
    } catch (const std::exception& e) {
        std::cerr << "record_plugin_versions: " << argv[2] << ": " << e.what() << "\n";
        return 1;
    }
    return 0;
}

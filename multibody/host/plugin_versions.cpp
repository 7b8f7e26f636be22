#include "multibody/host/plugin_versions.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "multibody/host/plugin_file_check.hpp"
#include "multibody/host/plugin_loader.hpp"

namespace vssw::multibody {
namespace {

// The record's first line: what the file is and its layout's number (raise it when the layout changes).
constexpr const char* kRecordHeading = "vssw plugin versions 1";

bool holds_separator(const std::string& text) { return text.find_first_of("\t\n\r") != std::string::npos; }

}  // namespace

std::string plugin_versions_file(const std::string& plugin_path) {
    const std::string so = ".so";
    const bool named_so = plugin_path.size() >= so.size() && plugin_path.compare(plugin_path.size() - so.size(), so.size(), so) == 0;
    return (named_so ? plugin_path.substr(0, plugin_path.size() - so.size()) : plugin_path) + ".versions";
}

std::string plugin_versions_text(const std::string& plugin_path,
                                 const std::vector<std::pair<std::string, std::string>>& versions) {
    const std::string id = plugin_build_note(plugin_path);
    if (id.empty())
        throw std::runtime_error(plugin_path + " has no GNU build-id (link it with -Wl,--build-id)");
    std::string text = std::string(kRecordHeading) + "\nplugin\t" + id + "\nbuild\t" + program_build_id() + "\n";
    for (const auto& [name, version] : versions) {
        if (holds_separator(name) || holds_separator(version))
            throw std::runtime_error(plugin_path + ": the engine '" + name + "' or its version holds a tab or a line break");
        text += "engine\t" + name + "\t" + version + "\n";
    }
    return text;
}

std::map<std::string, std::string> recorded_versions(const std::string& plugin_path) {
    std::ifstream file(plugin_versions_file(plugin_path));
    std::string heading, line;
    if (!std::getline(file, heading) || heading != kRecordHeading) return {};
    const std::string id = plugin_build_note(plugin_path);
    bool plugin_matches = false, build_matches = false;
    std::map<std::string, std::string> versions;
    while (std::getline(file, line)) {
        std::istringstream fields(line);
        std::string key, value, version;
        if (!std::getline(fields, key, '\t') || !std::getline(fields, value, '\t')) return {};
        if (key == "plugin") plugin_matches = !id.empty() && value == id;
        else if (key == "build") build_matches = value == program_build_id();
        else if (key == "engine" && std::getline(fields, version)) versions[value] = version;
        else return {};
    }
    if (!file.eof() || !plugin_matches || !build_matches) return {};
    return versions;
}

}  // namespace vssw::multibody

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "multibody/engine_plugin.hpp"
#include "multibody/host/isolated_engine.hpp"
#include "multibody/host/plugin_file_check.hpp"
#include "multibody/host/plugin_loader.hpp"
#include "multibody/host/plugin_versions.hpp"
#include "multibody/host/engine_names.hpp"
#include "multibody/host/registry.hpp"
#include "vssw_engine_facts.hpp"  // kEngineFacts (generated: cmake/engines.cmake)

namespace vssw::multibody {

namespace {

// Every backend this code knows, in listing order, with its display name (the adapter's own: the test
// Plugins.DisplayNamesAreTheAdapters holds them), the plugin that holds its adapter and whether this build has it:
// generated from each engine folder's engine.cmake. available_engines(), missing_engines() and engine_display_name()
// read this table alone, so that naming the engines loads no plugin.
using KnownEngine = EngineFacts;
constexpr const auto& kKnownEngines = kEngineFacts;

std::vector<std::string> known_engines(bool built) {
    std::vector<std::string> names;
    for (const KnownEngine& e : kKnownEngines)
        if (e.built == built) names.push_back(e.name);
    return names;
}

// The name folded for a loose comparison: lower case, '_' as '-' (names are ASCII; anything else stays as it is).
std::string folded(std::string name) {
    for (char& c : name) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        else if (c == '_') c = '-';
    }
    return name;
}

// The backend of this build a name means (canonical_engine), or null.
const KnownEngine* built_engine(const std::string& name) {
    for (const KnownEngine& e : kKnownEngines)
        if (e.built && name == e.name) return &e;
    const std::string loose = folded(name);
    for (const KnownEngine& e : kKnownEngines)
        if (e.built && (loose == folded(e.name) || loose == folded(e.display_name))) return &e;
    return nullptr;
}

std::string plugin_file_of(const KnownEngine& engine) {
    return plugin_file(std::string("vssw_engine_") + engine.plugin);
}

const KnownEngine& require_built(const std::string& name) {
    const KnownEngine* known = built_engine(name);
    if (!known)
        throw InputError(fmt::format("engine '{}' is not available in this build{} (available: {})", name,
                                     engine_name_hint(name), fmt::join(available_engines(), ", ")));
    return *known;
}

// A list of engines that cannot be read (none where some are counted, one without a name or a factory) refused: the
// loader would follow its pointers. Bounded, so that a count read from a broken description is not trusted.
void check_engine_list(const OpenedPlugin& plugin, const std::string& what, const EnginePlugin& description) {
    constexpr std::size_t kMostEnginesInAPlugin = 64;  // the real plugins hold one or two
    bool readable = description.engine_count <= kMostEnginesInAPlugin &&
                    (description.engines != nullptr || description.engine_count == 0);
    for (std::size_t i = 0; readable && i < description.engine_count; ++i)
        readable = description.engines[i].name != nullptr && description.engines[i].make != nullptr;
    if (!readable)
        throw InputError(fmt::format("{}: the plugin {} is broken: its description lists {} engines it does not give "
                                     "(a name or a factory missing)",
                                     what, plugin.path, description.engine_count));
}

// The plugin holding an engine, checked to be of this build (open_plugin opens each once per process). Its path in
// `path` when asked.
const EnginePlugin& engine_plugin(const KnownEngine& engine, std::string* path = nullptr) {
    const std::string what = fmt::format("engine '{}'", engine.name);
    const OpenedPlugin plugin = open_plugin(plugin_file_of(engine), kEnginePluginEntry, what);
    const EnginePlugin& description = plugin_description<EnginePlugin>(plugin, what, kEnginePluginEntry);
    check_plugin_build(plugin, what, description.abi, kEnginePluginAbi, description.build_id);
    check_engine_list(plugin, what, description);
    if (path) *path = plugin.path;
    return description;
}

}  // namespace

std::vector<std::string> available_engines() { return known_engines(true); }

std::vector<std::string> missing_engines() { return known_engines(false); }

std::vector<std::string> default_compared_engines() {
    std::vector<std::string> engines;
    for (const KnownEngine& e : kKnownEngines)
        if (e.built && e.default_compared) engines.push_back(e.name);
    return engines;
}

std::string engine_display_name(const std::string& name) {
    const KnownEngine* e = built_engine(name);
    return e ? e->display_name : name;
}

std::optional<std::string> canonical_engine(const std::string& name) {
    const KnownEngine* e = built_engine(name);
    return e ? std::optional<std::string>(e->name) : std::nullopt;
}

namespace {

// A name this far from a backend's (letters inserted, removed or changed, after folding) is taken as a slip of the
// keyboard ("mujuco", "bulet"), one slip per kLettersPerSlip letters of the name at most ("warp" is no slip of "dart");
// farther, no backend is suggested.
constexpr std::size_t kSuggestedDistance = 2;
constexpr std::size_t kLettersPerSlip = 3;

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string engine_name_hint(const std::string& name) {
    if (built_engine(name)) return "";
    const std::string loose = folded(name);
    const KnownEngine* closest = nullptr;
    std::size_t best = std::min(kSuggestedDistance, loose.size() / kLettersPerSlip) + 1;
    for (const KnownEngine& e : kKnownEngines) {
        if (!e.built) continue;
        const std::size_t d = std::min(edit_distance(loose, folded(e.name)), edit_distance(loose, folded(e.display_name)));
        if (d < best) {
            best = d;
            closest = &e;
        }
    }
    return closest ? fmt::format(" (did you mean '{}'?)", closest->name) : "";
}

std::string engine_plugin_file(const std::string& name) {
    const KnownEngine& known = require_built(name);
    return known.plugin ? plugin_file_of(known) : "";
}

std::string engine_plugin_path(const std::string& name) {
    const KnownEngine& known = require_built(name);
    if (!known.plugin) return "";
    std::string path;
    (void)engine_plugin(known, &path);
    return path;
}

std::optional<RecordedVersion> recorded_engine_version(const std::string& name) {
    const KnownEngine& known = require_built(name);
    if (!known.plugin) return std::nullopt;
    const std::string path = find_plugin(plugin_file_of(known));
    if (path.empty() || !plugin_file_problem(path).empty()) return std::nullopt;
    const std::map<std::string, std::string> versions = recorded_versions(path);
    const auto it = versions.find(known.name);
    if (it == versions.end()) return std::nullopt;
    return RecordedVersion{it->second, path};
}

std::unique_ptr<Engine> make_engine(const std::string& name) {
    std::unique_ptr<Engine> engine = make_engine_in_process(name);
    if (engine->name() == "analytic") return engine;  // this project's own code, a fraction of a millisecond a run
    return isolated(std::move(engine));
}

std::unique_ptr<Engine> make_engine_in_process(const std::string& name) {
    const KnownEngine& known = require_built(name);
    if (!known.plugin) return std::make_unique<AnalyticEngine>();
    const EnginePlugin& plugin = engine_plugin(known);
    for (std::size_t i = 0; i < plugin.engine_count; ++i)
        if (std::string(known.name) == plugin.engines[i].name) return plugin.engines[i].make();
    throw InputError(fmt::format("engine '{}': its plugin {} does not provide it", name, plugin_file_of(known)));
}

}  // namespace vssw::multibody

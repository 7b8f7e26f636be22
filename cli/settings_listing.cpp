#include "cli/settings_listing.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "io/json.hpp"
#include "cli/option_values.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {
namespace {

// How a setting is given on the command line.
std::string flag_of(const std::string& name) {
    if (name == "dt") return "--dt";
    if (name == "iterations") return "--iterations";
    return "--set " + name + "=";
}

// The range column: a knob's documented range without its unit (the unit has its own column); dt and iterations have
// rules of their own (a step the run can resolve, docs/guide/program.md "Bad input"; --iterations 1 to 1000).
std::string range_of(const multibody::SettingDescription& s) {
    return multibody::is_knob(s.name) ? multibody::range_bounds_text(s) : "-";
}

// The meaning as the text listing prints it: a setting for one kind of wall says so (any other value than its
// default is refused for the other kind).
std::string meaning_of(const multibody::SettingDescription& s) {
    if (s.vssw_only) return s.meaning + " (VSSW only)";
    if (s.parapet_only) return s.meaning + " (parapet only)";
    return s.meaning;
}

// A range's end in JSON: null when unbounded.
io::Json end_of(double v) { return std::isinf(v) ? io::Json(nullptr) : io::Json(v); }

std::string text_of(const multibody::Engine& engine) {
    const std::vector<multibody::SettingDescription> settings = engine.setting_descriptions();
    std::size_t flag_width = 0, default_width = 0, unit_width = 0, range_width = 0;
    for (const auto& s : settings) {
        flag_width = std::max(flag_width, flag_of(s.name).size());
        default_width = std::max(default_width, s.default_value.size());
        unit_width = std::max(unit_width, s.unit.size());
        range_width = std::max(range_width, range_of(s).size());
    }
    std::string text = fmt::format("{} ({}): {}\n", engine.display_name(), engine.name(), engine.version());
    for (const auto& s : settings)
        text += fmt::format("  {:<{}}  {:<{}}  {:<{}}  {:<{}}  {}\n", flag_of(s.name), flag_width, s.default_value,
                            default_width, s.unit, unit_width, range_of(s), range_width, meaning_of(s));
    return text;
}

io::Json json_of(const multibody::Engine& engine) {
    io::Json settings = io::Json::array();
    for (const auto& s : engine.setting_descriptions())
        settings.push_back(
            {{"name", s.name}, {"flag", flag_of(s.name)}, {"default", s.default_value}, {"unit", s.unit},
             {"min", end_of(s.lo)}, {"max", end_of(s.hi)}, {"meaning", s.meaning},
             {"walls", multibody::walls_of(s)}});
    return {{"engine", engine.name()}, {"version", engine.version()}, {"settings", settings}};
}

}  // namespace

std::string settings_listing(const std::vector<std::string>& engines, bool json) {
    const std::vector<std::string> names =
        engines.empty() ? multibody::available_engines() : parse_engine_list("--engine", engines);
    std::string text;
    io::Json all = io::Json::array();
    for (const std::string& name : names) {
        const std::unique_ptr<multibody::Engine> engine = multibody::make_engine(name);
        if (json) all.push_back(json_of(*engine));
        else text += (text.empty() ? "" : "\n") + text_of(*engine);
    }
    if (json) return io::dump_json(all, 2) + "\n";
    return text +
           "\nColumns: how the setting is given, its default, its unit (0/1: a switch; choice: 0, 1, ...), its range "
           "(both\nends included; a value outside it is refused), its meaning. \"(VSSW only)\", \"(parapet only)\": for "
           "the other\nkind of wall any value but the default is refused.\n"
           "Each default and why it was chosen: docs/contributing/engines.md.\n";
}

}  // namespace vssw::cli

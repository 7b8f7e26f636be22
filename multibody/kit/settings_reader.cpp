#include "multibody/kit/settings_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::multibody {

SettingsReader::SettingsReader(std::string engine, const EngineSettings& settings,
                               const std::vector<SettingDescription>& described)
    : engine_(std::move(engine)), settings_(settings) {
    std::vector<std::string> known;
    for (const SettingDescription& d : described)
        if (is_knob(d.name)) known.push_back(d.name);
    // Not a structured binding: clang 14 (the sanitizer build's) refuses to capture one in the lambda below (C++20).
    for (const auto& knob : settings.knobs) {
        const std::string& name = knob.first;
        const double value = knob.second;
        if (std::find(known.begin(), known.end(), name) == known.end())
            throw InputError(
                fmt::format("unknown {} setting '{}' (known: {})", engine_, name, fmt::join(known, ", ")));
        require(!std::isnan(value), label(name), "a number", value);
        const auto d = std::find_if(described.begin(), described.end(),
                                    [&](const SettingDescription& x) { return x.name == name; });
        require(value >= d->lo && value <= d->hi, label(name),
                fmt::format("within its documented range {} (vssw compare --list-settings)", range_text(*d)), value);
    }
}

void require_settings_fit_wall(const std::string& engine, const EngineSettings& settings,
                               const std::vector<SettingDescription>& described, const WallScene& scene) {
    const bool vssw = scene.vssw.has_value();
    for (const SettingDescription& d : described) {
        const auto given = settings.knobs.find(d.name);
        if (!(vssw ? d.parapet_only : d.vssw_only) || given == settings.knobs.end()) continue;
        if (given->second == std::strtod(d.default_value.c_str(), nullptr)) continue;
        throw InputError(fmt::format("{} setting {} = {:g} is for a {} only: give {} (its default) for a {}", engine,
                                     d.name, given->second, vssw ? "parapet wall" : "VSSW (two blocks and a roller)",
                                     d.default_value, vssw ? "VSSW" : "parapet"));
    }
}

std::string range_bounds_text(const SettingDescription& d) {
    if (std::isinf(d.lo) && std::isinf(d.hi)) return "any";
    return fmt::format("[{:g}, {:g}]", d.lo, d.hi);
}

std::string range_text(const SettingDescription& d) {
    const bool unitless = d.unit == "0/1" || d.unit == "choice" || d.unit.empty();
    return range_bounds_text(d) + (unitless ? "" : " " + d.unit);
}

double SettingsReader::value(const std::string& name, double fallback) const {
    const auto it = settings_.knobs.find(name);
    return it == settings_.knobs.end() ? fallback : it->second;
}

double SettingsReader::number(const std::string& name, double fallback) const { return value(name, fallback); }

double SettingsReader::positive(const std::string& name, double fallback) const {
    const double v = value(name, fallback);
    require(std::isfinite(v) && v > 0.0, label(name), "finite and > 0", v);
    return v;
}

double SettingsReader::non_negative(const std::string& name, double fallback) const {
    const double v = value(name, fallback);
    require(std::isfinite(v) && v >= 0.0, label(name), "finite and >= 0", v);
    return v;
}

int SettingsReader::choice(const std::string& name, int fallback, int count) const {
    return whole_number(name, fallback, count - 1);
}

int SettingsReader::whole_number(const std::string& name, int fallback, int max) const {
    const double v = value(name, fallback);
    require(v >= 0.0 && v <= max && v == std::floor(v), label(name), fmt::format("a whole number in [0, {}]", max), v);
    return static_cast<int>(v);
}

bool SettingsReader::flag(const std::string& name) const { return choice(name, 0, 2) == 1; }

}  // namespace vssw::multibody

#pragma once
// An adapter's named settings (EngineSettings::knobs), read in one way for every backend: a name the adapter does
// not know is bad input that lists the known ones; a value is the one given or the adapter's default; the common
// kinds of value are checked with a message naming the setting and the value.
#include <string>
#include <vector>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// InputError naming the engine, the setting, its value and the wall when a setting `described` marks parapet_only
// (vssw_only) is given a value other than its default for a VSSW (a parapet). Every entry point checks it with the
// other settings, once it knows the wall, before anything runs (compare, study, report suites; IsolatedEngine again
// for any other caller).
void require_settings_fit_wall(const std::string& engine, const EngineSettings& settings,
                               const std::vector<SettingDescription>& described, const WallScene& scene);

class SettingsReader {
public:
    // Throws InputError on a name that is not one of the described knobs, or a NaN value. `described` is the
    // adapter's Engine::setting_descriptions() (its "dt" and "iterations" are not knobs).
    SettingsReader(std::string engine, const EngineSettings& settings, const std::vector<SettingDescription>& described);

    double number(const std::string& name, double fallback) const;        // any value but NaN (inf allowed)
    double positive(const std::string& name, double fallback) const;      // finite and > 0
    double non_negative(const std::string& name, double fallback) const;  // finite and >= 0
    int choice(const std::string& name, int fallback, int count) const;   // a whole number in [0, count)
    int whole_number(const std::string& name, int fallback, int max) const;  // a whole number in [0, max]
    bool flag(const std::string& name) const;                             // 0 (the default) or 1

private:
    double value(const std::string& name, double fallback) const;
    std::string label(const std::string& name) const { return engine_ + " setting " + name; }

    std::string engine_;
    const EngineSettings& settings_;
};

}  // namespace vssw::multibody

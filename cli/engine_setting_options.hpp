#pragma once
// An engine's settings as the command line gives them: --dt, --iterations and --set NAME=VALUE (vssw compare, and
// free, history and scene with --engine). Read against the engine's own table: a knob it does not know, or a value
// outside its range, is refused naming it before anything runs.
#include <optional>
#include <string>
#include <vector>

#include "multibody/engine.hpp"

namespace CLI {
class App;
}

namespace vssw::cli {

struct EngineSettingOptions {
    std::optional<double> dt;
    std::optional<std::string> iterations;  // as typed, checked by parse_bounded_int
    std::vector<std::string> knobs;         // NAME=VALUE, as typed
};

// --dt, --iterations and --set for one engine (--engine NAME), with their help.
void add_engine_setting_options(CLI::App& cmd, EngineSettingOptions& o);

// The engine's defaults with the options given; InputError naming a bad value, a knob given twice or one the engine
// does not know.
multibody::EngineSettings engine_settings_of(const multibody::Engine& engine, const EngineSettingOptions& o);

}  // namespace vssw::cli

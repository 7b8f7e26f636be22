#include "cli/engine_setting_options.hpp"

#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/option_values.hpp"

namespace vssw::cli {

void add_engine_setting_options(CLI::App& cmd, EngineSettingOptions& o) {
    cmd.add_option("--dt", o.dt, "the engine's step [s] (default: the engine's own; vssw compare --list-settings)");
    cmd.add_option("--iterations", o.iterations,
                   fmt::format("the engine's solver iterations, 1 to {} (default: the engine's own)",
                               multibody::kMaxIterations));
    cmd.add_option("--set", o.knobs,
                   "engine setting NAME=VALUE (repeatable; vssw compare --list-settings lists each engine's)");
}

multibody::EngineSettings engine_settings_of(const multibody::Engine& engine, const EngineSettingOptions& o) {
    multibody::EngineSettings s = engine.default_settings();
    if (o.dt) s.dt = *o.dt;
    require(std::isfinite(s.dt) && s.dt > 0.0, "--dt (engine step, s)", "a positive finite number", s.dt);
    if (o.iterations) {
        s.iterations = parse_bounded_int("--iterations", *o.iterations, 1, multibody::kMaxIterations);
    }
    std::set<std::string> given;
    for (const std::string& kv : o.knobs) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError(fmt::format("--set takes NAME=VALUE, got '{}'", kv));
        const std::string value = kv.substr(eq + 1);
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(v))
            throw InputError(fmt::format("--set {}: '{}' is not a finite number", kv.substr(0, eq), value));
        // Given twice, the last value won without a word (other options repeated are refused by CLI11).
        if (!given.insert(kv.substr(0, eq)).second)
            throw InputError(fmt::format("--set names '{}' more than once: give each setting once", kv.substr(0, eq)));
        s.knobs[kv.substr(0, eq)] = v;
    }
    engine.check_settings(s);  // an unknown knob is refused before any engine runs, naming the engine
    return s;
}

}  // namespace vssw::cli

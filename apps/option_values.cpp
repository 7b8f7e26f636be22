#include "apps/option_values.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {

int parse_bounded_int(const std::string& name, const std::string& text, int lo, int hi, const std::string& meaning) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(begin, &end, 10);
    const bool whole = !text.empty() && end == begin + text.size() && errno == 0;
    if (!whole || value < lo || value > hi)
        throw InputError(fmt::format("{} must be an integer from {} to {}{}, got {}", name, lo, hi, meaning, text));
    return static_cast<int>(value);
}

int parse_threads(const std::string& text) {
    return parse_bounded_int("--threads", text, 0, kMaxThreads, " (0: the available cores)");
}

std::vector<std::string> parse_engine_list(const std::string& option, const std::vector<std::string>& names) {
    const std::vector<std::string> defaults = multibody::default_compared_engines();
    std::vector<std::string> engines;
    for (const std::string& name : names) {
        if (name == "all") engines.insert(engines.end(), defaults.begin(), defaults.end());
        else engines.push_back(name);
    }
    const std::vector<std::string> available = multibody::available_engines();
    auto holds = [](const auto& begin, const auto& end, const std::string& name) {
        return std::find(begin, end, name) != end;
    };
    std::vector<std::string> unknown, repeated;
    for (auto it = engines.begin(); it != engines.end(); ++it) {
        const bool seen = holds(engines.begin(), it, *it);
        if (!holds(available.begin(), available.end(), *it)) {
            if (!seen) unknown.push_back(*it);
        } else if (seen && !holds(repeated.begin(), repeated.end(), *it)) {
            repeated.push_back(*it);
        }
    }
    std::vector<std::string> problems;
    if (engines.empty()) problems.push_back("no engine given");
    if (!unknown.empty()) problems.push_back(fmt::format("no engine '{}' in this build", fmt::join(unknown, "', '")));
    if (!repeated.empty()) problems.push_back(fmt::format("'{}' named more than once", fmt::join(repeated, "', '")));
    if (!problems.empty())
        throw InputError(fmt::format("{}: {} (available: {}; all: {})", option, fmt::join(problems, "; "),
                                     fmt::join(available, ", "), fmt::join(defaults, ", ")));
    return engines;
}

void require_finite_numbers(const CLI::App& cmd) {
    for (const CLI::Option* option : cmd.get_options()) {
        if (option->get_type_name() != "FLOAT") continue;
        for (const std::string& text : option->results()) {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (!std::isfinite(value))
                throw InputError(fmt::format("{} must be a finite number, got {}", option->get_name(), text));
        }
    }
}

}  // namespace vssw::cli

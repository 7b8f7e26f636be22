#include "cli/option_values.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/engine_names.hpp"

namespace vssw::cli {

int parse_bounded_int(const std::string& name, const std::string& text, int lo, int hi, const std::string& meaning) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(begin, &end, 10);
    const bool whole = !text.empty() && end == begin + text.size() && errno == 0;
    if (!whole || value < lo || value > hi)
        throw InputError(fmt::format("{} must be an integer from {} to {}{}, got {}", name, lo, hi, meaning,
                                     text.empty() ? "an empty value" : text));
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
        else engines.push_back(multibody::canonical_engine(name).value_or(name));  // "ODE" is ode
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
    if (!unknown.empty()) {
        std::vector<std::string> named;  // "'mujuco' (did you mean 'mujoco'?)"
        for (const std::string& name : unknown)
            named.push_back(fmt::format("'{}'{}", name, multibody::engine_name_hint(name)));
        problems.push_back(fmt::format("no engine {} in this build", fmt::join(named, ", ")));
    }
    if (!repeated.empty()) problems.push_back(fmt::format("'{}' named more than once", fmt::join(repeated, "', '")));
    if (!problems.empty())
        throw InputError(fmt::format("{}: {} (available: {}; all: {})", option, fmt::join(problems, "; "),
                                     fmt::join(available, ", "), fmt::join(defaults, ", ")));
    return engines;
}

std::vector<std::string> list_items(const std::string& option, const std::vector<std::string>& given) {
    std::vector<std::string> items;
    for (const std::string& text : given) {
        std::size_t start = 0;
        while (true) {
            const std::size_t comma = text.find(',', start);
            const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            if (item.empty())
                throw InputError(text.empty() ? fmt::format("{} must list names, got an empty value", option)
                                              : fmt::format("{} has an empty item in '{}'", option, text));
            if (std::find(items.begin(), items.end(), item) != items.end())
                throw InputError(fmt::format("{} names '{}' more than once", option, item));
            items.push_back(item);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    return items;
}

CLI::Option* add_list_option(CLI::App& cmd, const std::string& name, std::vector<std::string>& target,
                             const std::string& help) {
    return cmd.add_option_function<std::vector<std::string>>(
        name, [&target, name](const std::vector<std::string>& given) { target = list_items(name, given); }, help);
}

namespace {

bool is_number_option(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    return type == "FLOAT" || type == "INT" || type == "UINT";
}

void require_values_of(const CLI::App& cmd) {
    for (const CLI::Option* option : cmd.get_options()) {
        for (const std::string& text : option->results()) {
            if (text.empty()) throw InputError(empty_value_message(*option));
            if (option->get_type_name() != "FLOAT") continue;
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (!std::isfinite(value))
                throw InputError(fmt::format("{} must be a finite number, got {}", option->get_name(), text));
        }
    }
}

}  // namespace

std::string empty_value_message(const CLI::Option& option) {
    return is_number_option(option) ? fmt::format("{} must be a number, got an empty value", option.get_name())
                                    : fmt::format("{} needs a value, got an empty one", option.get_name());
}

void require_option_values(const CLI::App& cmd) {
    require_values_of(cmd);
    for (const CLI::App* sub : cmd.get_subcommands())
        if (sub->parsed()) require_values_of(*sub);  // `study merge`'s
}

}  // namespace vssw::cli

#include "apps/option_values.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"

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

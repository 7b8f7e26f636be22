#include "io/text.hpp"

#include <cctype>
#include <cmath>

#include <fmt/format.h>

namespace vssw::study {

std::string num(double value) { return fmt::format("{:.6g}", value); }

std::string yes_no(bool value) { return value ? "yes" : "no"; }

std::string percent(double rel_error) {
    if (!std::isfinite(rel_error)) return "n/a";
    const double p = 100.0 * rel_error;
    const double a = std::abs(p);
    if (a == 0.0) return "0 %";
    if (a >= 1.0) return fmt::format("{:+.1f} %", p);
    if (a >= 0.01) return fmt::format("{:+.2f} %", p);
    return fmt::format("{:+.1e} %", p);
}

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

std::string file_stem(const std::string& case_id) {
    std::string s = case_id;
    for (char& c : s) {
        if (c == '/') c = '_';
        else if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '-';
    }
    return s;
}

}  // namespace vssw::study

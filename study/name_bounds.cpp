#include "study/name_bounds.hpp"

#include <cctype>

#include <fmt/format.h>

namespace vssw::study {

std::optional<std::string> template_too_wide(const std::string& tmpl) {
    for (std::size_t i = 0; i < tmpl.size(); ++i) {
        if (tmpl[i] != '{') continue;
        if (i + 1 < tmpl.size() && tmpl[i + 1] == '{') {  // "{{": a brace
            ++i;
            continue;
        }
        const std::size_t close = tmpl.find('}', i);
        if (close == std::string::npos) return std::nullopt;  // not a field: the grid names that mistake
        const std::size_t colon = tmpl.find(':', i);
        // Every number in a format ("0>8", ">8.3f"), a fill digit included, is at most the bound: widths and
        // precisions are its only numbers of more than one digit.
        for (std::size_t k = colon; k < close; ++k) {
            if (!std::isdigit(static_cast<unsigned char>(tmpl[k]))) continue;
            std::size_t end = k;
            while (end < close && std::isdigit(static_cast<unsigned char>(tmpl[end]))) ++end;
            const std::string digits = tmpl.substr(k, end - k);
            const std::size_t first = digits.find_first_not_of('0');
            const bool too_wide = first != std::string::npos &&
                                  (digits.size() - first > 3 || std::stol(digits.substr(first)) > kMaxTemplateWidth);
            if (too_wide)
                return fmt::format("the field '{}' asks for a width or precision of {}, more than {} characters",
                                   tmpl.substr(i, close - i + 1), digits, kMaxTemplateWidth);
            k = end;
        }
        i = close;
    }
    return std::nullopt;
}

}  // namespace vssw::study

#include "error.hpp"

#include <fmt/format.h>

namespace vssw {

void require(bool ok, const std::string& what, const std::string& rule, double value) {
    if (!ok) throw InputError(fmt::format("{} must be {}, got {}", what, rule, value));
}

}  // namespace vssw

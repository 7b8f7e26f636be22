#include "io/clock.hpp"

#include <ctime>

namespace vssw::io {

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);  // not gmtime: no static buffer shared with other threads
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

}  // namespace vssw::io

#pragma once
// The files this process has mapped (/proc/self/maps): which plugins and engine libraries a test has loaded.
#include <fstream>
#include <sstream>
#include <string>

namespace vssw::testing {

inline std::string mapped_files() {
    std::ifstream maps("/proc/self/maps");
    std::stringstream text;
    text << maps.rdbuf();
    return text.str();
}

}  // namespace vssw::testing

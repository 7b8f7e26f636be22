#pragma once
// Whether a backend is compiled into this build: tests of an optional engine (Bullet, ODE, Simbody) skip without it.
#include <algorithm>
#include <string>
#include <vector>

#include "multibody/engine.hpp"

namespace vssw::testing {

inline bool engine_available(const std::string& name) {
    const std::vector<std::string> names = multibody::available_engines();
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace vssw::testing

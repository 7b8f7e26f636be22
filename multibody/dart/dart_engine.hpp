#pragma once
// The DART adapter (DART 6.12.1, Debian libdart-dev). DART's headers stay inside multibody/dart/ (dart_engine.cpp and
// dart_urdf.cpp): a translation unit that includes them takes about a minute to compile (docs/contributing/engines.md
// "DART").
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_dart_engine();

}  // namespace vssw::multibody

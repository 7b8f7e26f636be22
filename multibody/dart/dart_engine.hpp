#pragma once
// The DART adapter (DART 6.12.1, Debian libdart-dev). DART's headers stay inside dart_engine.cpp: a translation unit
// that includes them takes about a minute to compile, and they need C++17 (docs/contributing/engines.md "DART").
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_dart_engine();

}  // namespace vssw::multibody

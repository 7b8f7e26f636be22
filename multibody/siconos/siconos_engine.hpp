#pragma once
// The Siconos adapter (Siconos 4.4 kernel: nonsmooth contact dynamics, Moreau-Jean time stepping). Siconos's headers
// stay inside siconos_engine.cpp (each costs seconds of compile time, and its kernel headers bring Boost's graph
// library with them).
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_siconos_engine();

}  // namespace vssw::multibody

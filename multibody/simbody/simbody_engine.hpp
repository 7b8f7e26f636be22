#pragma once
// The Simbody adapter (Simbody 3.7, rigid unilateral contact in SemiExplicitEulerTimeStepper). Simbody's headers stay
// inside simbody_engine.cpp: they must never meet <ode/ode.h> (its dNaN macro) in one translation unit, and they are
// compiled as C++17 (they do not compile as C++20 with GCC 12).
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_simbody_engine();

}  // namespace vssw::multibody

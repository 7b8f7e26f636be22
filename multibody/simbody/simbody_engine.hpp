#pragma once
// The Simbody adapter (Simbody 3.7), two routes behind two engine names. Simbody's headers stay inside simbody/'s
// .cpp files (and simbody_wall.hpp, which only they include): they must never meet <ode/ode.h> (its dNaN macro) in
// one translation unit, and they are compiled as C++17 (they do not compile as C++20 with GCC 12).
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// "simbody": Hunt-Crossley compliant contact integrated by CPodes (simbody_compliant.cpp), the default route.
std::unique_ptr<Engine> make_simbody_engine();
// "simbody-rigid": rigid unilateral contact in SemiExplicitEulerTimeStepper (simbody_engine.cpp).
std::unique_ptr<Engine> make_simbody_rigid_engine();

}  // namespace vssw::multibody

#pragma once
// The ODE adapter (ODE 0.16.2, double precision). ODE's headers stay inside ode_engine.cpp: <ode/ode.h> defines a
// macro dNaN that breaks Simbody's headers, so it must never reach a translation unit that might include both.
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_ode_engine();

}  // namespace vssw::multibody

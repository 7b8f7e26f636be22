#pragma once
// The MuJoCo adapter (MuJoCo 2.2.2, Debian libmujoco-dev). MuJoCo's headers stay inside mujoco_engine.cpp.
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_mujoco_engine();

}  // namespace vssw::multibody

#pragma once
// The Bullet adapter (Bullet 3.24, double precision). Bullet's headers stay inside bullet_engine.cpp.
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_bullet_engine();

}  // namespace vssw::multibody

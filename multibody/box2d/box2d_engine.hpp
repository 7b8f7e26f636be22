#pragma once
// The Box2D adapter (Box2D 2.4.1, single precision, 2D). Box2D's headers stay inside box2d_engine.cpp.
#include <memory>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::unique_ptr<Engine> make_box2d_engine();

}  // namespace vssw::multibody

// The Box2D adapter as a plugin, vssw_engine_box2d.so (engine_plugin.hpp): its one exported symbol.
#include "multibody/box2d/box2d_engine.hpp"
#include "multibody/engine_plugin.hpp"

VSSW_ENGINE_PLUGIN({"box2d", &vssw::multibody::make_box2d_engine})

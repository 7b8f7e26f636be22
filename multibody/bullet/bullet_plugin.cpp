// The Bullet adapter as a plugin, vssw_engine_bullet.so (engine_plugin.hpp): its one exported symbol.
#include "multibody/bullet/bullet_engine.hpp"
#include "multibody/engine_plugin.hpp"

VSSW_ENGINE_PLUGIN({"bullet", &vssw::multibody::make_bullet_engine})

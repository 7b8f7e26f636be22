// The MuJoCo adapter as a plugin, vssw_engine_mujoco.so (engine_plugin.hpp): its one exported symbol.
#include "multibody/engine_plugin.hpp"
#include "multibody/mujoco/mujoco_engine.hpp"

VSSW_ENGINE_PLUGIN({"mujoco", &vssw::multibody::make_mujoco_engine})

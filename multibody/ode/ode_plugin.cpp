// The ODE adapter as a plugin, vssw_engine_ode.so (engine_plugin.hpp): its one exported symbol.
#include "multibody/engine_plugin.hpp"
#include "multibody/ode/ode_engine.hpp"

VSSW_ENGINE_PLUGIN({"ode", &vssw::multibody::make_ode_engine})

// The Siconos adapter as a plugin, vssw_engine_siconos.so (engine_plugin.hpp): its one exported symbol.
#include "multibody/engine_plugin.hpp"
#include "multibody/siconos/siconos_engine.hpp"

VSSW_ENGINE_PLUGIN({"siconos", &vssw::multibody::make_siconos_engine})

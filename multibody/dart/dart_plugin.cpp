// The DART adapter as a plugin, vssw_engine_dart.so (engine_plugin.hpp): its one exported symbol.
#include "multibody/engine_plugin.hpp"
#include "multibody/dart/dart_engine.hpp"

VSSW_ENGINE_PLUGIN({"dart", &vssw::multibody::make_dart_engine})

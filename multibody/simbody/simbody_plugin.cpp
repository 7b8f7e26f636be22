// The Simbody adapter as a plugin, vssw_engine_simbody.so (engine_plugin.hpp): its one exported symbol, naming both
// routes (they share the library and quiet_stdout.hpp's state, hence one plugin).
#include "multibody/engine_plugin.hpp"
#include "multibody/simbody/simbody_engine.hpp"

VSSW_ENGINE_PLUGIN({"simbody", &vssw::multibody::make_simbody_engine},
                   {"simbody-rigid", &vssw::multibody::make_simbody_rigid_engine})

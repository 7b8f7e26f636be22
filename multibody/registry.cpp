#include <algorithm>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/analytic_engine.hpp"
#include "multibody/engine.hpp"
#ifdef VSSW_HAVE_BULLET
#include "multibody/bullet/bullet_engine.hpp"
#endif
#ifdef VSSW_HAVE_ODE
#include "multibody/ode/ode_engine.hpp"
#endif
#ifdef VSSW_HAVE_SIMBODY
#include "multibody/simbody/simbody_engine.hpp"
#endif
#ifdef VSSW_HAVE_SICONOS
#include "multibody/siconos/siconos_engine.hpp"
#endif

namespace vssw::multibody {

std::vector<std::string> available_engines() {
    std::vector<std::string> names = {"analytic"};
#ifdef VSSW_HAVE_BULLET
    names.push_back("bullet");
#endif
#ifdef VSSW_HAVE_ODE
    names.push_back("ode");
#endif
#ifdef VSSW_HAVE_SIMBODY
    names.push_back("simbody");
    names.push_back("simbody-rigid");
#endif
#ifdef VSSW_HAVE_SICONOS
    names.push_back("siconos");
#endif
    return names;
}

std::vector<std::string> missing_engines() {
    const std::vector<std::string> available = available_engines();
    std::vector<std::string> missing;
    for (const char* name : {"analytic", "bullet", "ode", "simbody", "simbody-rigid", "siconos"})
        if (std::find(available.begin(), available.end(), name) == available.end()) missing.push_back(name);
    return missing;
}

std::vector<std::string> default_compared_engines() {
    std::vector<std::string> engines;
    for (const std::string& name : available_engines())
        if (name != "analytic" && name != "simbody-rigid") engines.push_back(name);
    return engines;
}

std::string engine_display_name(const std::string& name) {
    const std::vector<std::string> known = available_engines();
    if (std::find(known.begin(), known.end(), name) == known.end()) return name;
    return make_engine(name)->display_name();
}

std::unique_ptr<Engine> make_engine(const std::string& name) {
    if (name == "analytic") return std::make_unique<AnalyticEngine>();
#ifdef VSSW_HAVE_BULLET
    if (name == "bullet") return make_bullet_engine();
#endif
#ifdef VSSW_HAVE_ODE
    if (name == "ode") return make_ode_engine();
#endif
#ifdef VSSW_HAVE_SIMBODY
    if (name == "simbody") return make_simbody_engine();
    if (name == "simbody-rigid") return make_simbody_rigid_engine();
#endif
#ifdef VSSW_HAVE_SICONOS
    if (name == "siconos") return make_siconos_engine();
#endif
    throw InputError(fmt::format("engine '{}' is not available in this build (available: {})", name,
                                 fmt::join(available_engines(), ", ")));
}

}  // namespace vssw::multibody

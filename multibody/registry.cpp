#include <algorithm>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "multibody/isolated_engine.hpp"
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

namespace {

// Every backend this code knows, in listing order, and whether this build has it: available_engines() and
// missing_engines() both read this one list.
struct KnownEngine {
    const char* name;
    bool built;
};
#ifdef VSSW_HAVE_BULLET
constexpr bool kHaveBullet = true;
#else
constexpr bool kHaveBullet = false;
#endif
#ifdef VSSW_HAVE_ODE
constexpr bool kHaveOde = true;
#else
constexpr bool kHaveOde = false;
#endif
#ifdef VSSW_HAVE_SIMBODY
constexpr bool kHaveSimbody = true;
#else
constexpr bool kHaveSimbody = false;
#endif
#ifdef VSSW_HAVE_SICONOS
constexpr bool kHaveSiconos = true;
#else
constexpr bool kHaveSiconos = false;
#endif
constexpr KnownEngine kKnownEngines[] = {
    {"analytic", true},
    {"bullet", kHaveBullet},
    {"ode", kHaveOde},
    {"simbody", kHaveSimbody},
    {"simbody-rigid", kHaveSimbody},
    {"siconos", kHaveSiconos},
};

std::vector<std::string> known_engines(bool built) {
    std::vector<std::string> names;
    for (const KnownEngine& e : kKnownEngines)
        if (e.built == built) names.push_back(e.name);
    return names;
}

}  // namespace

std::vector<std::string> available_engines() { return known_engines(true); }

std::vector<std::string> missing_engines() { return known_engines(false); }

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
    std::unique_ptr<Engine> engine = make_engine_in_process(name);
    if (name == "analytic") return engine;  // this project's own code, a fraction of a millisecond a run
    return isolated(std::move(engine));
}

std::unique_ptr<Engine> make_engine_in_process(const std::string& name) {
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

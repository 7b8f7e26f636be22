#include "multibody/host/contact_schemes.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>

namespace vssw::multibody {
namespace {

struct SchemeOf {
    const char* engine;
    std::size_t scheme;  // index into kSchemes
};

const ContactScheme kSchemes[] = {
    {"event-driven", "the analytic model: located impacts (root finding) between adaptive integrations of the "
                     "equation of motion, an impact law at each"},
    {"impulse stepping", "fixed-step symplectic Euler with plastic contact impulses at the velocity level, one "
                         "contact solve a step"},
    {"Moreau-Jean", "event-capturing time stepping (theta-method on the smooth forces, Newton's impact law on the "
                    "velocities at every contact that closes within the step)"},
    {"compliant", "penalty contact forces (Hunt-Crossley) integrated by an error-controlled implicit (BDF) "
                  "integrator"},
};

// Simbody's rigid route (SemiExplicitEulerTimeStepper) steps with impulses as Bullet does.
const SchemeOf kEngineSchemes[] = {
    {"analytic", 0}, {"bullet", 1}, {"ode", 1}, {"box2d", 1}, {"dart", 1}, {"mujoco", 1},
    {"simbody-rigid", 1}, {"siconos", 2}, {"simbody", 3},
};

std::size_t scheme_index(const std::string& engine) {
    for (const SchemeOf& s : kEngineSchemes)
        if (engine == s.engine) return s.scheme;
    return std::size(kSchemes);
}

}  // namespace

ContactScheme contact_scheme(const std::string& engine) {
    const std::size_t i = scheme_index(engine);
    if (i == std::size(kSchemes)) return {"other", "not described"};
    return kSchemes[i];
}

std::vector<std::string> ordered_by_scheme(const std::vector<std::string>& engines) {
    std::vector<std::string> out = engines;
    std::stable_sort(out.begin(), out.end(),
                     [](const std::string& a, const std::string& b) { return scheme_index(a) < scheme_index(b); });
    return out;
}

}  // namespace vssw::multibody

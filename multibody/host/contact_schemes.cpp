#include "multibody/host/contact_schemes.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string_view>

#include "vssw_engine_facts.hpp"  // each engine's scheme (generated from its engine.cmake: cmake/engines.cmake)

namespace vssw::multibody {
namespace {

// The schemes in report order; each engine's fact CONTACT_SCHEME names one by its key.
struct Scheme {
    std::string_view key, description;
};
constexpr Scheme kSchemes[] = {
    {"event-driven", "the analytic model: located impacts (root finding) between adaptive integrations of the "
                     "equation of motion, an impact law at each"},
    {"impulse stepping", "fixed-step symplectic Euler with plastic contact impulses at the velocity level, one "
                         "contact solve a step"},
    {"Moreau-Jean", "event-capturing time stepping (theta-method on the smooth forces, Newton's impact law on the "
                    "velocities at every contact that closes within the step)"},
    {"compliant", "penalty contact forces (Hunt-Crossley) integrated by an error-controlled implicit (BDF) "
                  "integrator"},
};

constexpr std::size_t index_of_scheme(std::string_view key) {
    std::size_t i = 0;
    while (i < std::size(kSchemes) && kSchemes[i].key != key) ++i;
    return i;
}

// A scheme named in an engine.cmake that this table does not hold fails the build, not a report.
constexpr bool every_engine_names_a_scheme() {
    for (const EngineFacts& e : kEngineFacts)
        if (index_of_scheme(e.contact_scheme) == std::size(kSchemes)) return false;
    return true;
}
static_assert(every_engine_names_a_scheme(), "an engine.cmake names a CONTACT_SCHEME that kSchemes does not hold");

std::size_t scheme_index(const std::string& engine) {
    for (const EngineFacts& e : kEngineFacts)
        if (engine == e.name) return index_of_scheme(e.contact_scheme);
    return std::size(kSchemes);
}

}  // namespace

ContactScheme contact_scheme(const std::string& engine) {
    const std::size_t i = scheme_index(engine);
    if (i == std::size(kSchemes)) return {"other", "not described"};
    return {std::string(kSchemes[i].key), std::string(kSchemes[i].description)};
}

std::vector<std::string> ordered_by_scheme(const std::vector<std::string>& engines) {
    std::vector<std::string> out = engines;
    std::stable_sort(out.begin(), out.end(),
                     [](const std::string& a, const std::string& b) { return scheme_index(a) < scheme_index(b); });
    return out;
}

}  // namespace vssw::multibody

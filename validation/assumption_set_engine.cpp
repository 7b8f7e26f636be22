#include "validation/assumption_set_engine.hpp"

namespace vssw::validation {

std::string assumption_set_engine_id(AssumptionSet set) { return std::string(to_string(set)) + "-model"; }

std::string assumption_set_engine_label(AssumptionSet set) {
    return std::string("analytic, ") + to_string(set) + "'s assumptions";
}

multibody::EngineSettings AssumptionSetEngine::default_settings() const {
    return multibody::analytic_settings(assumptions_of(set_));
}

}  // namespace vssw::validation

#include "analytic/assumption_sets.hpp"

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw {

AssumptionSet parse_assumption_set(const std::string& text) {
    if (text == "paper") return AssumptionSet::paper;
    if (text == "mechanism") return AssumptionSet::mechanism;
    throw InputError(fmt::format("assumptions must be 'paper' or 'mechanism', got '{}'", text));
}

const char* to_string(AssumptionSet set) { return set == AssumptionSet::paper ? "paper" : "mechanism"; }

std::string describe(AssumptionSet set) {
    return set == AssumptionSet::paper
               ? "paper (the paper's kinematics of Eq. 3, Eq. 19's impact, a bilateral roller)"
               : "mechanism (exact kinematics of Eq. 2, the whole mechanism's plastic impact, a unilateral roller)";
}

Assumptions assumptions_of(AssumptionSet set) {
    if (set == AssumptionSet::mechanism) return Assumptions{};
    return {Kinematics::paper, ImpactLaw{}, Roller::bilateral};
}

bool operator==(const Assumptions& a, const Assumptions& b) {
    const bool same_impact = a.impact.kind == b.impact.kind &&
                             (a.impact.kind != ImpactLaw::Kind::ratio || a.impact.ratio == b.impact.ratio);
    return a.kinematics == b.kinematics && same_impact && a.roller == b.roller;
}

std::optional<AssumptionSet> set_of(const Assumptions& assumptions) {
    for (const AssumptionSet set : {AssumptionSet::paper, AssumptionSet::mechanism})
        if (assumptions == assumptions_of(set)) return set;
    return std::nullopt;
}

std::string set_name(const Assumptions& assumptions) {
    const std::optional<AssumptionSet> set = set_of(assumptions);
    return set ? to_string(*set) : "custom";
}

void require_a_model(const Assumptions& assumptions, const std::string& how) {
    if (assumptions.roller == Roller::unilateral && assumptions.kinematics != Kinematics::exact)
        throw InputError(fmt::format("{}: the paper's Eq. (3) does not keep the top corner on the roller's line, so "
                                     "the top can neither leave the roller nor land back on it",
                                     how));
}

}  // namespace vssw

#pragma once
// The analytic model's assumptions as two named sets, so that every entry point (the commands, study files, the
// Python module, the report) starts from the same model unless told otherwise:
//   paper      the paper as printed: the linearised kinematics of Eq. (3), the impact of Eq. (19) and a bilateral
//              roller that holds the top corner on its line (pulling if it must);
//   mechanism  the mechanism the engines build: the exact kinematics of Eq. (2), the plastic impact with every
//              constraint of the new mechanism acting at once (restitution_whole_mechanism) and a roller that can
//              only push (the top leaves it where it would have to pull). The default, and the reference every
//              engine is compared against: its difference from `paper` is a finding about the paper's assumptions,
//              not an engine's error.
// A parapet (one block, no roller) has one kinematics and Housner's impact under either set.
#include <optional>
#include <string>

#include "analytic/model.hpp"     // Kinematics, ImpactLaw
#include "analytic/simulate.hpp"  // Roller

namespace vssw {

enum class AssumptionSet { paper, mechanism };
inline constexpr AssumptionSet kDefaultAssumptionSet = AssumptionSet::mechanism;

AssumptionSet parse_assumption_set(const std::string& text);  // "paper" | "mechanism", InputError otherwise
const char* to_string(AssumptionSet set);
// One line for help texts and reports: "mechanism (exact kinematics, whole-mechanism impact, unilateral roller)".
std::string describe(AssumptionSet set);

// The three assumptions one by one (a study varies them one by one; a command may override one of a set's).
// Default-constructed: the default set's.
struct Assumptions {
    Kinematics kinematics = Kinematics::exact;
    ImpactLaw impact{ImpactLaw::Kind::whole_mechanism, 0.0};
    Roller roller = Roller::unilateral;
};
Assumptions assumptions_of(AssumptionSet set);
// The set whose assumptions these are; none when they are neither set's (a set with one of them changed).
std::optional<AssumptionSet> set_of(const Assumptions& assumptions);
// "paper", "mechanism", or "custom" when set_of() finds none.
std::string set_name(const Assumptions& assumptions);
bool operator==(const Assumptions& a, const Assumptions& b);

// InputError when the assumptions are not a model: a roller that can only push needs the exact kinematics, since
// Eq. (3) does not keep the top corner on the roller's line (the top could neither leave it nor land back).
// `how` names how the user gave them, e.g. "--roller unilateral needs --kinematics exact".
void require_a_model(const Assumptions& assumptions, const std::string& how);

}  // namespace vssw

#pragma once
// How each backend's defaults integrate a rocking wall, grouped by what sets their dominant error. Engines of one
// scheme share it: Bullet, ODE, Box2D, DART and MuJoCo with stiff contact all step with symplectic Euler and resolve
// contacts as plastic impulses at the velocity level, and on the parapet their quarter-period errors at 1 ms agree to
// three digits (-0.072 to -0.075 %; docs/engines.md, "Contact schemes"). Agreement among them is one piece of
// evidence, not several; engines of different schemes agreeing is. The report groups the engines by scheme.
// Engine-free: a table by name, read without opening a plugin.
#include <string>
#include <vector>

namespace vssw::multibody {

struct ContactScheme {
    std::string key;          // short label for tables ("impulse stepping")
    std::string description;  // one sentence
};

// The scheme of a backend at its default settings; "other" for a name the table does not hold.
ContactScheme contact_scheme(const std::string& engine);

// The engines in the order of their schemes (the table's order), each scheme's engines in the order given.
std::vector<std::string> ordered_by_scheme(const std::vector<std::string>& engines);

}  // namespace vssw::multibody

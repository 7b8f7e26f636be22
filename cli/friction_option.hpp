#pragma once
// --friction: the engines' Coulomb friction at the base and the hinge, given by the user (docs/guide/program.md
// "Finite friction"). Given, sliding is a measured response of every engine run (multibody::SlipMeasures) and the
// analytic model says whether it would slide; not given, the default friction holds and a slide fails the run.
#include <optional>
#include <string>

#include "io/json.hpp"
#include "multibody/engine.hpp"

namespace CLI {
class App;
}

namespace vssw::cli {

// --friction MU or MU_BASE,MU_HINGE, kept as typed (checked by with_friction).
void add_friction_option(CLI::App& cmd, std::optional<std::string>& text);

// The scene with the friction typed: InputError "--friction must be ..., got '<text>'" unless it is one or two
// comma-separated finite numbers > 0. Unchanged when none was given.
multibody::WallScene with_friction(multibody::WallScene scene, const std::optional<std::string>& text);

// {base, hinge} of a scene whose friction was given; null otherwise.
io::Json friction_json(const multibody::WallScene& scene);
// The measured slips of an engine run: {base {largest_m, largest_b, residual_m, residual_b}, hinge {...},
// t_first_slip, t_first_lift, slid_before_rocking, slid_off}; hinge null for a parapet (it has none).
io::Json slip_json(const multibody::SlipMeasures& slip, bool has_hinge);

}  // namespace vssw::cli

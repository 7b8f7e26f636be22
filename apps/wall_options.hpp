#pragma once
// The options that describe a wall and its model, shared by the commands: one place that binds them to the command
// line, documents their units and defaults, and turns them into the analytic library's geometry and models.
// Values are not checked here: the library's constructors check them and name the bad value.
#include <memory>
#include <optional>
#include <string>

#include "analytic/ground_motion.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall.hpp"
#include "analytic/wall_scene.hpp"
#include "apps/json.hpp"

namespace CLI {
class App;
}

namespace vssw::cli {

// Standard gravity (kStandardGravity, analytic/ground_motion.hpp) converts accelerations given in g; --g is the wall's.
using vssw::kStandardGravity;

struct WallOptions {
    double height = 0.0;          // full height 2h [m]
    double thickness = 0.0;       // full thickness 2b [m]
    std::optional<double> hinge;  // h1/h, required for a VSSW
    double xi = 0.0;              // N/W
    double density = kDefaultDensity;
    double g = kDefaultGravity;
};

// The wall of Fig. 6 of the paper, the subject of `vssw summary`.
WallOptions fig6_wall();

enum class WallKind { vssw, parapet };
WallKind parse_wall_kind(const std::string& text);  // "vssw" | "parapet", InputError otherwise
const char* to_string(WallKind kind);
// The angle rotations are measured in: "alpha1" (VSSW) or "alpha" (parapet).
const char* reference_angle_name(WallKind kind);

struct ModelOptions {
    std::string model = "vssw";
    std::string kinematics = "paper";
    std::string impact = "eq19";        // the impact law (analytic/model.hpp ImpactLaw)
    std::string roller = "bilateral";   // bilateral (the paper's) | unilateral (can only push)
};

// --height, --thickness (required), --hinge, --xi, --density, --g. `model_choice` (the command also takes --model)
// only changes the help of --hinge: whether a hinge is required is decided by vssw_geometry(), so that a parapet
// can be given without one.
void add_wall_options(CLI::App& cmd, WallOptions& options, bool model_choice);
// --model, --kinematics; the help names options.kinematics as the default (paper, but exact for compare).
void add_model_options(CLI::App& cmd, ModelOptions& options);
// --impact, --roller: the analytic model's assumptions that `free`, `history` and `compare` (its reference) let a
// user change.
void add_assumption_options(CLI::App& cmd, ModelOptions& options);

VsswGeometry vssw_geometry(const WallOptions& options);  // InputError when --hinge is missing
ParapetGeometry parapet_geometry(const WallOptions& options);

// A model chosen on the command line, with what the reports say about it.
struct ChosenModel {
    WallKind kind;
    Wall wall;                             // as built from the options
    std::optional<Kinematics> kinematics;  // none for a parapet (Housner's block has one exact kinematics)
    std::unique_ptr<RockingModel> model;   // with the chosen impact law
    ImpactLaw impact;
    Roller roller = Roller::bilateral;     // always bilateral for a parapet (it has no roller)
};
ChosenModel choose_model(const WallOptions& wall, const ModelOptions& options);

// The wall as given, for the JSON outputs: height, thickness, hinge_ratio (null for a parapet), xi, density, g.
Json wall_inputs_json(const WallOptions& options, WallKind kind);
// One line naming the wall, e.g. "VSSW  height 4 m, thickness 0.4 m, hinge h1/h 0.7, xi 0, density 1800 kg/m^3".
std::string describe_wall(const WallOptions& options, WallKind kind);

}  // namespace vssw::cli

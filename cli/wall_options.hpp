#pragma once
// The options that describe a wall and its model, shared by the commands: one place that binds them to the command
// line, documents their units and defaults, and turns them into the analytic library's geometry and models.
// Values are not checked here: the library's constructors check them and name the bad value.
#include <memory>
#include <optional>
#include <string>

#include "analytic/assumption_sets.hpp"
#include "analytic/diaphragm.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall.hpp"
#include "analytic/wall_scene.hpp"
#include "io/json.hpp"

namespace CLI {
class App;
}

namespace vssw::cli {

// Standard gravity (kStandardGravity, analytic/ground_motion.hpp) converts accelerations given in g; --g is the wall's.

struct WallOptions {
    double height = 0.0;          // full height 2h [m]
    double thickness = 0.0;       // full thickness 2b [m]
    std::optional<double> hinge;  // h1/h, required for a VSSW
    double xi = 0.0;              // N/W
    double eccentricity = 0.0;    // e/b of N on the (upper) body's top face, in [-1, 1] (analytic/geometry.hpp)
    double density = kDefaultDensity;
    double g = kDefaultGravity;
    Diaphragm diaphragm;  // the VSSW's top support (--diaphragm-period, --diaphragm-damping): rigid unless given
    bool diaphragm_damping_given = false;  // refused without a period: a rigid top has no damping to take
    double corner_radius = 0.0;   // r/b of the blocks' rounded corners, in [0, kMaxCornerRadius] (analytic/wall.hpp)
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
    // The analytic model's assumptions: a named set (analytic/assumption_sets.hpp), the same default in every entry
    // point, and any of its three overridden one by one (as typed; parsed by resolve_assumptions).
    std::string assumptions = to_string(kDefaultAssumptionSet);
    std::optional<std::string> kinematics;  // paper | exact
    std::optional<std::string> impact;      // the impact law (analytic/model.hpp ImpactLaw)
    std::optional<std::string> roller;      // bilateral | unilateral
};
// The set with the overrides applied; InputError on a bad word or on assumptions that are no model (a unilateral
// roller with the paper's kinematics), naming the options that made them.
Assumptions resolve_assumptions(const ModelOptions& options);

// --height, --thickness (required), --hinge, --xi, --overburden-eccentricity, --density, --g. `model_choice` (the
// command also takes --model) only changes the help of --hinge: whether a hinge is required is decided by
// vssw_geometry(), so that a parapet can be given without one.
void add_wall_options(CLI::App& cmd, WallOptions& options, bool model_choice);
// --diaphragm-period, --diaphragm-damping: the VSSW's top support carried by a diaphragm (analytic/diaphragm.hpp), for
// the commands that run a wall under a ground motion (history, compare). Checked by choose_model. `model_only`: the
// command runs the analytic model alone (history), which cannot follow a flexible top and refuses it; its help says so.
void add_diaphragm_options(CLI::App& cmd, WallOptions& options, bool model_only);
// --corner-radius: on the commands whose answer holds for rounded corners (compare, wall); the analytic model's
// motion is the sharp blocks' (docs/model/analytic-core.md, "Rounded corners"), so free and history do not take it.
void add_corner_radius_option(CLI::App& cmd, WallOptions& options);
// --model.
void add_model_options(CLI::App& cmd, ModelOptions& options);
// --assumptions (paper | mechanism) and the overrides --kinematics, --impact, --roller: the analytic model's
// assumptions, which `free`, `history`, `summary` and `compare` (its reference) let a user choose.
void add_assumption_options(CLI::App& cmd, ModelOptions& options);

VsswGeometry vssw_geometry(const WallOptions& options);  // InputError when --hinge is missing
ParapetGeometry parapet_geometry(const WallOptions& options);

// A model chosen on the command line, with what the reports say about it.
struct ChosenModel {
    WallKind kind;
    Wall wall;                             // as built from the options
    std::unique_ptr<RockingModel> model;   // with the chosen impact law
    Assumptions assumptions;               // as resolved (a parapet's too: its kinematics and roller unused)

    // None for a parapet (Housner's block has one exact kinematics).
    std::optional<Kinematics> kinematics() const {
        return kind == WallKind::vssw ? std::optional(assumptions.kinematics) : std::nullopt;
    }
    const ImpactLaw& impact() const { return assumptions.impact; }
    Roller roller() const { return kind == WallKind::vssw ? assumptions.roller : Roller::bilateral; }  // parapet: none
    std::string set_name() const { return vssw::set_name(assumptions); }  // "paper", "mechanism" or "custom"
};
ChosenModel choose_model(const WallOptions& wall, const ModelOptions& options);

// The model's assumptions for the JSON outputs: {assumptions (the set's name or "custom"), kinematics, impact,
// roller}, kinematics and roller null for a parapet; and the same as one line, e.g. "mechanism: exact kinematics,
// impact whole-mechanism, unilateral roller" ("paper: impact eq19" for a parapet).
io::Json assumptions_json(const ChosenModel& chosen);
std::string describe_assumptions(const ChosenModel& chosen);

// The wall as given, for the JSON outputs: height, thickness, hinge_ratio (null for a parapet), xi, density, g, and
// overburden_eccentricity and corner_radius when they are not 0 (a centred N's and sharp corners' outputs are those of
// before they existed).
io::Json wall_inputs_json(const WallOptions& options, WallKind kind);
// One line naming the wall, e.g. "VSSW  height 4 m, thickness 0.4 m, hinge h1/h 0.7, xi 0, density 1800 kg/m^3".
std::string describe_wall(const WallOptions& options, WallKind kind);

}  // namespace vssw::cli

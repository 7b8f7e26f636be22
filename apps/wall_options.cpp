#include "apps/wall_options.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"

namespace vssw::cli {

WallOptions fig6_wall() {
    WallOptions w;
    w.height = 4.0;
    w.thickness = 0.4;
    w.hinge = 0.7;
    return w;  // xi = 0, default density and g
}

WallKind parse_wall_kind(const std::string& text) {
    if (text == "vssw") return WallKind::vssw;
    if (text == "parapet") return WallKind::parapet;
    throw InputError("model must be 'vssw' or 'parapet', got '" + text + "'");
}

const char* to_string(WallKind kind) { return kind == WallKind::vssw ? "vssw" : "parapet"; }

const char* reference_angle_name(WallKind kind) { return kind == WallKind::vssw ? "alpha1" : "alpha"; }

void add_wall_options(CLI::App& cmd, WallOptions& o, bool model_choice) {
    cmd.add_option("--height", o.height, "full wall height 2h [m] (required)")->required();
    cmd.add_option("--thickness", o.thickness, "full wall thickness 2b [m] (required)")->required();
    cmd.add_option_function<double>(
        "--hinge", [&o](const double& r) { o.hinge = r; },
        model_choice ? "hinge height ratio h1/h in (0, 1) (required for --model vssw; accepted and ignored for "
                       "--model parapet)"
                     : "hinge height ratio h1/h in (0, 1) (required)");
    cmd.add_option("--xi", o.xi, "overburden ratio N/W >= 0 (default 0)");
    cmd.add_option("--density", o.density, fmt::format("masonry density [kg/m^3] (default {})", kDefaultDensity));
    cmd.add_option("--g", o.g, fmt::format("gravity [m/s^2] (default {})", kDefaultGravity));
}

void add_model_options(CLI::App& cmd, ModelOptions& o) {
    cmd.add_option("--model", o.model, "vssw (two blocks with a top roller) or parapet (one block) (default vssw)");
    cmd.add_option("--kinematics", o.kinematics,
                   fmt::format("VSSW kinematics: paper (Eq. 3 inside Eq. 10-11, as printed) or exact (Eq. 2) (default "
                               "{}; ignored for a parapet)",
                               o.kinematics));
}

void add_assumption_options(CLI::App& cmd, ModelOptions& o) {
    cmd.add_option("--impact", o.impact,
                   "impact law: eq19 (the paper's Eq. 19; Housner's e for a parapet), whole-mechanism (the plastic "
                   "impact with every constraint of the new mechanism acting, the roller's too: what the engines do), "
                   "or a restitution e in [0, 1] (default eq19)");
    cmd.add_option("--roller", o.roller,
                   "VSSW top roller: bilateral (holds the top corner on its line, pulling if it must: the paper's "
                   "assumption) or unilateral (can only push: where it would pull the top leaves it and the wall moves "
                   "with two degrees of freedom, against the other face's guide or free, until it lands back; needs "
                   "--kinematics exact) (default bilateral; ignored for a parapet)");
}

VsswGeometry vssw_geometry(const WallOptions& o) {
    if (!o.hinge) throw InputError("--hinge (the hinge height ratio h1/h) is required for a VSSW");
    return make_vssw(o.height, o.thickness, *o.hinge, o.xi, o.density, o.g);
}

ParapetGeometry parapet_geometry(const WallOptions& o) {
    return make_parapet(o.height, o.thickness, o.xi, o.density, o.g);
}

ChosenModel choose_model(const WallOptions& wall, const ModelOptions& options) {
    const WallKind kind = parse_wall_kind(options.model);
    const Kinematics kinematics = parse_kinematics(options.kinematics);  // checked even when a parapet ignores it
    const ImpactLaw impact = parse_impact_law(options.impact);
    const Roller roller = parse_roller(options.roller);
    if (kind == WallKind::parapet) {
        const ParapetGeometry p = parapet_geometry(wall);
        return {kind, Wall::of(p), std::nullopt, with_impact_law(make_parapet_model(p), impact), impact,
                Roller::bilateral};
    }
    const VsswGeometry w = vssw_geometry(wall);
    if (roller == Roller::unilateral && kinematics != Kinematics::exact)
        throw InputError("--roller unilateral needs --kinematics exact: the paper's Eq. (3) does not keep the top "
                         "corner on the roller's line, so the top can neither leave the roller nor land back on it");
    return {kind, Wall::of(w), kinematics, with_impact_law(make_vssw_model(w, kinematics), impact), impact, roller};
}

Json wall_inputs_json(const WallOptions& o, WallKind kind) {
    Json j;
    j["height"] = o.height;
    j["thickness"] = o.thickness;
    j["hinge_ratio"] = kind == WallKind::vssw ? or_null(o.hinge) : Json(nullptr);
    j["xi"] = o.xi;
    j["density"] = o.density;
    j["g"] = o.g;
    return j;
}

std::string describe_wall(const WallOptions& o, WallKind kind) {
    const std::string hinge = kind == WallKind::vssw && o.hinge ? fmt::format(", hinge h1/h {}", *o.hinge) : "";
    return fmt::format("{}: height {} m, thickness {} m{}, xi {}, density {} kg/m^3, g {} m/s^2",
                       kind == WallKind::vssw ? "VSSW" : "parapet", o.height, o.thickness, hinge, o.xi, o.density, o.g);
}

}  // namespace vssw::cli

#include "cli/wall_options.hpp"

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

namespace {

void add_eccentricity_option(CLI::App& cmd, WallOptions& o) {
    cmd.add_option("--overburden-eccentricity", o.eccentricity,
                   "where N acts on the (upper) body's top face, e/b in [-1, 1]: 0 the centre (the paper's "
                   "assumption, default), +1 the corner on the side the wall tips toward when theta1 > 0, -1 the "
                   "other corner");
}

}  // namespace

void add_wall_options(CLI::App& cmd, WallOptions& o, bool model_choice) {
    cmd.add_option("--height", o.height, "full wall height 2h [m] (required)")->required();
    cmd.add_option("--thickness", o.thickness, "full wall thickness 2b [m] (required)")->required();
    cmd.add_option_function<double>(
        "--hinge", [&o](const double& r) { o.hinge = r; },
        model_choice ? "hinge height ratio h1/h in (0, 1) (required for --model vssw; accepted and ignored for "
                       "--model parapet)"
                     : "hinge height ratio h1/h in (0, 1) (required)");
    cmd.add_option("--xi", o.xi, "overburden ratio N/W >= 0 (default 0)");
    add_eccentricity_option(cmd, o);
    cmd.add_option("--density", o.density, fmt::format("masonry density [kg/m^3] (default {})", kDefaultDensity));
    cmd.add_option("--g", o.g, fmt::format("gravity [m/s^2] (default {})", kDefaultGravity));
}

void add_corner_radius_option(CLI::App& cmd, WallOptions& o) {
    cmd.add_option("--corner-radius", o.corner_radius,
                   fmt::format("round every block corner to r = this * b, r/b in [0, {:g}]: 0 sharp corners (the "
                               "paper's blocks, default); the base pivot and the hinge move in to b - r (Eq. 12r, "
                               "17r); engines that cannot round their blocks refuse it",
                               kMaxCornerRadius));
}

void add_diaphragm_options(CLI::App& cmd, WallOptions& o, bool model_only) {
    const std::string follows =
        model_only ? "the analytic model cannot follow a moving top (Eq. 9e), so a period > 0 is refused with that "
                     "reason here: `vssw compare` runs it in the engines"
                   : "the roller follows its response to the ground motion (Eq. 9d)";
    cmd.add_option("--diaphragm-period", o.diaphragm.period,
                   fmt::format("period T_d [s] of the diaphragm that carries a VSSW's top roller, in [0, {:g}]: {}; 0 "
                               "a rigid diaphragm, the top moving with the ground (the paper's Eq. 9, default)",
                               kMaxDiaphragmPeriod, follows));
    cmd.add_option_function<double>(
        "--diaphragm-damping",
        [&o](const double& damping) {
            o.diaphragm.damping = damping;
            o.diaphragm_damping_given = true;
        },
        fmt::format("the diaphragm's damping ratio zeta_d in [0, {:g}] (default {:g}), with --diaphragm-period",
                    kMaxDiaphragmDamping, kDefaultDiaphragmDamping));
}

void add_model_options(CLI::App& cmd, ModelOptions& o) {
    cmd.add_option("--model", o.model, "vssw (two blocks with a top roller) or parapet (one block) (default vssw)");
}

void add_assumption_options(CLI::App& cmd, ModelOptions& o) {
    cmd.add_option("--assumptions", o.assumptions,
                   fmt::format("the analytic model's assumptions, a named set: {}, or {} (default {}: what every "
                               "engine is compared against)",
                               describe(AssumptionSet::paper), describe(AssumptionSet::mechanism),
                               to_string(kDefaultAssumptionSet)));
    cmd.add_option("--kinematics", o.kinematics,
                   "overrides the set's VSSW kinematics: paper (Eq. 3 inside Eq. 10-11, as printed) or exact (Eq. 2) "
                   "(ignored for a parapet)");
    cmd.add_option("--impact", o.impact,
                   "overrides the set's impact law: eq19 (the paper's Eq. 19; Housner's e for a parapet), "
                   "whole-mechanism (the plastic impact with every constraint of the new mechanism acting, the "
                   "roller's too: what the engines do), or a restitution e in [0, 1]");
    cmd.add_option("--roller", o.roller,
                   "overrides the set's VSSW top roller: bilateral (holds the top corner on its line, pulling if it "
                   "must) or unilateral (can only push: where it would pull the top leaves it and the wall moves with "
                   "two degrees of freedom, against the other face's guide or free, until it lands back; needs exact "
                   "kinematics) (ignored for a parapet)");
}

Assumptions resolve_assumptions(const ModelOptions& o) {
    Assumptions a = assumptions_of(parse_assumption_set(o.assumptions));
    if (o.kinematics) a.kinematics = parse_kinematics(*o.kinematics);
    if (o.impact) a.impact = parse_impact_law(*o.impact);
    if (o.roller) a.roller = parse_roller(*o.roller);
    return a;
}

namespace {

// How the user came to a unilateral roller with the paper's kinematics, for the one line that refuses it.
std::string unilateral_with_paper_kinematics(const ModelOptions& o) {
    if (o.roller) return "--roller unilateral needs --kinematics exact";
    return fmt::format("--kinematics paper with --assumptions {} (its unilateral roller) needs --roller bilateral, or "
                       "--assumptions paper",
                       o.assumptions);
}

}  // namespace

VsswGeometry vssw_geometry(const WallOptions& o) {
    if (!o.hinge) throw InputError("--hinge (the hinge height ratio h1/h) is required for a VSSW");
    return with_corner_radius(
        with_eccentricity(make_vssw(o.height, o.thickness, *o.hinge, o.xi, o.density, o.g), o.eccentricity),
        o.corner_radius);
}

ParapetGeometry parapet_geometry(const WallOptions& o) {
    return with_corner_radius(
        with_eccentricity(make_parapet(o.height, o.thickness, o.xi, o.density, o.g), o.eccentricity),
        o.corner_radius);
}

ChosenModel choose_model(const WallOptions& wall, const ModelOptions& options) {
    const WallKind kind = parse_wall_kind(options.model);
    const Assumptions a = resolve_assumptions(options);  // checked even where a parapet ignores a part
    require_diaphragm(wall.diaphragm, "--diaphragm-period T_d (s)", "--diaphragm-damping zeta_d");
    if (wall.diaphragm_damping_given && wall.diaphragm.is_rigid())
        throw InputError(fmt::format("--diaphragm-damping {:g} without --diaphragm-period: a rigid top support has no "
                                     "damping to take (give the diaphragm's period T_d > 0)",
                                     wall.diaphragm.damping));
    if (kind == WallKind::parapet) {
        if (!wall.diaphragm.is_rigid())
            throw InputError(fmt::format("--diaphragm-period {:g}: a parapet has no top support for a diaphragm to "
                                         "carry (give it for a VSSW, or 0)",
                                         wall.diaphragm.period));
        const ParapetGeometry p = parapet_geometry(wall);
        return {kind, Wall::of(p), with_impact_law(make_parapet_model(p), a.impact), a};
    }
    const VsswGeometry w = vssw_geometry(wall);
    require_a_model(a, unilateral_with_paper_kinematics(options));
    Wall built = Wall::of(w);
    built.diaphragm = wall.diaphragm;
    return {kind, built, with_impact_law(make_vssw_model(w, a.kinematics), a.impact), a};
}

io::Json assumptions_json(const ChosenModel& c) {
    const bool vssw = c.kind == WallKind::vssw;
    return {{"assumptions", c.set_name()},
            {"kinematics", vssw ? io::Json(to_string(c.assumptions.kinematics)) : io::Json(nullptr)},
            {"impact", to_string(c.impact())},
            {"roller", vssw ? io::Json(to_string(c.roller())) : io::Json(nullptr)}};
}

std::string describe_assumptions(const ChosenModel& c) {
    if (c.kind != WallKind::vssw) return fmt::format("{}: impact {}", c.set_name(), to_string(c.impact()));
    return fmt::format("{}: {} kinematics, impact {}, {} roller", c.set_name(), to_string(c.assumptions.kinematics),
                       to_string(c.impact()), to_string(c.roller()));
}

io::Json wall_inputs_json(const WallOptions& o, WallKind kind) {
    io::Json j;
    j["height"] = o.height;
    j["thickness"] = o.thickness;
    j["hinge_ratio"] = kind == WallKind::vssw ? io::or_null(o.hinge) : io::Json(nullptr);
    j["xi"] = o.xi;
    j["density"] = o.density;
    j["g"] = o.g;
    if (o.eccentricity != 0.0) j["overburden_eccentricity"] = o.eccentricity;
    if (!o.diaphragm.is_rigid()) {  // a rigid top's outputs are those of before the diaphragm existed
        j["diaphragm_period"] = o.diaphragm.period;
        j["diaphragm_damping"] = o.diaphragm.damping;
    }
    if (o.corner_radius != 0.0) j["corner_radius"] = o.corner_radius;
    return j;
}

std::string describe_wall(const WallOptions& o, WallKind kind) {
    const std::string hinge = kind == WallKind::vssw && o.hinge ? fmt::format(", hinge h1/h {}", *o.hinge) : "";
    const std::string at = o.eccentricity != 0.0 ? fmt::format(" at e/b {}", o.eccentricity) : "";
    const std::string top = o.diaphragm.is_rigid() ? ""
                            : fmt::format(", top support on a diaphragm T_d {} s zeta_d {}", o.diaphragm.period,
                                          o.diaphragm.damping);
    const std::string corners = o.corner_radius != 0.0 ? fmt::format(", corners rounded r/b {}", o.corner_radius) : "";
    return fmt::format("{}: height {} m, thickness {} m{}, xi {}{}, density {} kg/m^3, g {} m/s^2{}{}",
                       kind == WallKind::vssw ? "VSSW" : "parapet", o.height, o.thickness, hinge, o.xi, at, o.density,
                       o.g, top, corners);
}

}  // namespace vssw::cli

#include "cli/wall_output.hpp"

#include <optional>
#include <ostream>
#include <string>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/same_size_parapet.hpp"
#include "cli/table.hpp"

namespace vssw::cli {

namespace {

// The parapet of the VSSW's size, xi, e/b and r/b, and whether it stands: with rounded corners and N off-centre it
// may not where the VSSW does (N's lever on the parapet is not lengthened by the upper block's k). The VSSW took
// the same r/b, so with_corner_radius can refuse the parapet only because it cannot stand.
struct SameSizeParapet {
    ParapetGeometry geometry;
    bool stands = true;
};

SameSizeParapet same_size_parapet(const WallOptions& o) {
    const ParapetGeometry sharp = make_parapet(o.height, o.thickness, o.xi, o.density, o.g);
    if (const std::optional<ParapetGeometry> p = parapet_with_n_and_corners(sharp, o.eccentricity, o.corner_radius))
        return {*p, true};
    return {with_eccentricity(sharp, o.eccentricity), false};
}

}  // namespace

WallFigures wall_figures(const WallOptions& options) {
    const VsswGeometry w = vssw_geometry(options);
    const SameSizeParapet same = same_size_parapet(options);
    const ParapetGeometry& pw = same.geometry;
    const std::optional<double> parapet_threshold =
        same.stands ? std::optional(eq17_parapet_threshold(pw)) : std::nullopt;
    WallFigures f{};
    f.inputs = options;
    f.alpha1 = w.alpha1;
    f.alpha2 = w.alpha2;
    f.R1 = w.R1;
    f.R2 = w.R2;
    f.threshold_g = eq12_threshold(w) / w.g;
    f.restitution = eq19_restitution(w);
    f.A = eq21_A(w);
    f.P = eq21_P(w);
    f.theta_lim = eq26_limit_rotation(w);
    f.period_half_A = eq22_period(w, f.A / 2.0);
    f.collapse_angle = make_vssw_model(w, Kinematics::paper)->collapse_angle();
    f.reference_velocity = eq24_reference_velocity(w);
    if (parapet_threshold) f.threshold_ratio_vssw_over_parapet = eq12_threshold(w) / *parapet_threshold;
    f.optimal_hinge_ratio = eq15_optimal_hinge_ratio(w.xi, w.eccentricity, w.corner_radius);
    f.parapet = {pw.alpha, pw.R, parapet_threshold ? std::optional(*parapet_threshold / pw.g) : std::nullopt,
                 housner_restitution(pw.alpha), housner_p(pw.R, pw.g)};
    return f;
}

io::Json to_json(const WallFigures& f) {
    io::Json j = wall_inputs_json(f.inputs, WallKind::vssw);
    j["alpha1"] = f.alpha1;
    j["alpha2"] = f.alpha2;
    j["R1"] = f.R1;
    j["R2"] = f.R2;
    j["threshold_g"] = f.threshold_g;
    j["restitution"] = f.restitution;
    j["A"] = f.A;
    j["P"] = f.P;
    j["theta_lim"] = io::or_null(f.theta_lim);
    j["period_half_A"] = f.period_half_A;
    j["collapse_angle"] = f.collapse_angle;
    j["reference_velocity"] = f.reference_velocity;
    j["threshold_ratio_vssw_over_parapet"] = io::or_null(f.threshold_ratio_vssw_over_parapet);
    j["optimal_hinge_ratio"] = f.optimal_hinge_ratio;
    j["parapet"] = {{"alpha", f.parapet.alpha},
                    {"R", f.parapet.R},
                    {"threshold_g", io::or_null(f.parapet.threshold_g)},
                    {"restitution", f.parapet.restitution},
                    {"p", f.parapet.p}};
    return j;
}

void print_wall(std::ostream& out, const WallFigures& f) {
    const bool has_overburden = f.inputs.xi != 0.0;
    // N off the centre: the thresholds are Eq. (12e) and (17e), the lower of the two directions of tipping, and the
    // optimal hinge is Eq. (15e)'s, Eq. (15r)'s with rounded corners (docs/model/analytic-core.md, "The overburden's
    // position", "Rounded corners").
    const bool eccentric = has_overburden && f.inputs.eccentricity != 0.0;
    // Rounded corners: the thresholds are Eq. (12r) and (17r); the other closed forms are the sharp blocks' (docs/model/
    // analytic-core.md, "Rounded corners").
    const bool rounded = f.inputs.corner_radius != 0.0;
    auto sharp = [rounded](std::string what) { return rounded ? what + ", sharp corners" : what; };
    const std::string vssw_threshold = rounded ? "Eq. (12r)" : eccentric ? "Eq. (12e)" : "Eq. (12)";
    const std::string parapet_threshold = rounded ? "Eq. (17r)" : eccentric ? "Eq. (17e)" : "Eq. (17)";
    const std::string lower_side = eccentric ? ", the lower of the two sides" : "";
    Table(describe_wall(f.inputs, WallKind::vssw))
        .add("alpha1, alpha2", io::num(f.alpha1) + ", " + io::num(f.alpha2), "rad", "atan(b/h1), atan(b/h2)")
        .add("R1, R2", io::num(f.R1) + ", " + io::num(f.R2), "m", "half-diagonals")
        .add("threshold acceleration", io::num(f.threshold_g), "g", vssw_threshold + lower_side)
        .add("coefficient of restitution", io::num(f.restitution), "", sharp("Eq. (19)"))
        .add("A", io::num(f.A), "rad", has_overburden ? "Eq. (21a), linearised, ignores N" : "Eq. (21a), linearised")
        .add("P", io::num(f.P), "1/s", has_overburden ? "Eq. (21b), linearised, ignores N" : "Eq. (21b), linearised")
        .add("period from theta10 = A/2", io::num(f.period_half_A), "s",
             sharp(has_overburden ? "Eq. (22), ignores N" : "Eq. (22)"))
        .add("roller limit theta1,lim", num_or(f.theta_lim, "none"), f.theta_lim ? "rad" : "",
             f.theta_lim ? "Eq. (26)" : "Eq. (26) needs the hinge above mid-height")
        .add("collapse angle (paper model)", io::num(f.collapse_angle), "rad",
             f.collapse_angle < (1.0 - 1e-5) * f.theta_lim.value_or(1.5707963267948966)
                 ? "where Eq. (3) locks (cos A2 = 0), before Eq. (26)"  // margin: kRollerLimitMargin is 1e-6
                 : (f.theta_lim ? "just below Eq. (26)" : "pi/2: the lower body lies on its face"))
        .add("reference velocity", io::num(f.reference_velocity), "rad/s", sharp("Eq. (24)"))
        .add("optimal hinge ratio h1/h", io::num(f.optimal_hinge_ratio), "",
             eccentric ? (rounded ? "Eq. (15r) at this xi, e/b and r/b" : "Eq. (15e) at this xi and e/b")
                       : "Eq. (15) at this xi")
        .add("threshold VSSW / parapet", num_or(f.threshold_ratio_vssw_over_parapet, "none"), "",
             f.threshold_ratio_vssw_over_parapet ? vssw_threshold + " / " + parapet_threshold
                                                 : "the parapet of its size cannot stand")
        .print(out);
    Table(eccentric || rounded ? fmt::format("Parapet of the same height, thickness, xi{}{} (Housner 1963)",
                                             eccentric ? " and e/b" : "", rounded ? " and r/b" : "")
                               : "Parapet of the same height, thickness and xi (Housner 1963)")
        .add("alpha", io::num(f.parapet.alpha), "rad", "atan(b/h)")
        .add("R", io::num(f.parapet.R), "m", "half-diagonal")
        .add("threshold acceleration", num_or(f.parapet.threshold_g, "none"), f.parapet.threshold_g ? "g" : "",
             f.parapet.threshold_g ? parapet_threshold + lower_side
                                   : "it cannot stand: N outside its rounded pivot's flat tips it at rest")
        .add("coefficient of restitution", io::num(f.parapet.restitution), "", "1 - 3/2 sin^2(alpha)")
        .add("frequency parameter p", io::num(f.parapet.p), "1/s", "sqrt(3g / 4R)")
        .print(out);
}

}  // namespace vssw::cli

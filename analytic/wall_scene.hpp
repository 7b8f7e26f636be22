#pragma once
// A wall as every layer above the analytic core passes it around: exactly one of the paper's two descriptions, a VSSW
// (two blocks with a top roller) or a parapet (one block), and the analytic model built from it. The engines' scene
// (multibody/engine.hpp) is this wall with its contacts' friction; studies, comparisons and the CLI hold it as built
// once, so that a wall is checked where it is made and never rebuilt from its numbers.
#include <memory>
#include <optional>

#include "analytic/diaphragm.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/model.hpp"
#include "analytic/wall.hpp"

namespace vssw {

// Exactly one of the two descriptions (require_one_description).
struct Wall {
    std::optional<VsswGeometry> vssw;
    std::optional<ParapetGeometry> parapet;
    // The VSSW's top support (docs/model/top-support.md): rigid (T_d = 0, the paper's Eq. 9) unless given; a parapet
    // has no top support and refuses a flexible one (require_one_description).
    Diaphragm diaphragm;

    static Wall of(const VsswGeometry& w) { return {w, std::nullopt, {}}; }
    static Wall of(const ParapetGeometry& p) { return {std::nullopt, p, {}}; }
    bool is_vssw() const { return vssw.has_value(); }
    double alpha() const { return vssw ? vssw->alpha1 : parapet->alpha; }  // reference angle alpha1 or alpha
    double gravity() const { return vssw ? vssw->g : parapet->g; }
    double overburden() const { return vssw ? vssw->N : parapet->N; }  // N [N/m]
    // N's point on the (upper) body's top face: e/b in [-1, 1], and e [m] toward the side theta1 > 0 (geometry.hpp).
    double overburden_eccentricity() const { return vssw ? vssw->eccentricity : parapet->eccentricity; }
    double overburden_offset() const { return overburden_eccentricity() * (vssw ? vssw->b : parapet->b); }
    // The blocks' rounded corners: r/b in [0, kMaxCornerRadius], and r [m] (geometry.hpp; 0: the paper's sharp ones).
    double corner_radius_ratio() const { return vssw ? vssw->corner_radius : parapet->corner_radius; }
    double corner_radius() const { return corner_radius_ratio() * (vssw ? vssw->b : parapet->b); }
};

// Throws InputError unless exactly one description (VSSW or parapet) is set and the diaphragm is in range and rigid
// for a parapet (it has no top support): every backend's first check.
void require_one_description(const Wall& wall);

// Throws InputError when the wall's top support is flexible and a ground motion shakes it: the one-degree-of-freedom
// model cannot follow u_d != 0 (docs/model/top-support.md, "What the model can follow"). Without ground motion u_d = 0
// and the paper's model holds as it is.
void require_model_follows_top(const Wall& wall, const GroundMotion& ground);

// The rocking model of a wall: make_vssw_model(*wall.vssw, k) or make_parapet_model(*wall.parapet) (the parapet has
// one kinematics; k is ignored). Throws InputError unless exactly one description is set.
std::unique_ptr<RockingModel> analytic_model(const Wall& wall, Kinematics kinematics);

// The wall's threshold acceleration at rest in closed form [m/s^2]: Eq. (12) for a VSSW, Eq. (17) for a parapet, with
// N off the centre (12e, 17e) and rounded corners (12r, 17r) as the wall has them; the lower of the two sides.
double closed_form_threshold(const Wall& wall);

}  // namespace vssw

#pragma once
// One-degree-of-freedom rocking models in Lagrangian form. For q = |theta1| >= 0 a model gives the mass function
// M(q), the Coriolis coefficient C(q) (= M'(q)/2 for a Lagrangian system), and the lever functions
//   X(q) = sum_i m_i dx_Gi/dq,  Y(q) = sum_i m_i dy_Gi/dq,  L(q) = dy_N/dq (N at the top face's centre),
//   L_e(q) = d/dq of the rise that N's point gains per metre of eccentricity e toward the side of rocking,
// so that for theta1 > 0 the equation of motion (10) reads
//   M theta1'' + C theta1'^2 = -a_h X - (g + a_v) Y - N (L + e L_e),
// and for theta1 < 0 the mirrored mechanism gives the same with the signs of C, Y and L flipped and e replaced by -e
// (Eq. 10's sgn; a mirrored wall sees N on the other side of the centre: docs/model/analytic-core.md, "The
// overburden's position").
// a_h is the horizontal ground acceleration, a_v the vertical one (up positive).
//
// Three models: the paper's VSSW (Eq. 11 as printed, Eq. 3 inside), the exact VSSW (Eq. 2 in a Lagrangian), and the
// parapet wall (Housner's block, with N at the top centre).
#include <memory>
#include <optional>
#include <string>

#include "wall.hpp"

namespace vssw {

enum class Kinematics { paper, exact };
Kinematics parse_kinematics(const std::string& text);  // "paper" | "exact", InputError otherwise
const char* to_string(Kinematics k);

struct ModelTerms {
    double M;  // generalised mass [kg m^2 / m]
    double C;  // Coriolis coefficient
    double X;  // horizontal lever sum m_i dx_i/dq [kg m / m]
    double Y;  // vertical lever sum m_i dy_i/dq
    double L;  // lever of the overburden dy_N/dq [m], N at the top face's centre
    double Le = 0.0;  // the eccentricity's lever: d/dq of N's point's extra rise per metre of e [-]
};

// theta1'' and the ground's generalised force from terms already evaluated at q = side * theta1 (the mirror rule).
struct RockingRates {
    double acceleration;  // theta1''
    double ground_force;  // generalised force of the ground motion (its power is this times theta1')
};
// e: N's eccentricity [m] toward the side theta1 > 0 (RockingModel::eccentricity()).
RockingRates rocking_rates(const ModelTerms& t, int side, double theta_dot, double a_h, double a_v, double g,
                           double N, double e);
// The same from the five terms all multiplied by one common non-zero factor (Eq. 10 is homogeneous in them), with X
// and Y unscaled for the ground's force: the VSSW models' terms share a power of a cosine as denominator, and
// multiplied through by it they need no division, leaving theta1'' one division at the end instead of two on every
// stage's chain of dependent operations.
RockingRates rocking_rates_scaled(const ModelTerms& scaled, double X, double Y, int side, double theta_dot,
                                  double a_h, double a_v, double g, double N, double e);

class RockingModel {
public:
    virtual ~RockingModel() = default;
    virtual ModelTerms terms(double q) const = 0;
    // rocking_rates(terms(q), side, ...) at q = side * theta1 >= 0: what the integrator evaluates at every stage. A
    // model may override it with an equal (to rounding) but cheaper form.
    virtual RockingRates rates(int side, double q, double theta_dot, double a_h, double a_v) const;
    // Sum m_i y_Gi(q) (the bodies' weight potential is g times it) and the height of N's point, both for q >= 0.
    virtual double mass_moment_height(double q) const = 0;
    virtual double load_height(double q) const = 0;
    // N's eccentricity e [m] toward the side theta1 > 0 (0: the paper's centreline), and the rise N's point gains per
    // metre of it at q >= 0 on side +1: N's point is at load_height(q) + side e load_height_per_eccentricity(q).
    virtual double eccentricity() const { return 0.0; }
    virtual double load_height_per_eccentricity(double /*q*/) const { return 0.0; }
    // (b - r) / b: the share of the half-thickness between the centreline and the pivots at rest, 1 for sharp corners
    // (the paper's blocks). Only rest_threshold reads it (Eq. 12r / 17r); the motion stays the sharp blocks'
    // (docs/model/analytic-core.md, "Rounded corners": the analytic backend refuses a rounded wall's runs).
    virtual double flat_share() const { return 1.0; }
    virtual double restitution() const = 0;     // impact map theta1'+ = e theta1'- (Eq. 19, or Housner's e)
    virtual double reference_angle() const = 0; // alpha1 (VSSW) or alpha (PW): where rotations are normalised
    virtual double collapse_angle() const = 0;  // |theta1| at which the wall counts as overturned (docs/model/analytic-core.md, "Overturning")
    virtual double gravity() const = 0;
    virtual double overburden() const = 0;      // N [N/m]
    virtual std::string name() const = 0;

    // The two-block wall behind a VSSW model (nullptr for a parapet), and the upper body's rotation along the
    // model's mechanism at q = |theta1| >= 0 on side +1: theta2(q) and its first two derivatives over q (Eq. 2 for
    // the exact kinematics, Eq. 3 for the paper's). With them a one-DOF run is embedded in the two blocks, where
    // Newton-Euler gives the supports' forces (analytic/two_block.hpp).
    struct UpperRotation {
        double theta2 = 0.0, d1 = 0.0, d2 = 0.0;
    };
    virtual const VsswGeometry* vssw_geometry() const { return nullptr; }
    virtual std::optional<Kinematics> kinematics() const { return std::nullopt; }  // none for a parapet
    virtual UpperRotation upper_rotation(double /*q*/) const { return {}; }

    // theta1'' while the wall rocks on side `side` (+1: theta1 >= 0, -1: theta1 <= 0), from terms() with the mirror
    // rule above. The side is explicit because at theta1 = 0 (lift-off) the sign of theta1 does not tell it.
    double acceleration(int side, double theta, double theta_dot, double a_h, double a_v) const;
    // Generalised force of the ground motion on theta1 (its power is this times theta1').
    double ground_force(int side, double theta, double a_h, double a_v) const;
    // Energies relative to rest [J/m]: the weights' potential, the work done by N, and their difference.
    double weight_potential(double theta) const;
    double overburden_work(double theta) const;
    double potential(double theta) const { return weight_potential(theta) - overburden_work(theta); }
    double kinetic(double theta, double theta_dot) const;
    // V_r: potential energy at the reference angle (the paper's normalising energy, Sect. 7). With N off-centre the
    // two sides differ (N's lever is longer on one); V_r is then the side's of the larger |V|, so that every tolerance
    // scaled by it (the energy a run may gain, the blow-up rate) holds on both sides. A centred N: V(alpha1) itself.
    double reference_energy() const;
    // Reference velocity: sqrt(2 |V_r| / M(0)); equals Eq. (24) for the VSSW with N = 0.
    double reference_velocity() const;
    // Smallest |a_h| that tips the wall off rest toward `side` (+1: theta1 > 0, which a_h < 0 does), from the
    // equation of motion at q = 0; without a side, the lower of the two (they differ only when N is eccentric).
    double rest_threshold(double a_v, int side) const;
    double rest_threshold(double a_v) const;
    // The mechanism's capacity curve c(q): the |a_h| toward `side` that holds the sharp-cornered wall still at
    // q = side theta1 >= 0 under a_v. Eq. (10) with theta1' = theta1'' = 0 reads 0 = -a_h X(q) - (g + a_v) Y(q)
    // - N (L(q) + side e L_e(q)), so c(q) = ((g + a_v) Y + N (L + side e L_e)) / X, which at a_v = 0 is V'(q) / X(q),
    // V the potential of the weights and N. `side` is +1 or -1 (not checked: every caller passes one of the two). At
    // q = 0 it is the rest threshold of sharp corners (Eq. 12 / 17); it falls with q and is 0 at the unstable
    // equilibrium (the potential's maximum); past it c is negative: gravity turns the wall outward, and only an inward
    // acceleration of at least -c can hold it or turn it back (docs/earthquakes.md, "Overturning, the same for every
    // backend"). X > 0 over the mechanism's range; c is +-infinity where X vanishes.
    double holding_acceleration(int side, double q, double a_v = 0.0) const;
    // The side whose rest threshold is the lower: -1 (tipped by a_h > 0) on a tie, as on every centred wall.
    int easier_side() const;
    // The unstable equilibrium on side `side` (+1: theta1 > 0): the |theta1| in (0, collapse angle) where the
    // potential (weights and overburden) is largest. Past it, with the ground still, the wall falls outward; nothing
    // standing can rest there, which is how a folded engine wall (at rest at 3-4 alpha1 short of the collapse angle) is
    // told from a standing one. Without a side, the larger of the two (they differ only when N is eccentric): no
    // standing wall, on either side, rests past it.
    double unstable_equilibrium(int side) const;
    double unstable_equilibrium() const;
};

// Restitution from the peaks either side of an impact, by energy conservation in flight with no ground motion:
// 1/2 M(0) theta1'^2 = V(peak), so e = sqrt(V(after) / V(before)). The consistent form of Eq. (23), for any model.
double restitution_from_peaks(const RockingModel& m, double peak_before, double peak_after);

std::unique_ptr<RockingModel> make_vssw_model(const VsswGeometry& w, Kinematics kinematics);
std::unique_ptr<RockingModel> make_parapet_model(const ParapetGeometry& p);
// The same model with another impact ratio e in [0, 1] (InputError otherwise): the assumption-sensitivity study of
// the impact law, e.g. the whole mechanism's plastic impact (restitution_whole_mechanism) in place of Eq. (19).
std::unique_ptr<RockingModel> with_restitution(std::unique_ptr<RockingModel> model, double e);

// The same model with its runs ending (as "overturned") once |theta1| reaches `stop` if that comes before its collapse
// angle: a threshold trial, which needs only whether the wall lifts that far (multibody/host/analytic_engine.cpp).
std::unique_ptr<RockingModel> with_stop_angle(std::unique_ptr<RockingModel> model, double stop);

// The impact law as a named assumption: the paper's Eq. (19) (Housner's e for a parapet), the whole mechanism's
// plastic impact (restitution_whole_mechanism, the engines' landing; Housner's e again for a single block), or a given
// ratio e in [0, 1].
struct ImpactLaw {
    enum class Kind { eq19, whole_mechanism, ratio } kind = Kind::eq19;
    double ratio = 0.0;  // used when kind == ratio
};
// "eq19" | "whole-mechanism" | a number in [0, 1]; InputError otherwise, naming the text.
ImpactLaw parse_impact_law(const std::string& text);
std::string to_string(const ImpactLaw& law);
// The model with that impact law (the model itself for eq19).
std::unique_ptr<RockingModel> with_impact_law(std::unique_ptr<RockingModel> model, const ImpactLaw& law);

}  // namespace vssw

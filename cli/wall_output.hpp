#pragma once
// The closed forms of a VSSW (Sorrentino, Masiani & Griffith 2008) and of the parapet of the same size (Housner
// 1963): what `vssw wall` prints, and the first part of `vssw summary`.
#include <iosfwd>
#include <optional>

#include "io/json.hpp"
#include "cli/wall_options.hpp"

namespace vssw::cli {

struct ParapetFigures {
    double alpha, R;     // [rad], [m]
    // Eq. (17) / g; none when the parapet cannot stand (rounded corners and N outside the pivot's flat with a
    // moment past the weight's: analytic/wall.hpp with_corner_radius), though the VSSW of its size does.
    std::optional<double> threshold_g;
    double restitution;  // Housner's e = 1 - 3/2 sin^2(alpha)
    double p;            // Housner's frequency parameter sqrt(3g / 4R) [1/s]
};

struct WallFigures {
    WallOptions inputs;
    double alpha1, alpha2, R1, R2;             // [rad], [m]
    double threshold_g;                        // Eq. (12) / g
    double restitution;                        // Eq. (19)
    double A, P;                               // Eq. (21a) [rad], Eq. (21b) [1/s] (linearised, N = 0)
    std::optional<double> theta_lim;           // Eq. (26) [rad]; none with the hinge at or below mid-height
    double period_half_A;                      // Eq. (22) at theta10 = A/2 [s]
    double collapse_angle;                     // where the paper-kinematics model counts the wall as overturned [rad]
    double reference_velocity;                 // Eq. (24) [rad/s]
    std::optional<double> threshold_ratio_vssw_over_parapet;  // Eq. (12) / Eq. (17); none as parapet.threshold_g
    double optimal_hinge_ratio;                // Eq. (15) at this xi
    ParapetFigures parapet;                    // the parapet of the same height, thickness, xi
};

WallFigures wall_figures(const WallOptions& options);  // InputError on bad dimensions or a missing hinge
io::Json to_json(const WallFigures& figures);
void print_wall(std::ostream& out, const WallFigures& figures);

}  // namespace vssw::cli

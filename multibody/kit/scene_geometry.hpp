#pragma once
// Placement of the blocks shared by every engine adapter, from the analytic description: where each block's centre
// is and how it is turned for a lower-body rotation theta1 (the mechanism of Eq. 1-2, exact kinematics), and where the
// points the adapters measure sit on each block. Engine-free: adapters turn these numbers into their own bodies.
#include <memory>

#include "analytic/model.hpp"
#include "analytic/wall_scene.hpp"
#include "multibody/engine.hpp"

namespace vssw::multibody {

struct BlockPose {
    double x, y;   // centre [m]
    double angle;  // rotation, clockwise positive (engine.hpp's sign) [rad]
};

struct WallPose {
    BlockPose lower, upper;  // upper is unused for a parapet
};

// Half extents of the blocks: (b, h1) and (b, h2) for a VSSW, (b, h) for a parapet (lower only). Checks the scene
// (require_one_description).
struct BlockSizes {
    double b, h_lower, h_upper;  // h_upper = 0 for a parapet
    double m_lower, m_upper;     // masses per unit depth [kg/m]
};
BlockSizes block_sizes(const WallScene& scene);

// The wall released at theta1 (either sign) from the mechanism's configuration: the lower block turned about the base
// corner on the side it tips towards; the upper block on the hinge, theta2 from Eq. (2).
WallPose pose_at(const WallScene& scene, double theta1);

// The figures of the scene's analytic model (exact kinematics) that a run's checks read, from one model built once:
// a run's monitor and its parts take them together (built per figure, the model was built five times per run).
struct MechanismFigures {
    double collapse_angle;        // as collapse_angle()
    double unstable_equilibrium;  // as unstable_equilibrium()
    double rest_threshold;        // as rest_threshold()
    double reference_energy;      // as reference_energy()
    double reference_velocity;    // as reference_velocity()
};
MechanismFigures mechanism_figures(const WallScene& scene);

// Collapse angle of the scene (the analytic model's: Eq. 26 or pi/2 for a VSSW, pi/2 for a parapet).
double collapse_angle(const WallScene& scene);

// The unstable equilibrium |theta1| of the scene's analytic model (exact kinematics): past it a still wall falls.
double unstable_equilibrium(const WallScene& scene);
// |theta2| of a VSSW's mechanism at |theta1| (Eq. 2); at the unstable equilibrium, an upper block turned further than
// this has left the standing wall's range, the roller holding it or not. +infinity for a parapet (no upper block) or
// where Eq. (2) has no solution.
double mechanism_theta2(const WallScene& scene, double theta1);

// The smallest |a_h| that tips the scene's wall off rest (Eq. 12 for a VSSW, Eq. 17 for a parapet; exact kinematics).
double rest_threshold(const WallScene& scene);

// V_r of the scene's analytic model (exact kinematics): the potential energy at the reference angle [J/m], the
// scale of the energy check (wall_parts.hpp).
double reference_energy(const WallScene& scene);

// theta1'_r of the scene's analytic model (exact kinematics): the scale engines use for rest and failure checks.
double reference_velocity(const WallScene& scene);

// The roller rule of every adapter: of the upper block's two top corners (world x of each), the guide to give the
// engine is the one whose corner is further out past its line (x = ground_x -/+ b). True: the left guide.
bool left_guide_binds(double right_corner_x, double left_corner_x, double ground_x, double b);

}  // namespace vssw::multibody

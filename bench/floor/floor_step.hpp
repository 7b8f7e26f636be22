#pragma once
// The floor: the least a fixed step of the impulse engines' own contact scheme costs on the two-block wall, as a
// yardstick for their per-step cost (docs/measurements/speed.md, "The floor and the adapters"). It is not an engine of
// the harness (no plugin, no registry, no settings file): it is what Box2D, Bullet and ODE's quickstep do on this
// scene with nothing else around it, written once here so that an engine's cost has something to be measured against.
//
// The scheme, chosen to be the engines' and not a better one:
//  - planar rigid bodies (x, y, angle), symplectic Euler: velocities from gravity first, then the contacts' impulses,
//    then positions from the new velocities (Box2D's and Bullet's order);
//  - the ground motion as gravity tilted by the ground's acceleration, taken at the step's midpoint (the kit's drive
//    hook, multibody/kit/step_loop.hpp);
//  - six corner contacts, found from the positions at the step's start: the lower block's two base corners on the
//    ground, the upper block's two bottom corners on the lower block's top face, the upper block's two top corners
//    against frictionless roller guides at x = -b and x = +b; a contact is given to the solver while its gap is under
//    the margin (speculative: the solver lets it close by its gap and no more, so impacts are plastic);
//  - a penetration pushed out by Baumgarte's bias (a share of it per step), Coulomb friction clamped by the normal
//    impulse, no restitution: the landing's loss is the mechanism's own plastic impact;
//  - sequential impulses (projected Gauss-Seidel) over the contacts, friction before the normal row, warm-started
//    from the previous step's impulses.
#include <functional>

#include "analytic/wall_scene.hpp"
#include "multibody/engine.hpp"

namespace vssw::yardstick {

struct FloorSettings {
    double dt = 1e-3;        // [s] the step (the impulse engines' default on this wall)
    int iterations = 8;      // sequential-impulse sweeps per step (Box2D's default velocity iterations)
    double mu = 2.0;         // base and hinge friction: high enough that nothing slides (the scene's no-sliding model)
    double margin = 1e-3;    // [m] gap under which a contact is given to the solver (ODE's adapter's default)
    double baumgarte = 0.2;  // share of a penetration removed per step (ODE's erp, Box2D's baumgarte)
};

// The Fig. 6 kind of wall (a VSSW scene: two blocks, a roller at the top) released from theta0 with its blocks still,
// in the mechanism's configuration (multibody/kit/scene_geometry.hpp, pose_at).
class FloorWall {
public:
    // std::invalid_argument for a scene that is not a square-cornered VSSW or settings out of their sense
    // (dt <= 0, iterations < 0, mu < 0, margin < 0, baumgarte outside [0, 1]).
    FloorWall(const multibody::WallScene& scene, double theta0, const FloorSettings& settings);

    // One step under the horizontal ground acceleration a_h [m/s^2] (its value at the step's midpoint).
    void step(double a_h);

    double theta1() const;      // the lower block's rotation, clockwise positive (multibody/engine.hpp's sign) [rad]
    double theta1_dot() const;  // [rad/s]
    double lower_y() const;     // the lower block centre's height [m]: below its half height it has sunk
    int contacts() const;       // contacts given to the solver in the last step

    struct Body {
        double x, y, phi, vx, vy, w;  // centre [m], angle counterclockwise [rad], their rates
        double inv_m, inv_i;          // 1 / mass, 1 / moment of inertia about the centre (per unit depth)
        double half_w, half_h;        // half extents [m]
    };
    struct Contact {
        int a, b;                      // bodies (a = -1: the ground or a guide); the impulse pushes b along n
        double nx, ny;                 // unit normal from a to b
        double ra_x, ra_y, rb_x, rb_y; // contact point from each body's centre
        double gap;                    // along n [m], negative when overlapping
        double mu;                     // friction coefficient (0: no friction row)
        double k_n, k_t;               // effective masses along the normal and the tangent
        double target_vn;              // the least normal velocity the row allows (speculative or Baumgarte)
        double p_n = 0.0, p_t = 0.0;   // accumulated impulses, kept for the next step's warm start
        bool active = false;
    };

private:
    void find_contacts();
    void warm_start();
    void solve_sweep();
    void apply(const Contact& c, double p_n, double p_t);

    FloorSettings settings_;
    double b_, g_;
    Body body_[2];         // 0 lower, 1 upper
    Contact contact_[6];   // base left/right, hinge left/right, guide left/right
    int active_ = 0;
};

// A run of the floor sampled every step, as an engine's motion-only trajectory (the harness's metrics read it:
// compare/metrics.hpp). a_h(t): the ground acceleration; empty for free vibration.
multibody::Trajectory run_floor(const multibody::WallScene& scene, double theta0, double t_end,
                                const FloorSettings& settings, const std::function<double(double)>& a_h = {});

}  // namespace vssw::yardstick

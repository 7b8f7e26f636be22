#pragma once
// Parts of a run's result (SimulationResult, simulate.hpp) that other parts of the run fill in too: the flight off the
// roller (off_roller.hpp) reports its turning points, the supports' monitor (support_monitor.hpp) records what the
// supports had to do. Here so that those two need not include the simulation's header.
#include <limits>
#include <optional>

namespace vssw {

struct TurningPoint {
    double t, theta;  // theta1' = 0 while rocking (the release is the first when starting from rest)
};

// What the supports had to do along a VSSW run, from Newton-Euler on each block along the motion
// (analytic/two_block.hpp): the roller's reaction (N per metre of wall, positive when it pushes), the friction
// coefficient the base and the hinge need not to slide (largest |T|/N), and whether a contact would have to pull.
// Empty (computed == false) for a parapet.
struct SupportDemand {
    bool computed = false;
    double min_roller_reaction = std::numeric_limits<double>::infinity();  // [N/m] over the one-DOF phases
    double t_min_roller_reaction = 0.0;
    std::optional<double> roller_tension_at;  // first time the bilateral roller would have to pull
    double base_friction = 0.0, hinge_friction = 0.0;  // largest |T|/N while the contact pushes
    std::optional<double> base_pulls_at, hinge_pulls_at;  // first time the contact would have to pull
    // A unilateral roller: how often the top left it, and for how long in all [s].
    int roller_departures = 0;
    double time_off_roller = 0.0;
};

}  // namespace vssw

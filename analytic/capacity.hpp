#pragma once
// The mechanism's capacity curve: the horizontal ground acceleration that holds the wall still at a rotation. Eq. (10)
// with theta1' = theta1'' = 0 on side s (q = s theta1 >= 0) reads 0 = -a_h X(q) - g Y(q) - N (L(q) + s e L_e(q)), so
// the |a_h| tipping the wall toward s that holds it at q is
//     c(q) = (g Y + N (L + s e L_e)) / X = V'(q) / X(q),
// V the potential of the weights and N (model.hpp: its derivative is g Y + N (L + s e L_e)). At q = 0 it is the rest
// threshold (Eq. 12 / 17); it falls with q and is 0 at the unstable equilibrium (the potential's maximum); past it c is
// negative: gravity turns the wall outward, and only an inward acceleration of at least -c can hold it or turn it
// back (docs/earthquakes.md, "Overturning, the same for every backend").
#include "analytic/model.hpp"

namespace vssw {

// c(q) above [m/s^2] on side `side` (+1: theta1 > 0), q >= 0. X(q) > 0 over the mechanism's range (an outward
// acceleration of the ground tips every block further); c is +infinity or -infinity where X vanishes.
double capacity_acceleration(const RockingModel& model, int side, double q);

}  // namespace vssw

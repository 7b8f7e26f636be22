#include "analytic/capacity.hpp"

#include "analytic/error.hpp"

namespace vssw {

double capacity_acceleration(const RockingModel& model, int side, double q) {
    require(side == 1 || side == -1, "side of rocking", "+1 or -1", side);
    return model.holding_acceleration(side, q);  // V'(q) / X(q)
}

}  // namespace vssw

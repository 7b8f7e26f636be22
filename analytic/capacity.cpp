#include "analytic/capacity.hpp"

#include "analytic/error.hpp"

namespace vssw {

double capacity_acceleration(const RockingModel& model, int side, double q) {
    require(side == 1 || side == -1, "side of rocking", "+1 or -1", side);
    const ModelTerms t = model.terms(q);
    const double restoring =
        model.gravity() * t.Y + model.overburden() * (t.L + side * model.eccentricity() * t.Le);  // V'(q)
    return restoring / t.X;
}

}  // namespace vssw

#include "analytic/wall_scene.hpp"

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"

namespace vssw {

void require_one_description(const Wall& wall) {
    if (wall.vssw.has_value() == wall.parapet.has_value())
        throw InputError("a wall scene must hold exactly one description (a VSSW or a parapet wall)");
    require_diaphragm(wall.diaphragm);
    if (wall.parapet && !wall.diaphragm.is_rigid())
        throw InputError(fmt::format("diaphragm period T_d = {:g} s: a parapet has no top support for a diaphragm to "
                                     "carry (T_d must be 0)",
                                     wall.diaphragm.period));
}

void require_model_follows_top(const Wall& wall, const GroundMotion& ground) {
    if (wall.diaphragm.is_rigid() || ground.is_zero()) return;
    throw InputError(fmt::format(
        "the analytic model cannot follow a flexible diaphragm (T_d = {:g} s) under a ground motion: the top lags "
        "the ground, so the wall lifts off with its upper block turning about the hinge on the pivot's side "
        "(Eq. 9e), a mechanism its one degree of freedom does not hold (docs/model/top-support.md); run an engine "
        "that moves its roller (ode, box2d, dart, bullet)",
        wall.diaphragm.period));
}

std::unique_ptr<RockingModel> analytic_model(const Wall& wall, Kinematics kinematics) {
    require_one_description(wall);
    if (wall.vssw) return make_vssw_model(*wall.vssw, kinematics);
    return make_parapet_model(*wall.parapet);
}

double closed_form_threshold(const Wall& wall) {
    require_one_description(wall);
    return wall.vssw ? eq12_threshold(*wall.vssw) : eq17_parapet_threshold(*wall.parapet);
}

}  // namespace vssw

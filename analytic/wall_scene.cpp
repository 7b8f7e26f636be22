#include "analytic/wall_scene.hpp"

#include "analytic/error.hpp"

namespace vssw {

void require_one_description(const Wall& wall) {
    if (wall.vssw.has_value() == wall.parapet.has_value())
        throw InputError("a wall scene must hold exactly one description (a VSSW or a parapet wall)");
}

std::unique_ptr<RockingModel> analytic_model(const Wall& wall, Kinematics kinematics) {
    require_one_description(wall);
    if (wall.vssw) return make_vssw_model(*wall.vssw, kinematics);
    return make_parapet_model(*wall.parapet);
}

}  // namespace vssw

#pragma once
// What an adapter does with the VSSW's top support (WallScene::diaphragm): a flexible one moves the roller by u_d(t) of
// Eq. (9d) relative to the ground (step_loop.hpp hands it over in GroundStep::top_u and top_v); an adapter whose
// roller cannot follow it refuses it here, naming why (docs/model/top-support.md, "The engines").
#include <string>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/engine.hpp"

namespace vssw::multibody {

inline void require_rigid_top(const WallScene& scene, const std::string& engine, const std::string& reason) {
    if (!scene.diaphragm.is_rigid())
        throw InputError(fmt::format("{} cannot move its roller with a flexible diaphragm (T_d = {:g} s): {}", engine,
                                     scene.diaphragm.period, reason));
}

}  // namespace vssw::multibody

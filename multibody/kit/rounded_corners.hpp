#pragma once
// Rounded corners in the engines' scenes (docs/contributing/engines.md, "Rounded corners"): every corner of every block
// rounded to the scene's radius r (WallScene::corner_radius), the blocks' masses, inertias and centres kept the
// rectangles' (the model's m_i and I_G,i: the corners removed are (4 - pi) r^2 of a block's 4 b h, 2e-4 of a Table 1 block
// at r/b = 0.1), the roller's guides still holding the nominal top corner (a point of the block, not of its outline).
#include <string>

#include "multibody/engine.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw::multibody {

// InputError for an engine that does not round its blocks yet when the scene's corner radius is not 0, naming the
// engine and why: an engine never runs a rounded wall with sharp blocks.
void require_sharp_corners(const std::string& engine, const WallScene& scene, const std::string& why);

// pose_at for rounded corners (scene.corner_radius() > 0): the lower block rolled without slip on its base arc by
// theta1, the upper block's bottom arc rolled on the lower block's top arc (equal circles: their line of centres turns
// by the mean of the two rotations), theta2 solved (Newton, from Eq. 2's sharp value) so that the nominal top corner
// on the pivot's side is on its guide, x = side b.
WallPose rounded_pose_at(const WallScene& scene, double theta1);

}  // namespace vssw::multibody

// DART's scene file (Engine::scene_file): the wall's blocks as URDF, the text the DART adapter loads with DART's own
// URDF loader to build its blocks, so that the file a user opens is what the run steps.
#pragma once

#include <dart/dynamics/SmartPointer.hpp>

#include <string>

#include "multibody/engine.hpp"

namespace vssw::multibody {

inline constexpr double kDartDepth = 1.0;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

// The blocks: a link each ("lower", and "upper" for a VSSW) with its mass and inertia per depth kDartDepth and its
// box (the flat part, b - r wide, for rounded corners), on a planar joint from the link "world": DART's PlanarJoint in
// its XY plane, q = (x, y, counter-clockwise angle), vssw's plane. A comment says what URDF cannot hold and the run
// adds: the ground, the roller, the rounded corners' capsules, friction, the release pose, N and the ground motion.
std::string wall_urdf(const WallScene& scene, double theta0);

// The blocks of wall_urdf()'s text as DART loads them, a skeleton each (as the contacts between them need): the
// loader makes one skeleton of the two trees under "world", which each block leaves by BodyNode::split.
// EngineFailure, with the loader's messages, when the text does not load or lacks a block the wall has (vssw: two).
struct UrdfBlocks {
    dart::dynamics::SkeletonPtr lower, upper;  // upper null for a parapet
};
UrdfBlocks load_wall_urdf(const std::string& text, bool vssw);

}  // namespace vssw::multibody

#pragma once
// The wall's energy in a sample, one sum for every adapter: the blocks' kinetic energy relative to the ground, the
// potential of both blocks' weights from the upright wall at rest, and the work N has not done (N times the top's
// rise), all per unit depth. An adapter reads its bodies (EnergyReading); the sum and its order of operations are
// here, so that every engine's energy is the same quantity (docs/architecture.md, "The stepping kit"). Engine-free.
#include "multibody/engine.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw::multibody {

// Kinetic energy of one block moving in the plane [J for the scene's depth]: its centre's velocity relative to the
// ground (vx, vy) and its spin omega, with the block's mass and its inertia about the centre.
inline double block_kinetic_energy(double mass, double inertia, double vx, double vy, double omega) {
    return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega;
}

// What an adapter reads off its bodies for a sample's energy (the upper block's fields ignored for a parapet).
struct EnergyReading {
    double kinetic_lower, kinetic_upper;  // [J] for the scene's depth, relative to the ground
    double y_lower, y_upper;              // the centres' heights [m]
    double y_top;                         // the height of N's point on the top face [m] (its centre unless eccentric)
};

class WallEnergy {
public:
    // depth: the adapter's out-of-plane depth [m] (its masses are the blocks' masses per unit depth times it).
    // contact_gap: how far the adapter's contacts lift the wall at rest [m] (Simbody's corner spheres: the lower block
    // by one, the upper block by two), so that the rest heights are the adapter's own.
    WallEnergy(const WallScene& scene, double depth, double contact_gap = 0.0)
        : s_(block_sizes(scene)),
          vssw_(scene.is_vssw()),
          g_(scene.gravity()),
          N_(scene.overburden() * depth),
          depth_(depth),
          y_lower0_(s_.h_lower + contact_gap),
          y_upper0_(2.0 * s_.h_lower + s_.h_upper + 2.0 * contact_gap),
          y_top0_(2.0 * (s_.h_lower + s_.h_upper) + (vssw_ ? 2.0 : 1.0) * contact_gap) {}

    // Sets p.top_dy, p.kinetic and p.potential (per unit depth) from the reading.
    void fill(TrajectorySample& p, const EnergyReading& r) const {
        p.top_dy = r.y_top - y_top0_;
        p.kinetic = (r.kinetic_lower + (vssw_ ? r.kinetic_upper : 0.0)) / depth_;
        p.potential = (s_.m_lower * depth_ * g_ * (r.y_lower - y_lower0_) +
                       (vssw_ ? s_.m_upper * depth_ * g_ * (r.y_upper - y_upper0_) : 0.0) + N_ * p.top_dy) /
                      depth_;
    }

private:
    BlockSizes s_;
    bool vssw_;
    double g_, N_, depth_, y_lower0_, y_upper0_, y_top0_;
};

}  // namespace vssw::multibody

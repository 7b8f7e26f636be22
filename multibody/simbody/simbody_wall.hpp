#pragma once
// What both Simbody routes (simbody_engine.cpp, simbody_compliant.cpp) share: the loads on the wall and the reading of
// a state into a trajectory sample. Includes <Simbody.h>: only those two files may include it (engine headers stay
// inside their adapter).
#include <Simbody.h>

#include <cmath>
#include <functional>
#include <utility>

#include "multibody/engine.hpp"
#include "multibody/kit/energy.hpp"
#include "multibody/kit/scene_geometry.hpp"
#include "multibody/kit/step_loop.hpp"  // Rocking
#include "multibody/kit/wall_parts.hpp"

namespace vssw::multibody::simbody_wall {

constexpr double kDepth = 1.0;  // [m] out-of-plane depth of the blocks (masses and energies per unit depth)

// Pseudo-forces -m a_h at the centres of mass (fixed supports) and N on the top face, at load_x from its centre toward
// theta1 > 0 (only when N > 0).
// The acceleration comes from the route: the rigid route's step midpoint value, the compliant route's a_h(t).
class WallLoads : public SimTK::Force::Custom::Implementation {
public:
    WallLoads(std::function<double(const SimTK::State&)> a_h, const SimTK::MobilizedBody& lower,
              const SimTK::MobilizedBody* upper, const BlockSizes& sizes, double N, double load_x)
        : a_h_(std::move(a_h)), lower_(lower), has_upper_(upper != nullptr), sizes_(sizes), N_(N), load_x_(load_x) {
        if (upper) upper_ = *upper;
    }
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        const double a = a_h_(s);
        if (a != 0.0) {
            lower_.applyForceToBodyPoint(s, SimTK::Vec3(0), SimTK::Vec3(-sizes_.m_lower * kDepth * a, 0, 0),
                                         body_forces);
            if (has_upper_)
                upper_.applyForceToBodyPoint(s, SimTK::Vec3(0), SimTK::Vec3(-sizes_.m_upper * kDepth * a, 0, 0),
                                             body_forces);
        }
        if (N_ > 0.0) {
            const SimTK::MobilizedBody& top = has_upper_ ? upper_ : lower_;
            const double half = has_upper_ ? sizes_.h_upper : sizes_.h_lower;
            top.applyForceToBodyPoint(s, SimTK::Vec3(load_x_, half, 0), SimTK::Vec3(0, -N_, 0), body_forces);
        }
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0.0; }

private:
    std::function<double(const SimTK::State&)> a_h_;
    SimTK::MobilizedBody lower_, upper_;
    bool has_upper_;
    BlockSizes sizes_;
    double N_;
    double load_x_;  // N's point on the top face from its centre [m]
};

// Clockwise angle of a body about z.
inline double clockwise_angle(const SimTK::MobilizedBody& body, const SimTK::State& s) {
    const SimTK::Rotation& r = body.getBodyRotation(s);
    return -std::atan2(r[1][0], r[0][0]);
}

// A point of a body (body coordinates lx, ly) in the world.
inline SimTK::Vec3 world_point(const SimTK::MobilizedBody& body, const SimTK::State& s, double lx, double ly) {
    return body.findStationLocationInGround(s, SimTK::Vec3(lx, ly, 0));
}

// A block as RunMonitor reads it (its origin is its centre; the ground does not move in either route).
inline BlockState block_state(const SimTK::MobilizedBody& body, const SimTK::State& s) {
    const SimTK::Vec3 c = body.getBodyOriginLocation(s), v = body.getBodyOriginVelocity(s);
    return {c[0], c[1], clockwise_angle(body, s), v[0], v[1], -body.getBodyAngularVelocity(s)[2]};
}

// The wall as a sampler of states: its bodies and its energy sum (the kit's, with the route's rest heights).
struct WallBodies {
    SimTK::MobilizedBody lower, upper;
    bool vssw;
    BlockSizes sizes;
    WallEnergy energy;
    double load_x;  // N's point on the top face from its centre, toward theta1 > 0 [m]
};

// The lower body's rotation and rate of a state realized to Velocity.
inline Rocking rocking_of(const WallBodies& w, const SimTK::State& st) {
    return {clockwise_angle(w.lower, st), -w.lower.getBodyAngularVelocity(st)[2]};
}

// The lower body's motion of a state realized to Velocity (Excitation::motion_only: the rest NaN).
inline TrajectorySample motion_of(const WallBodies& w, const SimTK::State& st, double t) {
    const Rocking r = rocking_of(w, st);
    return motion_sample(t, r.theta1, r.theta1_dot);
}

// The rest of a full sample of a state realized to Velocity (contacts left to the route, which counts them its own
// way): theta2, the top's rise and the energy.
inline void fill_sample(const WallBodies& w, const SimTK::State& st, TrajectorySample& p) {
    const BlockSizes& s = w.sizes;
    const SimTK::MobilizedBody& top_body = w.vssw ? w.upper : w.lower;
    const double top_half = w.vssw ? s.h_upper : s.h_lower;
    p.theta2 = w.vssw ? clockwise_angle(w.upper, st) : 0.0;
    // Homogeneous blocks: I = m (b^2 + h^2) / 3 about the centre.
    auto kinetic = [&](const SimTK::MobilizedBody& body, double mass, double half_h) {
        const SimTK::Vec3 v = body.getBodyOriginVelocity(st);
        return block_kinetic_energy(mass, mass * (s.b * s.b + half_h * half_h) / 3.0, v[0], v[1],
                                    body.getBodyAngularVelocity(st)[2]);
    };
    w.energy.fill(p, {kinetic(w.lower, s.m_lower * kDepth, s.h_lower),
                      w.vssw ? kinetic(w.upper, s.m_upper * kDepth, s.h_upper) : 0.0,
                      w.lower.getBodyOriginLocation(st)[1], w.vssw ? w.upper.getBodyOriginLocation(st)[1] : 0.0,
                      world_point(top_body, st, w.load_x, top_half)[1]});
}

// The sample of a state realized to Velocity (contacts left to the route).
inline TrajectorySample sample_of(const WallBodies& w, const SimTK::State& st, double t) {
    TrajectorySample p = motion_of(w, st, t);
    fill_sample(w, st, p);
    return p;
}

}  // namespace vssw::multibody::simbody_wall

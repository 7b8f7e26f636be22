#pragma once
// The compliant route's contacts as one Force::Custom: each corner sphere against the one half-space it can touch,
// with the force law of Simbody's CompliantContactSubsystem (HertzCircular generator, Hunt-Crossley dissipation,
// Stribeck friction; Simbody 3.7's CompliantContactSubsystem.cpp and ContactTracker.cpp, HalfSpaceSphere), evaluated
// directly. Why: the subsystem re-pairs every surface with every other through ContactTrackerSubsystem at each
// evaluation (cliques, type dispatch, cache entries behind dynamic_cast) though in a two-block planar wall the pairs
// never change; measured share of the run time in docs/contributing/engines.md "Simbody (3.7)". Includes <Simbody.h>:
// only the Simbody adapter's files may include this header.
#include <Simbody.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace vssw::multibody::simbody_wall {

// A sphere of radius r centred on a station of `sphere_body` against the half-space of `plane_body` whose surface
// passes through `plane_point` with outward normal `normal` (both in plane_body's frame).
struct CornerPair {
    SimTK::MobilizedBody plane_body, sphere_body;
    SimTK::Vec3 plane_point, normal;  // plane body frame
    SimTK::Vec3 centre;               // sphere body frame
    double mu;                        // Simbody's combined coefficient 2 mu1 mu2 / (mu1 + mu2): mu or 0 here
};

// The contact law's constants (the pair's effective values, as the subsystem combines two equal materials).
struct CornerLaw {
    double stiffness;    // [Pa] effective modulus E: fH = 4/3 E sqrt(r) x^3/2
    double radius;       // [m] r, also the effective radius of a sphere on a half-space
    double dissipation;  // [s/m] Hunt-Crossley c
    double transition;   // [m/s] Stribeck transition velocity vt
};

class CornerContacts : public SimTK::Force::Custom::Implementation {
public:
    CornerContacts(std::vector<CornerPair> pairs, const CornerLaw& law)
        : pairs_(std::move(pairs)), law_(law), hertz_(4.0 / 3.0 * law.stiffness * std::sqrt(law.radius)) {}

    // Pairs pressing (penetration > 0) in a state realized to Position: what getNumContactForces counted.
    int count_touching(const SimTK::State& s) const {
        int n = 0;
        for (const CornerPair& p : pairs_) n += geometry(s, p).depth > 0.0 ? 1 : 0;
        return n;
    }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        for (const CornerPair& p : pairs_) {
            const Geometry g = geometry(s, p);
            if (g.depth <= 0.0) continue;
            const double x = g.depth;
            // Relative velocity of the sphere body's material point at the contact point against the plane body's.
            const SimTK::Vec3 vel =
                station_velocity(s, p.sphere_body, g.point) -
                (p.plane_body.isGround() ? SimTK::Vec3(0) : station_velocity(s, p.plane_body, g.point));
            const double xdot = -SimTK::dot(vel, g.normal);  // penetration rate
            const double fH = hertz_ * x * std::sqrt(x);
            const double fN = fH * (1.0 + 1.5 * law_.dissipation * xdot);
            if (fN <= 0.0) continue;  // "yanking": no force, as the subsystem
            SimTK::Vec3 force = fN * g.normal;
            if (p.mu > 0.0) {
                const SimTK::Vec3 slip = vel + xdot * g.normal;  // tangential part
                const double v2 = slip.normSqr();
                if (v2 > SimTK::square(SimTK::SignificantReal)) {
                    const double v = std::sqrt(v2);
                    // Stribeck with equal static and dynamic coefficients: mu stepUp(v / vt) below vt (SimTK:
                    // 10u^3 - 15u^4 + 6u^5), mu above.
                    const double mu = p.mu * SimTK::stepUp(std::min(v / law_.transition, 1.0));
                    force -= (fN * mu / v) * slip;
                }
            }
            apply(s, p.sphere_body, g.point, force, body_forces);
            if (!p.plane_body.isGround()) apply(s, p.plane_body, g.point, -force, body_forces);
        }
    }
    // Hertz's stored energy 2/5 fH x, as the subsystem reports it.
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
        double pe = 0.0;
        for (const CornerPair& p : pairs_) {
            const double x = geometry(s, p).depth;
            if (x > 0.0) pe += 0.4 * hertz_ * x * x * std::sqrt(x);
        }
        return pe;
    }

private:
    struct Geometry {
        double depth;        // penetration x (> 0 when touching)
        SimTK::Vec3 point;   // contact point in Ground: half way between the plane and the sphere's deepest point
        SimTK::Vec3 normal;  // outward normal of the half-space in Ground (towards the sphere)
    };
    Geometry geometry(const SimTK::State& s, const CornerPair& p) const {
        const SimTK::Transform& X_GP = p.plane_body.getBodyTransform(s);
        const SimTK::Vec3 c = p.sphere_body.getBodyTransform(s) * p.centre;
        const SimTK::Vec3 n = X_GP.R() * p.normal;
        const double depth = law_.radius - SimTK::dot(c - X_GP * p.plane_point, n);
        return {depth, c - (law_.radius - 0.5 * depth) * n, n};
    }
    static SimTK::Vec3 station_velocity(const SimTK::State& s, const SimTK::MobilizedBody& b, const SimTK::Vec3& pG) {
        const SimTK::SpatialVec& V = b.getBodyVelocity(s);
        return V[1] + V[0] % (pG - b.getBodyOriginLocation(s));
    }
    static void apply(const SimTK::State& s, const SimTK::MobilizedBody& b, const SimTK::Vec3& pG,
                      const SimTK::Vec3& f, SimTK::Vector_<SimTK::SpatialVec>& body_forces) {
        body_forces[b.getMobilizedBodyIndex()] += SimTK::SpatialVec((pG - b.getBodyOriginLocation(s)) % f, f);
    }

    std::vector<CornerPair> pairs_;
    CornerLaw law_;
    double hertz_;  // 4/3 E sqrt(r)
};

}  // namespace vssw::multibody::simbody_wall

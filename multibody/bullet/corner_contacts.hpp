#pragma once
// The wall's contacts from its corners, written straight into Bullet manifolds for the solver (included by
// bullet_engine.cpp only: Bullet's headers stay inside multibody/bullet/).
//
// A planar wall of two boxes can touch in known places only: a bottom corner of the lower block on the ground, a
// bottom corner of the upper block on the lower block's top face (the blocks are equally wide, so that also covers a
// top corner of the lower block on the upper's bottom face), and the upper block's top corner on its guide line (the
// roller). Each is one point in the plane, with its signed distance, every step. Bullet's box-box detector found the
// same corners as two points each (the depth's two ends) and only once they overlapped: a contact found a step late
// had already penetrated, and the landing, the hinge and the roller's guide were resolved at different steps (the
// restitution moved by several % with the step; docs/contributing/engines.md "Bullet"). Here every corner is in the
// solve every step: one that is apart by d becomes a speculative row (Bullet lets the gap close by d/dt and no more,
// then holds it), so the base, the hinge and the roller all take the impact in the same step, and the roller is no
// longer a limit that acts only once its corner is past the line.
#include <btBulletDynamicsCommon.h>

#include <array>
#include <memory>

namespace vssw::multibody {

class CornerContacts {
public:
    // ground: the static (or kinematic) box whose top face is y = 0; upper may be null (a parapet). b: half width;
    // h_lower, h_upper: half heights; friction at the ground and at the hinge (the roller is frictionless): each
    // point's m_combinedFriction, Bullet's Coulomb bound on its two friction rows, set here rather than mixed.
    // corner_radius: r of every block corner (kit/rounded_corners.hpp), 0 for the sharp blocks. roller: the body whose
    // x the guides' lines follow, the ground's unless a flexible top support carries them (its origin's x is then the
    // lines' offset, as the ground's is); the roller holds the nominal top corners, rounded or not.
    CornerContacts(btRigidBody& ground, btRigidBody& lower, btRigidBody* upper, double b, double h_lower,
                   double h_upper, double friction, double hinge_friction, double corner_radius = 0.0,
                   btRigidBody* roller = nullptr)
        : lower_(lower), upper_(upper), roller_(roller ? *roller : ground), b_(b), h_lower_(h_lower),
          h_upper_(h_upper), friction_(friction), hinge_friction_(hinge_friction), r_(corner_radius) {
        manifolds_[0] = make(lower, ground);
        if (upper) {
            manifolds_[1] = make(*upper, lower);
            manifolds_[2] = make(*upper, roller_);
        }
    }

    // Rewrites every manifold for the bodies' present poses (the guides' lines move with the ground, or with the
    // flexible top support's carrier). Out of line: a profile tells this contact generation, the engine's scheme done
    // by the adapter, from the rest of the adapter's work (bench/adapter_share.py).
    [[gnu::noinline]] void update() {
        if (r_ > 0.0) {
            update_rounded();
            return;
        }
        btPersistentManifold& base = *manifolds_[0];
        base.clearManifold();
        const btTransform& tl = lower_.getWorldTransform();
        for (double side : {-1.0, 1.0}) {
            const btVector3 corner = tl * btVector3(side * b_, -h_lower_, 0);
            add(base, corner, btVector3(corner.x(), 0, 0), btVector3(0, 1, 0), friction_);
        }
        if (!upper_) return;
        btPersistentManifold& hinge = *manifolds_[1];
        hinge.clearManifold();
        const btTransform& tu = upper_->getWorldTransform();
        const btVector3 n = tl.getBasis() * btVector3(0, 1, 0);  // the lower block's top face normal
        const btVector3 face = tl * btVector3(0, h_lower_, 0);
        for (double side : {-1.0, 1.0}) {
            const btVector3 corner = tu * btVector3(side * b_, -h_upper_, 0);
            add(hinge, corner, corner - n * (corner - face).dot(n), n, hinge_friction_);
        }
        update_roller(tu);
    }

    // The constructor always makes the base's manifold, so the list is never empty.
    btPersistentManifold** manifolds() { return raw_.data(); }
    int count() const { return count_; }

    // Contact points in touch (not speculative): at or inside the surface, to a tolerance far below any step's
    // motion (1e-9 m).
    int touching() const {
        int n = 0;
        for (int i = 0; i < count_; ++i)
            for (int j = 0; j < manifolds_[i]->getNumContacts(); ++j)
                if (manifolds_[i]->getContactPoint(j).getDistance() <= 1e-9) ++n;
        return n;
    }

private:
    // Rounded corners: each corner is an arc of radius r about a centre r inside both faces. The base: per side the
    // lowest point of the arc's circle, or, when the block has turned that side up (the circle's lowest point is then
    // inside the block, past the arc's end), the arc's end on the flat base, the flat part's corner; at rest both are
    // the flat's end (b - r, 0). The hinge: per side the two arcs' circles (the lower block's top one, the upper
    // block's bottom one), normal along their centres' line, distance that line's length less 2 r: at rest the flats'
    // common end, then the arcs rolling on each other; the circles lie inside the blocks, so the distance never
    // reports an overlap the outlines do not have. The roller holds the nominal top corners, as for sharp blocks.
    void update_rounded() {
        const double in = b_ - r_;
        btPersistentManifold& base = *manifolds_[0];
        base.clearManifold();
        const btTransform& tl = lower_.getWorldTransform();
        for (double side : {-1.0, 1.0}) {
            const btVector3 centre = tl * btVector3(side * in, -(h_lower_ - r_), 0);
            const btVector3 down = tl.getBasis().transpose() * btVector3(0, -1, 0);  // the world's down, block frame
            const btVector3 lowest = side * down.x() >= 0.0 ? centre - btVector3(0, r_, 0)
                                                            : tl * btVector3(side * in, -h_lower_, 0);
            add(base, lowest, btVector3(lowest.x(), 0, 0), btVector3(0, 1, 0), friction_);
        }
        if (!upper_) return;
        btPersistentManifold& hinge = *manifolds_[1];
        hinge.clearManifold();
        const btTransform& tu = upper_->getWorldTransform();
        for (double side : {-1.0, 1.0}) {
            const btVector3 c_lower = tl * btVector3(side * in, h_lower_ - r_, 0);
            const btVector3 c_upper = tu * btVector3(side * in, -(h_upper_ - r_), 0);
            const btVector3 n = (c_upper - c_lower).normalized();  // on the lower block, towards the upper
            add(hinge, c_upper - n * r_, c_lower + n * r_, n, hinge_friction_);
        }
        update_roller(tu);
    }

    // The roller, rounded corners or not: both guides, each pushing the nominal top corner on its side back inside
    // (normal from the line towards the wall). The corner off the pivot's side sits inside its line by about
    // b theta2^2, a speculative row that stays idle. Measured: with only the pivot's guide in the solve (chosen before
    // the step, by the corners), the guide of the new pivot missed the impact step and took its impulse a step later,
    // a second impact that moved the Table 1 walls' restitution by up to 2.8 % at xi 0.5; with both, within 1 %
    // (docs/contributing/engines.md "Bullet"). (Two guides as Bullet joint limits had squeezed the top with opposing impulses;
    // as unilateral contact rows they do not.) The lines follow the roller's body (the ground, or a flexible top's).
    void update_roller(const btTransform& tu) {
        const double x0 = roller_.getWorldTransform().getOrigin().x();
        btPersistentManifold& roller = *manifolds_[2];
        roller.clearManifold();
        for (double side : {-1.0, 1.0}) {
            const btVector3 corner = tu * btVector3(side * b_, h_upper_, 0);
            add(roller, corner, btVector3(x0 + side * b_, corner.y(), 0), btVector3(-side, 0, 0), 0.0);
        }
    }

    std::unique_ptr<btPersistentManifold> make(btRigidBody& a, btRigidBody& b) {
        constexpr double kEverywhere = 1e30;  // every point written is solved: the manifold filters none
        auto m = std::make_unique<btPersistentManifold>(&a, &b, 0, kEverywhere, kEverywhere);
        raw_[static_cast<std::size_t>(count_)] = m.get();
        ++count_;
        return m;
    }

    // A point of body A (the manifold's body 0) at on_a, its nearest point of body B's surface at on_b, normal on B
    // pointing towards A; the distance is signed (negative: penetration).
    static void add(btPersistentManifold& m, const btVector3& on_a, const btVector3& on_b, const btVector3& normal,
                    double friction) {
        const btVector3 local_a = m.getBody0()->getWorldTransform().invXform(on_a);
        const btVector3 local_b = m.getBody1()->getWorldTransform().invXform(on_b);
        btManifoldPoint p(local_a, local_b, normal, (on_a - on_b).dot(normal));
        p.m_positionWorldOnA = on_a;
        p.m_positionWorldOnB = on_b;
        p.m_combinedFriction = friction;
        p.m_combinedRestitution = 0.0;
        m.addManifoldPoint(p);
    }

    btRigidBody& lower_;
    btRigidBody* upper_;
    btRigidBody& roller_;  // what the guides' lines follow: the ground, or a flexible top support's carrier
    double b_, h_lower_, h_upper_, friction_, hinge_friction_;
    double r_;  // the corners' radius (0: sharp)
    std::array<std::unique_ptr<btPersistentManifold>, 3> manifolds_{};
    std::array<btPersistentManifold*, 3> raw_{};
    int count_ = 0;
};

}  // namespace vssw::multibody

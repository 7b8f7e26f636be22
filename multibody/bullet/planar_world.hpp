#pragma once
// A btDiscreteDynamicsWorld whose step does only what a wall of two boxes on a ground box needs (included by
// bullet_engine.cpp only: Bullet's headers stay inside multibody/bullet/).
//
// btDiscreteDynamicsWorld::stepSimulation also updates every body's bounding box and asks the broadphase for pairs,
// runs the narrowphase of every pair, looks for predictive (CCD) contacts, builds simulation islands (a union-find over
// bodies, manifolds and constraints, then a sort), runs actions and puts bodies to sleep. Here the contacts come from
// the corners (corner_contacts.hpp), no body has a CCD threshold, the blocks are one island and never sleep, and there
// are no actions. So a step is: the kinematic ground's transform and velocity, gravity, the caller's contacts, one
// solve of every manifold, integration, forces cleared. Measured in docs/contributing/engines.md ("Bullet", where the time goes).
#include <btBulletDynamicsCommon.h>

#include <vector>

namespace vssw::multibody {

class PlanarDynamicsWorld : public btDiscreteDynamicsWorld {
public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

    // The solver's list of bodies follows the world's non-static bodies, which change only here (not every step).
    void addRigidBody(btRigidBody* body) override {
        btDiscreteDynamicsWorld::addRigidBody(body);
        sync_bodies();
    }
    void addRigidBody(btRigidBody* body, int group, int mask) override {
        btDiscreteDynamicsWorld::addRigidBody(body, group, mask);
        sync_bodies();
    }
    void removeRigidBody(btRigidBody* body) override {
        btDiscreteDynamicsWorld::removeRigidBody(body);
        sync_bodies();
    }

    // One step of dt in two halves, the same sequence as stepSimulation(dt, 0, dt) less the parts named above; the
    // caller writes the contacts in between, once the kinematic ground stands where it will be during the step.
    void begin_step(btScalar dt) {
        saveKinematicState(dt);  // a moving ground's transform and velocity, from its motion state
        applyGravity();
        predictUnconstraintMotion(dt);  // damping (zero here) and the interpolation transforms
    }
    void finish_step(btScalar dt, btPersistentManifold** manifolds, int n_manifolds) {
        getSolverInfo().m_timeStep = dt;
        btTypedConstraint** constraints = m_constraints.size() > 0 ? &m_constraints[0] : nullptr;
        // The whole scene as one island: what btSimulationIslandManager would hand the solver, without building it.
        // (stepSimulation also calls the solver's prepareSolve and allSolved around this; btConstraintSolver's are
        // empty and btSequentialImpulseConstraintSolver keeps them, so they are left out.)
        m_constraintSolver->solveGroup(bodies_.data(), static_cast<int>(bodies_.size()), manifolds, n_manifolds,
                                       constraints, m_constraints.size(), getSolverInfo(), nullptr, getDispatcher());
        integrateTransforms(dt);
        clearForces();
    }

private:
    void sync_bodies() {
        bodies_.clear();
        for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) bodies_.push_back(m_nonStaticRigidBodies[i]);
    }

    std::vector<btCollisionObject*> bodies_;
};

}  // namespace vssw::multibody

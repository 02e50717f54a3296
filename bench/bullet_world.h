#pragma once
// A Bullet 3.24 world as the Bullet benchmarks build it (bullet_pile, bullet_scenes): Bullet's
// default collision configuration, DBVT broad phase and sequential-impulse solver, a ground plane
// y = 0, and boxes of one shape with one friction coefficient and no restitution.
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

namespace rbsim::bench {

struct BulletWorld {
  BulletWorld(double boxEdge, double friction)
      : boxShape(btVector3(0.5, 0.5, 0.5) * btScalar(boxEdge)), friction(friction) {}

  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;  // Bullet's default and recommended broad phase
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btStaticPlaneShape groundShape{btVector3(0, 1, 0), 0};
  btBoxShape boxShape;
  double friction;  // [1]
  std::vector<std::unique_ptr<btDefaultMotionState>> motionStates;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  ~BulletWorld() {
    for (auto& body : bodies) world.removeRigidBody(body.get());
  }

  btRigidBody* add(btCollisionShape* shape, btScalar mass, const btVector3& position) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    btTransform transform;
    transform.setIdentity();
    transform.setOrigin(position);
    motionStates.push_back(std::make_unique<btDefaultMotionState>(transform));
    btRigidBody::btRigidBodyConstructionInfo info(mass, motionStates.back().get(), shape, inertia);
    info.m_friction = btScalar(friction);
    info.m_restitution = 0;
    bodies.push_back(std::make_unique<btRigidBody>(info));
    world.addRigidBody(bodies.back().get());
    return bodies.back().get();
  }
};

}  // namespace rbsim::bench

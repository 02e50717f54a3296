// soft/soft_contact through the World: a rigid box thrown at a soft block in free space exchanges
// momentum with it (the total is kept), pushes it, and leaves no node inside the box.
#include <memory>

#include <gtest/gtest.h>

#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/world.h"
#include "rbsim/world/systems.h"

namespace rbsim {
namespace {

TEST(SoftContact, RigidBoxAndSoftBlockExchangeMomentumExactly) {
  Settings settings;
  settings.gravity = Vec3::Zero();
  settings.timeStep = 1.0 / 240.0;
  World world(settings);
  BodyDef box;
  box.mesh = std::make_shared<const Mesh>(makeBox(Vec3(0.4, 0.4, 0.4)));
  box.mass = 20.0;
  box.inertiaBody = cuboidInertia(20.0, Vec3(0.4, 0.4, 0.4));
  box.position = Vec3(-1.0, 0.1, 0.05);
  world.addBody(box);
  world.body(world.idAt(0)).setVelocity(Vec3(3.0, 0.0, 0.0));
  SoftBodyDef soft;
  soft.mesh = makeTetBox(Vec3(1.0, 1.0, 1.0), 4, 4, 4);
  soft.position = Vec3(0.6, 0.0, 0.0);
  soft.density = 100.0;
  soft.youngsModulus = 2e4;
  soft.damping = 5.0;
  addSoftBody(world, soft);
  const auto total = [&] { return Vec3(world.bodies()[0].state().linearMomentum + softBodies(world)[0].linearMomentum()); };
  const Vec3 before = total();
  for (int step = 0; step < 240; ++step) world.step();
  EXPECT_LT((total() - before).norm(), 1e-9 * before.norm()) << "momentum exchanged, not created";
  EXPECT_LT(world.bodies()[0].velocity().x(), 2.5) << "the block slowed the box";
  EXPECT_GT(softBodies(world)[0].linearMomentum().x(), 5.0) << "and was pushed";
  // No node is left inside the box.
  const RigidBody& b = world.bodies()[0];
  for (const Vec3& x : softBodies(world)[0].positions()) {
    const Vec3 local = b.rotation().transpose() * (x - b.position());
    EXPECT_GT(local.cwiseAbs().maxCoeff(), 0.2 - 1e-9);
  }
}

}  // namespace
}  // namespace rbsim

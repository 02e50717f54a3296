// The example of docs/cpp-api.md, "Changes while running", as it stands there (between the
// markers; tests/python/test_changes.py checks the two are the same text), and what it does.
#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <string>

#include "rbsim/body/shape_body.h"
#include "rbsim/world/body_changes.h"
#include "rbsim/world/joint_changes.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"

namespace rbsim::test::changes_doc_example {
namespace {

TEST(ChangesDocExample, RunsAsDocumented) {
  // docs/cpp-api.md begin
  rbsim::World world(rbsim::Settings{});
  world.addPlane(rbsim::Plane{});
  rbsim::BodyDef def = rbsim::shapeBodyDef(rbsim::Shape::sphere(0.1), 1.0, "ball");
  def.position = rbsim::Vec3(0.0, 1.1, 0.0);
  const rbsim::BodyId ball = world.addBody(def);
  const rbsim::World start = world;                                  // a saved state
  rbsim::setBodyMaterial(world, ball, rbsim::Material{0.8, 0.6, 0.5});  // restitution, mu_s, mu_k, from the next step
  rbsim::setBodyMass(world, ball, 2.0, 2.0 * world.body(ball).inertiaBody());  // v and omega stay; P, L follow
  rbsim::CollisionFilter nothing;
  nothing.mask = 0;
  rbsim::setBodyFilter(world, ball, nothing);                        // from the next step it collides with nothing
  rbsim::BodyDef rod = rbsim::shapeBodyDef(rbsim::Shape::box(rbsim::Vec3(0.5, 0.05, 0.05)), 1.0, "rod");  // half extents [m]
  rod.position = rbsim::Vec3(3.5, 2.0, 0.0);
  rbsim::JointDef hinge;
  hinge.type = rbsim::JointDef::Type::Hinge;
  hinge.bodyA = world.addBody(rod);
  hinge.anchor = rbsim::Vec3(3.0, 2.0, 0.0);
  const rbsim::JointId j = world.addJoint(hinge);
  rbsim::setJointMotor(world, j, true, -2.0, 50.0);                  // on: speed [rad/s], largest torque [N m]
  rbsim::setJointLimits(world, j, true, -1.0, 1.0);                  // [rad]
  world.step();
  rbsim::removeJoint(world, j);                                      // j is stale from now on
  std::string refused;
  try {
    rbsim::setBodyMaterial(world, ball, rbsim::Material{1.5, 0.6, 0.5});
  } catch (const std::invalid_argument& e) {
    refused = e.what();  // setBodyMaterial: body 'ball': restitution: expected a coefficient in [0, 1]
  }
  world = start;                                                     // back to the saved state, old values and all
  // docs/cpp-api.md end
  EXPECT_EQ(refused, "setBodyMaterial: body 'ball': restitution: expected a coefficient in [0, 1]");
  EXPECT_EQ(world.body(ball).mass(), 1.0);  // the saved World's
  EXPECT_EQ(bodyMaterial(world, ball).restitution, 0.0);
  EXPECT_EQ(world.bodies().size(), 1u);
}

}  // namespace
}  // namespace rbsim::test::changes_doc_example

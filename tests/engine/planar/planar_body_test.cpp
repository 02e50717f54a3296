// planar/planar_body: seed 002's 2D rigid bodies against the 3D engine constrained to the xy
// plane: the same inertia (I = I_33), the same motion under a force at a point, and the same
// collision impulse with restitution and friction.
#include "rbsim/planar/planar_body.h"

#include <cmath>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "rbsim/dynamics/impulse.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

std::vector<Vec2> rectangle(double w, double h, const Vec2& offset = Vec2::Zero()) {
  return {offset + Vec2(-0.5 * w, -0.5 * h), offset + Vec2(0.5 * w, -0.5 * h), offset + Vec2(0.5 * w, 0.5 * h),
          offset + Vec2(-0.5 * w, 0.5 * h)};
}

TEST(PlanarBody, RectangleInertiaIsI33OfTheBoxAndTheCentroidIsFound) {
  const PlanarBody body("plate", rectangle(2.0, 0.5, Vec2(3.0, -1.0)), 4.0);
  EXPECT_NEAR(body.inertia(), 4.0 * (4.0 + 0.25) / 12.0, 1e-12);
  EXPECT_NEAR(body.inertia(), cuboidInertia(4.0, Vec3(2.0, 0.5, 0.1))(2, 2), 1e-12);
  Vec2 centre = Vec2::Zero();
  for (const Vec2& p : body.polygon()) centre += p / 4.0;
  EXPECT_LT(centre.norm(), 1e-12) << "re-centred on the centroid";
  EXPECT_THROW(PlanarBody("cw", {Vec2(0, 0), Vec2(0, 1), Vec2(1, 0)}, 1.0), std::invalid_argument);
  EXPECT_THROW(PlanarBody("massless", rectangle(1, 1), 0.0), std::invalid_argument);
}

TEST(PlanarBody, MatchesThe3DEngineConstrainedToThePlane) {
  const double w = 1.2, h = 0.4, d = 0.3, m = 2.0, dt = 1.0 / 240.0;
  const Vec2 pushPoint(0.5, 0.2);  // body frame
  const Vec2 push(3.0, 1.5);       // world frame [N]
  PlanarBody planar("box", rectangle(w, h), m);
  planar.state().position = Vec2(0.0, 2.0);

  Settings settings;
  settings.detectCollisions = false;
  settings.integrator = Integrator::SymplecticEuler;
  settings.timeStep = dt;
  World world(settings);
  BodyDef def;
  def.mesh = std::make_shared<const Mesh>(makeBox(Vec3(w, h, d)));
  def.mass = m;
  def.inertiaBody = cuboidInertia(m, Vec3(w, h, d));
  def.position = Vec3(0.0, 2.0, 0.0);
  world.addBody(def);
  ScriptedForce force;
  force.body = world.idAt(0);
  force.force = Vec3(push.x(), push.y(), 0.0);
  force.point = Vec3(pushPoint.x(), pushPoint.y(), 0.0);
  force.pointFrame = Frame::Body;
  force.start = 0.0;
  force.end = 0.5;
  world.addForce(force);

  for (int step = 0; step < 480; ++step) {
    if (world.time() < force.end) planar.applyForceAtPoint(push, planar.state().position + rotation2(planar.state().angle) * pushPoint);
    planar.step(dt, Vec2(0.0, -9.81));
    world.step();
  }
  const RigidBody& body = world.bodies()[0];
  const Quat q = body.orientation();
  const double angle3d = 2.0 * std::atan2(q.z(), q.w());
  EXPECT_NEAR(planar.state().position.x(), body.position().x(), 1e-10);
  EXPECT_NEAR(planar.state().position.y(), body.position().y(), 1e-10);
  EXPECT_NEAR(std::remainder(planar.state().angle - angle3d, 2.0 * M_PI), 0.0, 1e-10);
  EXPECT_NEAR(planar.angularVelocity(), body.angularVelocity().z(), 1e-10);
  EXPECT_NEAR(planar.state().angularMomentum, body.state().angularMomentum.z(), 1e-10);
  EXPECT_LT(std::abs(body.position().z()) + body.angularVelocity().head<2>().norm(), 1e-12) << "the 3D motion stayed planar";
  EXPECT_GT(std::abs(planar.state().angle), 0.3) << "the push turned it";
}

TEST(PlanarImpulse, EqualsThe3DCollisionImpulseInThePlane) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int sticking = 0, sliding = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double m1 = 1.0 + u(rng) * 0.5, m2 = 2.0 + u(rng), i1 = 0.3 + 0.2 * u(rng), i2 = 0.5 + 0.3 * u(rng);
    const Vec2 r1(u(rng), u(rng)), r2(u(rng), u(rng));
    const double angle = u(rng) * M_PI;
    const Vec2 n(std::cos(angle), std::sin(angle));
    const Vec2 velocity = -2.0 * n + 1.5 * Vec2(u(rng), u(rng));
    Material material;
    material.restitution = 0.5 + 0.5 * u(rng);
    material.staticFriction = 0.5 + 0.4 * u(rng);
    material.kineticFriction = 0.8 * material.staticFriction;
    const Mat2 k2 = planarImpulseFactor(1.0 / m1, 1.0 / i1, r1) + planarImpulseFactor(1.0 / m2, 1.0 / i2, r2);
    const PlanarImpulse planar = collisionImpulse<2>(k2, velocity, n, material);
    // The same contact in 3D: z the principal axis of I_33 = i, the other moments arbitrary.
    const Mat3 inv1 = Vec3(1.0 / 0.7, 1.0 / 0.9, 1.0 / i1).asDiagonal(), inv2 = Vec3(1.0 / 1.1, 1.0 / 0.6, 1.0 / i2).asDiagonal();
    const Mat3 k3 = impulseFactor(1.0 / m1, inv1, Vec3(r1.x(), r1.y(), 0.0)) + impulseFactor(1.0 / m2, inv2, Vec3(r2.x(), r2.y(), 0.0));
    const CollisionImpulse full = collisionImpulse(k3, Vec3(velocity.x(), velocity.y(), 0.0), Vec3(n.x(), n.y(), 0.0), material);
    ASSERT_EQ(planar.colliding, full.colliding);
    EXPECT_EQ(planar.sticking, full.sticking) << trial;
    EXPECT_LT((Vec3(planar.impulse.x(), planar.impulse.y(), 0.0) - full.impulse).norm(), 1e-12 * (1.0 + full.impulse.norm())) << trial;
    (planar.sticking ? sticking : sliding) += 1;
  }
  EXPECT_GT(sticking, 10);
  EXPECT_GT(sliding, 10);
}

}  // namespace
}  // namespace rbsim

// Friction, resting contact and stacking through the whole pipeline: a box sliding to a stop at
// v0^2 / (2 mu_k g), an incline it sticks on or slides down (tan theta against mu_s), a dropped
// box coming to rest, a stack and a pyramid standing, a bouncing box never rising above its apex.
#include <cmath>

#include <gtest/gtest.h>

#include "../../sanitized_build.h"
#include "dynamics_util.h"

namespace rbsim {
namespace {

constexpr double kRestingG = 9.81;  // [m/s^2], Settings' default |g|

Settings awakeSettings() {
  Settings s;
  s.allowSleep = false;  // the assertions are about the solver, not about sleeping hiding motion
  return s;
}

Material friction(double staticFriction, double kineticFriction, double restitution = 0.0) {
  Material m;
  m.staticFriction = staticFriction;
  m.kineticFriction = kineticFriction;
  m.restitution = restitution;
  return m;
}

TEST(Friction, ASlidingBoxStopsAtTheKinematicDistance) {
  // Deceleration mu_k g while sliding, so it stops after v0^2 / (2 mu_k g) = 0.815 m, in
  // v0 / (mu_k g) = 0.815 s. The ground and the box share the material, so mu_k is the pair's.
  const double mu = 0.5, v0 = 2.0;
  World world(awakeSettings());
  world.addPlane(Plane{}, friction(mu, mu));
  BodyDef box = test::boxWith(Vec3(0.4, 0.2, 0.4), 1.0, Vec3(0.0, 0.1, 0.0), friction(mu, mu), "box");
  box.velocity = Vec3(v0, 0.0, 0.0);
  world.addBody(box);
  const RigidBody& b = world.bodies()[0];
  // Half way through the slide the speed is v0 - mu_k g t.
  const double halfTime = 0.5 * v0 / (mu * kRestingG);
  while (world.time() < halfTime - 1e-9) world.step();
  EXPECT_NEAR(b.velocity().x(), v0 - mu * kRestingG * world.time(), 0.02);
  for (int i = 0; i < 480; ++i) world.step();
  const double distance = v0 * v0 / (2.0 * mu * kRestingG);
  EXPECT_NEAR(b.position().x(), distance, 0.01 * distance + 0.005);
  EXPECT_LT(b.velocity().norm(), 1e-3);
  // Rounding alone moves it sideways: 1.2e-6 m at 10 substeps (under 1e-6 at 8).
  EXPECT_NEAR(b.position().z(), 0.0, 1e-5) << "a straight slide stays straight";
}

// A box released on an incline of angle theta: static friction holds it when tan theta < mu_s
// (no creep beyond 1 mm in 10 s); beyond, it slides with acceleration g (sin - mu_k cos).
double slideAfter(double thetaDegrees, double seconds, double mu_s, double mu_k, double* acceleration = nullptr) {
  const double theta = thetaDegrees * M_PI / 180.0;
  World world(awakeSettings());
  const Vec3 normal(-std::sin(theta), std::cos(theta), 0.0);  // the slope rises towards +x
  world.addPlane(Plane{normal, 0.0}, friction(mu_s, mu_k));
  BodyDef box = test::boxWith(Vec3(0.4, 0.2, 0.4), 1.0, 0.1 * normal, friction(mu_s, mu_k), "box");
  box.orientation = Quat(Eigen::AngleAxisd(theta, Vec3::UnitZ()));
  world.addBody(box);
  for (int i = 0; i < 24; ++i) world.step();  // settle into the contact
  const Vec3 start = world.bodies()[0].position();
  const Vec3 downhill(-std::cos(theta), -std::sin(theta), 0.0);
  const double v1 = world.bodies()[0].velocity().dot(downhill);
  const double t1 = world.time();
  while (world.time() < t1 + seconds - 1e-9) world.step();
  if (acceleration) *acceleration = (world.bodies()[0].velocity().dot(downhill) - v1) / (world.time() - t1);
  return (world.bodies()[0].position() - start).dot(downhill);
}

TEST(Friction, ABoxStaysPutOnAnInclineShallowerThanTheFrictionAngle) {
  // atan(0.6) = 30.96 degrees.
  EXPECT_LT(std::abs(slideAfter(25.0, 10.0, 0.6, 0.5)), 1e-3);
  EXPECT_LT(std::abs(slideAfter(30.0, 10.0, 0.6, 0.5)), 1e-3);
}

TEST(Friction, ABoxSlidesDownAnInclineSteeperThanTheFrictionAngle) {
  double acceleration = 0.0;
  const double theta = 32.0 * M_PI / 180.0;
  EXPECT_GT(slideAfter(32.0, 1.0, 0.6, 0.5, &acceleration), 0.1);
  EXPECT_NEAR(acceleration, kRestingG * (std::sin(theta) - 0.5 * std::cos(theta)), 0.02);
}

TEST(RestingContact, ADroppedBoxComesToRestWithinTheSlopAndStaysThere) {
  Settings s = awakeSettings();
  World world(s);
  world.addPlane(Plane{});
  BodyDef box = test::boxWith(Vec3(0.5, 0.5, 0.5), 2.0, Vec3(0.0, 1.0, 0.0), Material{}, "box");
  box.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3(1.0, 0.0, 1.0).normalized()));
  world.addBody(box);
  const RigidBody& b = world.bodies()[0];
  while (world.time() < 3.0) world.step();  // fall, tumble, settle
  const Vec3 rest = b.position();
  double fastest = 0.0, deepest = 0.0;
  while (world.time() < 13.0) {
    world.step();
    fastest = std::max(fastest, b.velocity().norm());
    deepest = std::max(deepest, -test::lowestVertexHeight(b));
  }
  EXPECT_LT(fastest, 1e-3) << "jitter [m/s]";
  EXPECT_LT(deepest, s.contactSlop + 1e-3) << "penetration [m]";
  EXPECT_LT((b.position() - rest).norm(), 1e-3);
}

TEST(RestingContact, AStackOfTenBoxesStandsForTenSeconds) {
  World world(awakeSettings());
  world.addPlane(Plane{});
  const double size = 0.5;
  for (int i = 0; i < 10; ++i) {
    world.addBody(test::boxWith(Vec3(size, size, size), 1.0, Vec3(0.0, (i + 0.5) * size, 0.0), Material{},
                                "box" + std::to_string(i)));
  }
  const Vec3 start = world.bodies().back().position();
  while (world.time() < 10.0) world.step();
  EXPECT_LT((world.bodies().back().position() - start).norm(), 0.01) << (world.bodies().back().position() - start).transpose();
}

TEST(RestingContact, APyramidWithTenBoxesAtTheBaseStands) {
  World world(awakeSettings());
  world.addPlane(Plane{});
  const double size = 0.5, spacing = 0.55;
  std::vector<Vec3> starts;
  for (int row = 0; row < 10; ++row) {
    for (int k = 0; k < 10 - row; ++k) {
      const Vec3 x((k - 0.5 * (9 - row)) * spacing, (row + 0.5) * size, 0.0);
      world.addBody(test::boxWith(Vec3(size, size, size), 1.0, x, Material{}, "b" + std::to_string(starts.size())));
      starts.push_back(x);
    }
  }
  // 5 s; 1 s under the sanitizers, where every contact of the pyramid is already solved at every
  // step (5 s took 34 s of the sanitizer run, docs/ci.md).
  const double seconds = test::kSanitizedBuild ? 1.0 : 5.0;
  while (world.time() < seconds) world.step();
  double worst = 0.0;
  for (std::size_t i = 0; i < starts.size(); ++i) worst = std::max(worst, (world.bodies()[i].position() - starts[i]).norm());
  EXPECT_LT(worst, 0.02) << "largest displacement of any box [m]";
}

TEST(RestingContact, ABouncingBoxNeverRisesAboveItsPreviousApex) {
  for (double e : {0.3, 0.6, 0.9}) {
    World world(awakeSettings());
    world.addPlane(Plane{}, friction(0.6, 0.5, e));
    world.addBody(test::boxWith(Vec3(0.3, 0.3, 0.3), 1.0, Vec3(0.0, 2.0, 0.0), friction(0.6, 0.5, e), "box"));
    const RigidBody& b = world.bodies()[0];
    double apex = b.position().y(), previous = b.velocity().y();
    int bounces = 0;
    while (world.time() < 6.0) {
      world.step();
      const double vy = b.velocity().y();
      if (previous > 0.0 && vy <= 0.0) {  // an apex
        EXPECT_LE(b.position().y(), apex + 1e-9) << "e = " << e;
        apex = b.position().y();
        ++bounces;
      }
      previous = vy;
    }
    EXPECT_GE(bounces, 1) << "e = " << e;
  }
}

}  // namespace
}  // namespace rbsim

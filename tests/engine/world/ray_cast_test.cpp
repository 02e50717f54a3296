// World ray casts (engine/include/rbsim/world/ray_cast.h, issue 39): distances, points and normals
// against closed-form answers for a sphere, a rotated box, a capsule and the ground plane; the
// nearest of several; the reach; a start inside; bodies asleep and static; bad rays refused.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/world/ray_cast.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

constexpr double kTolerance = 1e-9;  // [m] the shapes' queries are exact to rounding (hulls to 1e-9)

BodyId add(World& world, const Shape& shape, const Vec3& position, const Quat& orientation = Quat::Identity(),
           bool isStatic = false) {
  BodyDef def = shapeBodyDef(shape, 1.0, "b" + std::to_string(world.bodies().size()));
  def.position = position;
  def.orientation = orientation;
  def.isStatic = isStatic;
  return world.addBody(def);
}

void expectVec(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR((a - b).norm(), 0.0, kTolerance) << a.transpose() << " vs " << b.transpose();
}

TEST(RayCast, ASphereIsHitWhereItsEquationSays) {
  World world{Settings{}};
  const BodyId ball = add(world, Shape::sphere(0.5), Vec3(0.0, 1.0, 0.0));
  // Off-centre by 0.3: enters at z = -sqrt(0.5^2 - 0.3^2) = -0.4.
  const auto hit = rayCast(world, Vec3(0.3, 1.0, -5.0), Vec3(0.0, 0.0, 2.0), 100.0);
  ASSERT_TRUE(hit);
  EXPECT_FALSE(hit->isPlane);
  EXPECT_EQ(hit->body, ball);
  EXPECT_NEAR(hit->distance, 4.6, kTolerance);
  expectVec(hit->point, Vec3(0.3, 1.0, -0.4));
  expectVec(hit->normal, Vec3(0.6, 0.0, -0.8));
}

TEST(RayCast, ARotatedBoxIsHitOnTheFaceItTurnedTowardsTheRay) {
  World world{Settings{}};
  // Half extents (1, 0.5, 0.25) turned 90 degrees about y: its thin side faces -x.
  const Quat turn(Eigen::AngleAxisd(M_PI / 2.0, Vec3::UnitY()));
  add(world, Shape::box(Vec3(1.0, 0.5, 0.25)), Vec3(2.0, 0.0, 0.0), turn);
  const auto hit = rayCast(world, Vec3(-5.0, 0.1, 0.2), Vec3::UnitX(), 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 6.75, kTolerance);
  expectVec(hit->normal, Vec3(-1.0, 0.0, 0.0));
}

TEST(RayCast, TheNearestOfSeveralBodiesAndThePlaneIsReturned) {
  World world{Settings{}};
  world.addPlane(Plane{});
  const BodyId capsule = add(world, Shape::capsule(0.2, 0.5), Vec3(0.0, 3.0, 0.0));  // y from 2.3 to 3.7
  const BodyId low = add(world, Shape::sphere(0.25), Vec3(0.0, 1.0, 0.0), Quat::Identity(), /*isStatic=*/true);
  const auto down = rayCast(world, Vec3(0.0, 5.0, 0.0), -Vec3::UnitY(), 100.0);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->body, capsule);
  EXPECT_NEAR(down->distance, 5.0 - 3.7, kTolerance);
  expectVec(down->normal, Vec3::UnitY());
  // Beside the capsule, the static sphere; beside both, the ground.
  const auto sphere = rayCast(world, Vec3(0.1, 2.0, 0.0), -Vec3::UnitY(), 100.0);
  ASSERT_TRUE(sphere);
  EXPECT_EQ(sphere->body, low);
  const auto ground = rayCast(world, Vec3(3.0, 2.0, 0.0), Vec3(0.0, -1.0, 1.0), 100.0);
  ASSERT_TRUE(ground);
  EXPECT_TRUE(ground->isPlane);
  EXPECT_EQ(ground->plane, 0u);
  EXPECT_NEAR(ground->distance, 2.0 * std::sqrt(2.0), kTolerance);
  expectVec(ground->point, Vec3(3.0, 0.0, 2.0));
}

TEST(RayCast, NothingPastTheReachAndAStartInsideHitsAtZero) {
  World world{Settings{}};
  world.addPlane(Plane{});
  add(world, Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3(0.0, 2.0, 0.0));
  EXPECT_FALSE(rayCast(world, Vec3(0.0, 5.0, 0.0), -Vec3::UnitY(), 2.4));  // the box's top is 2.5 away
  EXPECT_TRUE(rayCast(world, Vec3(0.0, 5.0, 0.0), -Vec3::UnitY(), 2.5));
  EXPECT_FALSE(rayCast(world, Vec3(0.0, 5.0, 0.0), Vec3::UnitY(), 1e9));  // up: nothing
  EXPECT_FALSE(rayCast(world, Vec3(0.0, 5.0, 0.0), Vec3::UnitY(), std::numeric_limits<double>::infinity()));
  const auto inside = rayCast(world, Vec3(0.1, 2.2, 0.0), Vec3::UnitX(), 10.0);
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->distance, 0.0);
  const auto underground = rayCast(world, Vec3(5.0, -1.0, 0.0), Vec3::UnitX(), 10.0);
  ASSERT_TRUE(underground);
  EXPECT_TRUE(underground->isPlane);
  EXPECT_EQ(underground->distance, 0.0);
}

TEST(RayCast, ASleepingBodyIsHitToo) {
  World world{Settings{}};
  world.addPlane(Plane{});
  const BodyId box = add(world, Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3(0.0, 0.5, 0.0));
  for (int i = 0; i < 600 && world.body(box).awake(); ++i) world.step();
  ASSERT_FALSE(world.body(box).awake());
  const auto hit = rayCast(world, Vec3(0.0, 3.0, 0.0), -Vec3::UnitY(), 10.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->body, box);
  EXPECT_NEAR(hit->distance, 3.0 - world.body(box).position().y() - 0.5, 1e-6);
}

TEST(RayCast, BadRaysAreRefused) {
  World world{Settings{}};
  const double nan = std::nan("");
  EXPECT_THROW(rayCast(world, Vec3::Zero(), Vec3::Zero(), 1.0), std::invalid_argument);
  EXPECT_THROW(rayCast(world, Vec3::Zero(), Vec3(nan, 0.0, 1.0), 1.0), std::invalid_argument);
  EXPECT_THROW(rayCast(world, Vec3(nan, 0.0, 0.0), Vec3::UnitX(), 1.0), std::invalid_argument);
  EXPECT_THROW(rayCast(world, Vec3::Zero(), Vec3::UnitX(), -1.0), std::invalid_argument);
  EXPECT_THROW(rayCast(world, Vec3::Zero(), Vec3::UnitX(), nan), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim

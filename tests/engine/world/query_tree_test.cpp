// The queries' tree (engine/src/world/query_tree.h) is never stale: right after a body is added,
// destroyed, moved by hand or by a step (at dt 1/60 and 1/240), the queries see the World as it is
// now; a copy answers for itself. And closed-form answers: a sphere swept onto a box's face, a
// capsule onto the ground, a compound's child named, the nearest point of a sphere.
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_queries.h"
#include "world/query_tree.h"

namespace rbsim {
namespace {

constexpr double kClosedFormTolerance = 1e-9;  // [m] closed-form shapes answer exactly

BodyId addQuerySphere(World& world, double radius, const Vec3& at, bool isStatic = false) {
  BodyDef def = shapeBodyDef(Shape::sphere(radius), 1.0, "s" + std::to_string(world.bodies().size()));
  def.position = at;
  def.isStatic = isStatic;
  return world.addBody(def);
}

double rayHitDistance(const World& world, const Vec3& origin) {
  const std::optional<QueryHit> hit = castRay(world, origin, Vec3::UnitX(), 100.0);
  return hit ? hit->distance : -1.0;
}

TEST(QueryTree, AddDestroyAndMoveAreSeenAtOnce) {
  World world{Settings{}};
  const BodyId a = addQuerySphere(world, 0.5, Vec3(5.0, 0.0, 0.0));
  EXPECT_NEAR(rayHitDistance(world, Vec3::Zero()), 4.5, kClosedFormTolerance);
  const BodyId b = addQuerySphere(world, 0.5, Vec3(3.0, 0.0, 0.0));
  EXPECT_NEAR(rayHitDistance(world, Vec3::Zero()), 2.5, kClosedFormTolerance) << "the body added after the first query";
  world.body(b).setPosition(Vec3(2.0, 0.0, 0.0));
  EXPECT_NEAR(rayHitDistance(world, Vec3::Zero()), 1.5, kClosedFormTolerance) << "moved by hand";
  world.destroyBody(b);
  EXPECT_NEAR(rayHitDistance(world, Vec3::Zero()), 4.5, kClosedFormTolerance) << "destroyed";
  world.destroyBody(a);
  EXPECT_LT(rayHitDistance(world, Vec3::Zero()), 0.0) << "nothing left";
  EXPECT_TRUE(queryAabb(world, Aabb{Vec3::Constant(-1e9), Vec3::Constant(1e9)}).empty());
}

class QueryTreeSteps : public ::testing::TestWithParam<double> {};

TEST_P(QueryTreeSteps, AFallingBodyIsHitWhereItIsAfterEachStep) {
  Settings settings;
  settings.timeStep = GetParam();
  World world(settings);
  const BodyId ball = addQuerySphere(world, 0.25, Vec3(0.0, 10.0, 0.0));
  for (int i = 0; i < 30; ++i) {
    world.step();
    const double y = world.body(ball).position().y();
    // A ray along x at the centre's height hits the sphere's side, 0.25 before the centre.
    const std::optional<QueryHit> hit = castRay(world, Vec3(-5.0, y, 0.0), Vec3::UnitX(), 100.0);
    ASSERT_TRUE(hit) << "step " << i;
    EXPECT_NEAR(hit->distance, 4.75, kClosedFormTolerance);
    EXPECT_EQ(hit->body, ball);
  }
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, QueryTreeSteps, ::testing::Values(1.0 / 60.0, 1.0 / 240.0));

TEST(QueryTree, SleepingAndStaticBodiesAnswer) {
  World world{Settings{}};
  world.addPlane(Plane{});
  const BodyId ground = addQuerySphere(world, 1.0, Vec3(0.0, -0.5, 5.0), /*isStatic=*/true);
  const BodyId resting = addQuerySphere(world, 0.25, Vec3(0.0, 0.25, 0.0));
  for (int i = 0; i < 600 && world.body(resting).awake(); ++i) world.step();
  ASSERT_FALSE(world.body(resting).awake()) << "the ball fell asleep on the ground";
  const std::optional<QueryHit> down = castRay(world, Vec3(0.0, 3.0, 0.0), -Vec3::UnitY(), 10.0);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->body, resting);
  const std::optional<QueryHit> side = castRay(world, Vec3(0.0, 0.2, 2.0), Vec3::UnitZ(), 10.0);
  ASSERT_TRUE(side);
  EXPECT_EQ(side->body, ground);
}

TEST(QueryTree, ACopyAnswersForItselfAndTheOriginalIsUnchanged) {
  World world{Settings{}};
  const BodyId a = addQuerySphere(world, 0.5, Vec3(5.0, 0.0, 0.0));
  EXPECT_NEAR(rayHitDistance(world, Vec3::Zero()), 4.5, kClosedFormTolerance);
  World copy(world);
  copy.body(a).setPosition(Vec3(8.0, 0.0, 0.0));
  EXPECT_NEAR(rayHitDistance(copy, Vec3::Zero()), 7.5, kClosedFormTolerance);
  EXPECT_NEAR(rayHitDistance(world, Vec3::Zero()), 4.5, kClosedFormTolerance);
}

TEST(QueryTree, ACompoundNamesTheChildHitAndFiltersEachChild) {
  World world{Settings{}};
  CompoundPart left, right;
  left.shape = right.shape = Shape::box(Vec3(0.5, 0.5, 0.5));
  left.position = Vec3(-1.0, 0.0, 0.0);
  right.position = Vec3(1.0, 0.0, 0.0);
  right.filter.category = 0b10;
  BodyDef def = compoundBodyDef({left, right});
  def.position = Vec3(0.0, 0.0, 10.0);
  const BodyId body = world.addBody(def);
  const std::optional<QueryHit> hit = castRay(world, Vec3(1.0, 0.0, 0.0), Vec3::UnitZ(), 100.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->body, body);
  EXPECT_EQ(hit->child, 1);
  EXPECT_NEAR(hit->distance, 9.5, kClosedFormTolerance);
  EXPECT_FALSE(castRay(world, Vec3(1.0, 0.0, 0.0), Vec3::UnitZ(), 100.0, QueryFilter{1, 0b01, true}))
      << "the right child is in category 2, which the mask leaves out";
  EXPECT_TRUE(castRay(world, Vec3(-1.0, 0.0, 0.0), Vec3::UnitZ(), 100.0, QueryFilter{1, 0b01, true}));
}

TEST(QueryTree, ASphereSweptOntoABoxFaceStopsARadiusShort) {
  World world{Settings{}};
  BodyDef def = shapeBodyDef(Shape::box(Vec3(1.0, 1.0, 1.0)), 1.0, "box");
  def.position = Vec3(6.0, 0.0, 0.0);
  const BodyId box = world.addBody(def);
  // The sphere of radius 0.5 at the origin meets the face x = 5 when its centre is at 4.5.
  const std::optional<QueryHit> hit = castShape(world, QueryShape::sphere(0.5, Vec3(0.0, 0.3, 0.0)), Vec3::UnitX(), 10.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->body, box);
  EXPECT_LE(hit->distance, 4.5);
  EXPECT_NEAR(hit->distance, 4.5, kShapeCastTolerance);
  EXPECT_NEAR((hit->normal - Vec3(-1.0, 0.0, 0.0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((hit->point - Vec3(5.0, 0.3, 0.0)).norm(), 0.0, 1e-5);
  EXPECT_FALSE(castShape(world, QueryShape::sphere(0.5, Vec3(0.0, 1.6, 0.0)), Vec3::UnitX(), 10.0))
      << "passes above the box: 1.6 - 0.5 > 1";
  EXPECT_FALSE(castShape(world, QueryShape::sphere(0.5, Vec3::Zero()), Vec3::UnitX(), 4.0)) << "short of it";
}

TEST(QueryTree, ALyingCapsuleDroppedOntoTheGroundLandsOnItsSide) {
  World world{Settings{}};
  world.addPlane(Plane{});
  // A capsule along x (local y turned onto x), radius 0.2, centre at height 3: it lands at 2.8.
  const Quat lying(Eigen::AngleAxisd(M_PI / 2.0, Vec3::UnitZ()));
  const std::optional<QueryHit> hit =
      castShape(world, QueryShape::capsule(0.2, 1.0, Vec3(0.0, 3.0, 0.0), lying), -Vec3::UnitY(), 10.0);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->isPlane);
  EXPECT_NEAR(hit->distance, 2.8, kClosedFormTolerance);
  EXPECT_NEAR((hit->normal - Vec3::UnitY()).norm(), 0.0, kClosedFormTolerance);
}

TEST(QueryTree, OverlapAndClosestPointOfASphere) {
  World world{Settings{}};
  const BodyId ball = addQuerySphere(world, 1.0, Vec3(0.0, 0.0, 0.0));
  addQuerySphere(world, 1.0, Vec3(10.0, 0.0, 0.0));
  // A box whose corner is 0.9 from the centre overlaps; one 1.1 away does not.
  const Vec3 corner = Vec3::Constant(1.0 / std::sqrt(3.0));
  const auto boxAt = [&](double cornerDistance) {
    return QueryShape::box(Vec3::Constant(0.25), corner * cornerDistance + Vec3::Constant(0.25));
  };
  const std::vector<QueryHit> touching = overlapShape(world, boxAt(0.9));
  ASSERT_EQ(touching.size(), 1u);
  EXPECT_EQ(touching[0].body, ball);
  EXPECT_TRUE(overlapShape(world, boxAt(1.1)).empty());
  const std::optional<QueryHit> near = closestPoint(world, Vec3(0.0, 3.0, 0.0), 100.0);
  ASSERT_TRUE(near);
  EXPECT_EQ(near->body, ball);
  EXPECT_NEAR(near->distance, 2.0, kClosedFormTolerance);
  EXPECT_NEAR((near->point - Vec3(0.0, 1.0, 0.0)).norm(), 0.0, kClosedFormTolerance);
  const std::optional<QueryHit> inside = closestPoint(world, Vec3(0.0, 0.25, 0.0), 100.0);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->distance, -0.75, kClosedFormTolerance);
  EXPECT_FALSE(closestPoint(world, Vec3(0.0, 3.0, 0.0), 1.5)) << "nothing within 1.5";
}

TEST(QueryTree, BadQueriesAreRefused) {
  World world{Settings{}};
  addQuerySphere(world, 1.0, Vec3::Zero());
  EXPECT_THROW(castShape(world, QueryShape::sphere(-1.0, Vec3::Zero()), Vec3::UnitX(), 1.0), std::invalid_argument);
  EXPECT_THROW(castShape(world, QueryShape::sphere(1.0, Vec3::Zero()), Vec3::Zero(), 1.0), std::invalid_argument);
  EXPECT_THROW(castShape(world, QueryShape::box(Vec3::Ones(), Vec3::Zero(), Quat(2.0, 0.0, 0.0, 0.0)), Vec3::UnitX(), 1.0),
               std::invalid_argument);
  EXPECT_THROW(overlapShape(world, QueryShape::capsule(1.0, 1.0, Vec3::Constant(NAN))), std::invalid_argument);
  EXPECT_THROW(closestPoint(world, Vec3::Zero(), -1.0), std::invalid_argument);
  EXPECT_THROW(queryAabb(world, Aabb{Vec3::Constant(NAN), Vec3::Zero()}), std::invalid_argument);
}

TEST(QueryTree, ManyBodiesAtOnePointKeepLeavesSmall) {
  std::vector<Aabb> boxes(1000, Aabb{Vec3::Zero(), Vec3::Ones()});
  const QueryTree tree(boxes);
  std::size_t visited = 0;
  tree.walkBox(Aabb{Vec3::Constant(0.5), Vec3::Constant(0.6)}, [&](std::uint32_t) { ++visited; });
  EXPECT_EQ(visited, 1000u) << "every box is found once";
  EXPECT_GE(tree.nodeCount(), 2 * 1000 / kMaxLeafItems - 1);
}

}  // namespace
}  // namespace rbsim

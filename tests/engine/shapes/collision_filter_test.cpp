// Collision filters (shapes/collision_filter.h, Box2D v3's b2ShouldShapesCollide): the rule's
// every case, then the same cases in a World, where a filtered pair passes through and an
// accepted one rests.
#include <gtest/gtest.h>

#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

CollisionFilter filter(std::uint64_t category, std::uint64_t mask, std::int32_t group = 0) { return {category, mask, group}; }

TEST(CollisionFilterRule, DefaultsCollide) { EXPECT_TRUE(shouldCollide(CollisionFilter{}, CollisionFilter{})); }

TEST(CollisionFilterRule, EachMaskMustAcceptTheOthersCategory) {
  const CollisionFilter debris = filter(0b010, 0b001), player = filter(0b100, ~std::uint64_t{0b010}), ground = filter(0b001, ~0ull);
  EXPECT_TRUE(shouldCollide(debris, ground));   // both accept
  EXPECT_TRUE(shouldCollide(ground, debris));   // symmetric
  EXPECT_FALSE(shouldCollide(debris, player));  // neither accepts
  EXPECT_FALSE(shouldCollide(player, debris));
  // One side accepting is not enough: A accepts B's category, B's mask refuses A's.
  const CollisionFilter a = filter(0b01, 0b10), b = filter(0b10, 0b10);
  EXPECT_FALSE(shouldCollide(a, b));
  EXPECT_FALSE(shouldCollide(b, a));
  EXPECT_TRUE(shouldCollide(b, b));
  EXPECT_FALSE(shouldCollide(filter(0, ~0ull), CollisionFilter{}));  // in no category: nothing accepts it
  EXPECT_FALSE(shouldCollide(filter(1, 0), CollisionFilter{}));      // accepting nothing
}

TEST(CollisionFilterRule, ASharedPositiveGroupAlwaysCollides) {
  // Masks that refuse each other, overridden by the shared group.
  EXPECT_TRUE(shouldCollide(filter(0b01, 0b01, 3), filter(0b10, 0b10, 3)));
}

TEST(CollisionFilterRule, ASharedNegativeGroupNeverCollides) {
  EXPECT_FALSE(shouldCollide(filter(1, ~0ull, -2), filter(1, ~0ull, -2)));
}

TEST(CollisionFilterRule, DifferentGroupsFallBackToTheMasks) {
  EXPECT_TRUE(shouldCollide(filter(1, ~0ull, -1), filter(1, ~0ull, -2)));
  EXPECT_FALSE(shouldCollide(filter(0b01, 0b01, -1), filter(0b10, 0b10, 2)));
  EXPECT_TRUE(shouldCollide(filter(1, ~0ull, 5), filter(1, ~0ull, 0)));   // one without a group
  EXPECT_FALSE(shouldCollide(filter(1, 0b10, 5), filter(1, ~0ull, 0)));
}

// A ball dropped 0.5 m onto a static ball of the same radius, both with the given filters: it
// rests on top (centre 2 r above the lower one's) or falls through (below it after a second).
double heightAfterDrop(const CollisionFilter& falling, const CollisionFilter& resting, double dt) {
  Settings s;
  s.timeStep = dt;
  World w(s);
  BodyDef base = shapeBodyDef(Shape::sphere(0.5), 1.0, "base");
  base.isStatic = true;
  base.filter = resting;
  w.addBody(base);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.5), 1.0, "ball");
  ball.position = Vec3(0.0, 1.5, 0.0);
  ball.filter = falling;
  const BodyId id = w.addBody(ball);
  for (int i = 0; i < static_cast<int>(1.0 / dt); ++i) w.step();
  return w.body(id).position().y();
}

class CollisionFilterWorld : public testing::TestWithParam<double> {};

TEST_P(CollisionFilterWorld, AFilteredPairPassesThroughAndAnAcceptedOneRests) {
  const double dt = GetParam();
  const double onTop = 1.0, fallenThrough = 0.0;  // the ball's centre, resting or dropped 1.5 m less
  EXPECT_NEAR(heightAfterDrop({}, {}, dt), onTop, 1e-3);
  EXPECT_LT(heightAfterDrop(filter(0b10, 0b01), filter(0b01, 0b01), dt), fallenThrough);  // the base refuses it
  EXPECT_NEAR(heightAfterDrop(filter(0b10, 0b01), filter(0b01, 0b10), dt), onTop, 1e-3);
  EXPECT_LT(heightAfterDrop(filter(1, ~0ull, -7), filter(1, ~0ull, -7), dt), fallenThrough);
  EXPECT_NEAR(heightAfterDrop(filter(0b10, 0b01, 4), filter(0b01, 0b01, 4), dt), onTop, 1e-3);
}

// Planes are in the default category (1) and accept every category: a body whose mask leaves
// category 1 out falls through the ground, a body in another category lands on it.
TEST_P(CollisionFilterWorld, PlanesAreInTheDefaultCategory) {
  const double dt = GetParam();
  for (const bool acceptsGround : {true, false}) {
    Settings s;
    s.timeStep = dt;
    World w(s);
    w.addPlane(Plane{});
    BodyDef box = shapeBodyDef(Shape::box(Vec3::Constant(0.25)), 1.0, "box");
    box.position = Vec3(0.0, 1.0, 0.0);
    box.filter = filter(0b100, acceptsGround ? 0b001 : 0b110);
    const BodyId id = w.addBody(box);
    for (int i = 0; i < static_cast<int>(1.0 / dt); ++i) w.step();
    if (acceptsGround) {
      EXPECT_NEAR(w.body(id).position().y(), 0.25, 1e-3);
    } else {
      EXPECT_LT(w.body(id).position().y(), -1.0);
    }
  }
}

// A compound's children are filtered one by one: a bar of two boxes dropped flat onto two static
// balls, one under each end. With the right box refusing the balls' category, only the left box
// touches (its ball, as child 0) and the right end falls below the left; with both accepting, the
// bar lies level on both.
TEST_P(CollisionFilterWorld, ACompoundsChildrenAreFilteredEachOnItsOwn) {
  const double dt = GetParam();
  for (const bool rightAccepts : {true, false}) {
    Settings s;
    s.timeStep = dt;
    World w(s);
    for (const double x : {-0.75, 0.75}) {
      BodyDef ball = shapeBodyDef(Shape::sphere(0.25), 1.0, x < 0 ? "left" : "right");
      ball.isStatic = true;
      ball.position = Vec3(x, 0.0, 0.0);
      ball.filter = filter(0b10, ~0ull);
      w.addBody(ball);
    }
    CompoundPart left, right;
    left.shape = right.shape = Shape::box(Vec3(0.5, 0.05, 0.25));
    left.position = Vec3(-0.5, 0.0, 0.0);
    right.position = Vec3(0.5, 0.0, 0.0);
    if (!rightAccepts) right.filter = filter(1, 0b01);
    BodyDef bar = compoundBodyDef({left, right}, "bar");
    bar.position = Vec3(0.0, 0.35, 0.0);  // 5 cm above the balls
    const BodyId id = w.addBody(bar);
    const std::size_t barIndex = w.indexOf(id);
    for (int i = 0; i < static_cast<int>(0.3 / dt); ++i) w.step();
    int leftTouches = 0, rightTouches = 0;
    for (const Contact& c : w.contacts()) {
      if (c.kind != Contact::Kind::BodyBody || c.manifold.count == 0 || c.manifold.maxDepth() < -1e-3) continue;
      const std::size_t ball = c.a == barIndex ? c.b : c.a;
      const std::uint16_t child = c.a == barIndex ? c.childA : c.childB;
      (ball == 0 ? leftTouches : rightTouches) += 1;
      EXPECT_EQ(child, ball == 0 ? 0 : 1) << "each ball touches the box above it";
    }
    const double tilt = w.body(id).rotation().col(0).y();  // the bar's long axis: < 0 when the right end is lower
    EXPECT_EQ(leftTouches, 1);
    if (rightAccepts) {
      EXPECT_EQ(rightTouches, 1);
      EXPECT_NEAR(tilt, 0.0, 1e-3);
      EXPECT_NEAR(w.body(id).position().y(), 0.30, 2e-3);
    } else {
      EXPECT_EQ(rightTouches, 0);
      EXPECT_LT(tilt, -0.05);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, CollisionFilterWorld, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return info.param > 0.01 ? "dt60" : "dt240"; });

}  // namespace
}  // namespace rbsim

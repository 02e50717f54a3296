// Shape ids of a generation (world/shape_ids.h, world/shape_table.h; issue 58, as Box2D v3's
// b2ShapeId): every body added gets its shapes' ids in child order; destroying or breaking it
// makes them stale, even once their slots are reused; a batch removal leaves the table one
// removal after another leaves; ray casts, queries and contact events name the shape they found
// (the child actually hit). Snapshots: shape_ids_snapshot_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fracture/pieces.h"
#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/fracture/fracture.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/contact_events.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/ray_cast.h"
#include "rbsim/world/shape_ids.h"
#include "rbsim/world/spawner.h"
#include "rbsim/world/spring.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_queries.h"
#include "refusal.h"
#include "test_util.h"
#include "world/world_access.h"
#include "shape_ids_scene.h"

namespace rbsim::test::shape_ids {
namespace {

// A box, a row of three, a ball: shape slots 0, 1 2 3, 4 in the order added, each naming its body
// and child; a copy of the World names them alike.
TEST(ShapeIds, ABodysShapesAreNamedInChildOrder) {
  World w = emptyWorld();
  const BodyId box = w.addBody(boxDef(Vec3(1, 1, 1), 1.0, "box"));
  const BodyId three = w.addBody(row(3, "three"));
  const BodyId ball = w.addBody(shapeBodyDef(Shape::sphere(0.5), 1.0, "ball"));
  const std::vector<ShapeId> ids = shapeIds(w, three);
  ASSERT_EQ(ids.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(ids[k], (ShapeId{static_cast<std::uint32_t>(1 + k), 0}));
    EXPECT_EQ(shapeIdAt(w, three, k), ids[k]);
    EXPECT_EQ(bodyOf(w, ids[k]), three);
    EXPECT_EQ(childOf(w, ids[k]), k);
  }
  EXPECT_EQ(shapeIds(w, box), std::vector<ShapeId>{(ShapeId{0, 0})});
  EXPECT_EQ(shapeIds(w, ball), std::vector<ShapeId>{(ShapeId{4, 0})});
  EXPECT_EQ(bodyOf(w, ShapeId{4, 0}), ball);
  EXPECT_EQ(childOf(w, ShapeId{4, 0}), 0u);
  expectRefused([&] { shapeIdAt(w, three, 3); }, "shapeIdAt: child 3 of body 'three', which has 3 shapes");
  expectRefused([&] { shapeIdAt(w, box, 1); }, "shapeIdAt: child 1 of body 'box', which has 1 shapes");
  EXPECT_FALSE(isValid(w, ShapeId{5, 0}));  // never made
  EXPECT_FALSE(isValid(w, ShapeId{}));
  const World copy(w);
  EXPECT_EQ(allShapes(copy), allShapes(w));
  expectSameTable(copy, w);
}

// The row destroyed: its three ids are stale and refused by name, the others still name their
// bodies (the ball moved to the row's index); a new row takes the freed slots with the next
// generation, and the old ids stay stale.
TEST(ShapeIds, DestroyingABodyMakesItsShapeIdsStaleEvenOnceTheirSlotsAreReused) {
  World w = emptyWorld();
  const BodyId box = w.addBody(boxDef(Vec3(1, 1, 1), 1.0, "box"));
  const BodyId three = w.addBody(row(3, "three"));
  const BodyId ball = w.addBody(shapeBodyDef(Shape::sphere(0.5), 1.0, "ball"));
  const std::vector<ShapeId> old = shapeIds(w, three);
  const ShapeId ballShape = shapeIdAt(w, ball, 0);
  w.destroyBody(three);
  for (const ShapeId id : old) {
    EXPECT_FALSE(isValid(w, id));
    expectRefused([&] { bodyOf(w, id); }, "bodyOf: shape id (slot " + std::to_string(id.slot) + ", generation 0) is stale");
    expectRefused([&] { childOf(w, id); }, "childOf: shape id");
  }
  expectRefused([&] { shapeIds(w, three); }, "shapeIds: body id");
  EXPECT_EQ(w.indexOf(ball), 1u);
  EXPECT_EQ(bodyOf(w, ballShape), ball);
  EXPECT_EQ(shapeIdAt(w, ball, 0), ballShape);
  EXPECT_EQ(bodyOf(w, shapeIdAt(w, box, 0)), box);
  const BodyId again = w.addBody(row(3, "again"));
  const std::vector<ShapeId> reused = shapeIds(w, again);
  ASSERT_EQ(reused.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    // The free list gives the slots back last freed first: child 2's, 1's, 0's.
    EXPECT_EQ(reused[k], (ShapeId{old[2 - k].slot, 1}));
    EXPECT_EQ(childOf(w, reused[k]), k);
    EXPECT_EQ(bodyOf(w, reused[k]), again);
  }
  for (const ShapeId id : old) EXPECT_FALSE(isValid(w, id));
}

// Rows of 1 to 4 children and balls, half of them destroyed in a shuffled order: destroyBodies
// in one call and destroyBody one after another leave the same table, and the bodies added next
// get the same ids.
TEST(ShapeIds, ABatchRemovalLeavesTheTableOneRemovalAfterAnotherLeaves) {
  World batch = emptyWorld();
  std::vector<BodyId> ids;
  for (int k = 0; k < 12; ++k) {
    ids.push_back(batch.addBody(k % 3 == 0 ? shapeBodyDef(Shape::sphere(0.5), 1.0, "ball") : row(1 + k % 5, "row")));
  }
  World single(batch);
  const std::vector<BodyId> gone = {ids[7], ids[0], ids[10], ids[3], ids[5], ids[11]};
  batch.destroyBodies(gone);
  for (const BodyId id : gone) single.destroyBody(id);
  expectSameTable(batch, single);
  EXPECT_EQ(allShapes(batch), allShapes(single));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(shapeIds(batch, batch.addBody(row(4, "new"))), shapeIds(single, single.addBody(row(4, "new"))));
  }
  expectSameTable(batch, single);
}

// Rays from above onto each child of a row of three (and a ball, and the ground beside them):
// the hit names the child under the ray, by index and by shape id; closestPoint and
// overlapShape name the child nearest and overlapped.
TEST(ShapeIds, QueriesNameTheShapeTheyFound) {
  World w = emptyWorld();
  w.addPlane(Plane{});
  const BodyId three = w.addBody(row(3, "three"));
  BodyDef ballDef = shapeBodyDef(Shape::sphere(0.5), 1.0, "ball");
  ballDef.position = Vec3(0.0, 0.5, 4.0);
  const BodyId ball = w.addBody(ballDef);
  const Vec3 down(0.0, -1.0, 0.0);
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 above(kSpacing * (static_cast<double>(k) - 1.0), 5.0, 0.0);
    const std::optional<QueryHit> hit = castRay(w, above, down, 10.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, three);
    EXPECT_EQ(hit->child, static_cast<int>(k));
    EXPECT_EQ(hit->shape, shapeIdAt(w, three, k));
    EXPECT_NEAR(hit->distance, 5.0 - 2.0 * kHalf, 1e-9);
    const std::optional<WorldRayHit> plain = rayCast(w, above, down, 10.0);
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->shape, shapeIdAt(w, three, k));
    const std::optional<QueryHit> near = closestPoint(w, above - Vec3(0.0, 3.5, 0.0), 10.0);
    ASSERT_TRUE(near);
    EXPECT_EQ(near->shape, shapeIdAt(w, three, k));
  }
  const std::optional<QueryHit> onBall = castRay(w, Vec3(0.0, 5.0, 4.0), down, 10.0);
  ASSERT_TRUE(onBall);
  EXPECT_EQ(onBall->shape, shapeIdAt(w, ball, 0));
  const std::optional<QueryHit> onGround = castRay(w, Vec3(0.0, 5.0, -4.0), down, 10.0);
  ASSERT_TRUE(onGround && onGround->isPlane);
  EXPECT_EQ(onGround->shape, ShapeId{});
  QueryShape probe;
  probe.radius = 0.3;
  probe.position = Vec3(kSpacing, 1.0, 0.0);  // in child 2's top face
  QueryFilter noPlanes;
  noPlanes.planes = false;
  const std::vector<QueryHit> over = overlapShape(w, probe, noPlanes);
  ASSERT_EQ(over.size(), 1u);
  EXPECT_EQ(over[0].shape, shapeIdAt(w, three, 2));
}

class ShapeIdsEvents : public testing::TestWithParam<double> {};

// A ball dropped onto child 1 of a static row of three, another onto the ground: the begin
// events name the child's and the balls' shapes (the ground's side ShapeId{}); the first ball
// destroyed, its end event names its shape, now stale.
TEST_P(ShapeIdsEvents, ContactEventsNameTheTouchingShapes) {
  const double dt = GetParam();
  World w = emptyWorld(dt);
  w.addPlane(Plane{});
  const BodyId three = w.addBody(row(3, "three"));
  BodyDef onRow = shapeBodyDef(Shape::sphere(0.25), 1.0, "on row");
  onRow.position = Vec3(0.0, 1.5, 0.0);  // above child 1
  const BodyId a = w.addBody(onRow);
  BodyDef onGround = shapeBodyDef(Shape::sphere(0.25), 1.0, "on ground");
  onGround.position = Vec3(0.0, 0.5, 4.0);
  const BodyId b = w.addBody(onGround);
  const ShapeId aShape = shapeIdAt(w, a, 0), bShape = shapeIdAt(w, b, 0);
  std::vector<ContactBeginEvent> begun;
  for (int step = 0; step < static_cast<int>(std::lround(0.5 / dt)); ++step) {
    w.step();
    for (const ContactBeginEvent& e : contactEvents(w).begin) begun.push_back(e);
  }
  ASSERT_EQ(begun.size(), 2u);
  for (const ContactBeginEvent& e : begun) {
    if (e.pair.bodyB == a) {
      EXPECT_EQ(e.pair.bodyA, three);
      EXPECT_EQ(e.pair.childA, 1);
      EXPECT_EQ(e.pair.shapeA, shapeIdAt(w, three, 1));
      EXPECT_EQ(e.pair.shapeB, aShape);
    } else {
      EXPECT_EQ(e.pair.bodyB, b);
      EXPECT_EQ(e.pair.plane, 0);
      EXPECT_EQ(e.pair.shapeA, ShapeId{});
      EXPECT_EQ(e.pair.shapeB, bShape);
    }
  }
  w.destroyBody(a);
  w.step();
  const std::vector<ContactEndEvent>& ends = contactEvents(w).end;
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(ends[0].pair.shapeA, shapeIdAt(w, three, 1));
  EXPECT_EQ(ends[0].pair.shapeB, aShape);
  EXPECT_FALSE(isValid(w, aShape));
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, ShapeIdsEvents, testing::Values(1.0 / 60.0, 1.0 / 240.0));

// A slab broken by a projectile: the slab keeps its body id, its old shape id goes stale (the end
// event of its pair names it), and the slab and every piece added have valid new shape ids.
TEST(ShapeIds, FractureRetiresTheBrokenBodysShapes) {
  Settings s;
  s.gravity = Vec3::Zero();
  s.timeStep = 1.0 / 240.0;
  s.allowSleep = false;
  World w(s);
  BodyDef slab = boxDef(Vec3(0.2, 1.0, 1.0), 3.0, "slab");
  auto pattern = std::make_shared<FracturePattern>();
  pattern->impulseThreshold = 2.0;  // [N s]
  for (Mesh& piece : voronoiPieces(*slab.mesh, sitesInside(*slab.mesh, 6, 1))) {
    pattern->pieces.push_back(std::make_shared<const Mesh>(std::move(piece)));
  }
  slab.fracture = pattern;
  const BodyId target = w.addBody(slab);
  BodyDef projectile = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "projectile");
  projectile.position = Vec3(-0.5, 0.1, 0.05);
  projectile.velocity = Vec3(6.0, 0.0, 0.0);
  w.addBody(projectile);
  const ShapeId before = shapeIdAt(w, target, 0);
  for (int step = 0; step < 120 && fractureEvents(w).empty(); ++step) w.step();
  ASSERT_EQ(fractureEvents(w).size(), 1u);
  EXPECT_FALSE(isValid(w, before));
  expectRefused([&] { bodyOf(w, before); }, "bodyOf: shape id");
  ASSERT_EQ(contactEvents(w).end.size(), 1u);
  EXPECT_EQ(contactEvents(w).end[0].pair.shapeA, before);
  const ShapeId now = shapeIdAt(w, target, 0);
  EXPECT_NE(now, before);
  EXPECT_EQ(bodyOf(w, now), target);
  ASSERT_EQ(fractureEvents(w)[0].added.size(), pattern->pieces.size() - 1);
  for (const BodyId piece : fractureEvents(w)[0].added) EXPECT_EQ(bodyOf(w, shapeIdAt(w, piece, 0)), piece);
  EXPECT_EQ(allShapes(w).size(), w.bodies().size());
}

// A step that spawns two rows and then fails (a spring of infinite stiffness) is undone:
// the shape table is as before, the generations of the slots the burst took included, and the
// retry gives the spawned bodies the ids an untouched twin gives them.
TEST(ShapeIds, AFailedStepThatSpawnsLeavesTheTableAsItWas) {
  Settings s;
  s.gravity = Vec3::Zero();
  World w(s);
  const BodyId box = w.addBody(boxDef(Vec3(1, 1, 1), 1.0, "box"));
  w.destroyBody(w.addBody(row(2, "two")));  // two free slots for the burst to take
  SpawnerDef rows;
  rows.name = "rows";
  rows.prototype = row(2, "spawned");
  rows.prototype.isStatic = false;
  rows.count = 2;
  rows.start = w.time();  // due at the next step
  rows.regionMin = Vec3(-1, 20, -1);
  rows.regionMax = Vec3(1, 21, 1);
  addSpawner(w, rows);
  const World twin(w);
  Spring wild;
  wild.body = box;
  wild.anchor = Vec3(0, -1e6, 0);
  wild.stiffness = std::numeric_limits<double>::max();
  const SpringId wildSpring = addSpring(w, wild);
  EXPECT_THROW(w.step(), SimulationError);
  expectSameTable(w, twin);
  removeSpring(w, wildSpring);
  World retry(twin);
  w.step();
  retry.step();
  ASSERT_EQ(w.bodies().size(), 3u);
  EXPECT_EQ(allShapes(w), allShapes(retry));
  expectSameTable(w, retry);
}

// The example of docs/cpp-api.md, "Shape ids", as it stands there (between the markers;
// tests/python/test_cpp_doc_blocks.py checks the two are the same text), and what it says.
TEST(ShapeIdsDocExample, RunsAsDocumented) {
  // docs/cpp-api.md begin
  rbsim::World world(rbsim::Settings{});
  rbsim::CompoundPart left, right;
  left.shape = right.shape = rbsim::Shape::box(rbsim::Vec3(0.5, 0.5, 0.5));  // half extents [m]
  left.position = rbsim::Vec3(-2.0, 0.0, 0.0);
  right.position = rbsim::Vec3(2.0, 0.0, 0.0);
  rbsim::BodyDef def = rbsim::compoundBodyDef({left, right}, "table");
  def.isStatic = true;
  const rbsim::BodyId table = world.addBody(def);
  const std::vector<rbsim::ShapeId> shapes = rbsim::shapeIds(world, table);  // child 0, child 1
  const std::optional<rbsim::QueryHit> hit = rbsim::castRay(world, {2, 5, 0}, {0, -1, 0}, 10.0);
  const bool named = hit->shape == shapes[1] && rbsim::childOf(world, hit->shape) == 1;  // true
  world.destroyBody(table);
  const bool stale = !rbsim::isValid(world, shapes[1]);                     // true, for good
  // docs/cpp-api.md end
  EXPECT_EQ(hit->child, 1);
  EXPECT_TRUE(named);
  EXPECT_TRUE(stale);
  expectRefused([&] { rbsim::bodyOf(world, shapes[1]); }, "bodyOf: shape id (slot 1, generation 0) is stale");
}

}  // namespace
}  // namespace rbsim::test::shape_ids

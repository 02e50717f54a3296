// contactEvents(world) on many bodies (issue 57): on a random pile of boxes and balls the begins
// and ends of every step are exactly the pairs of shapes that entered and left the contacts()
// set (brute force, by id), bodies destroyed mid-run included; a resting stack is silent once
// settled, asleep or not; compound children and fracture name their pairs.
#include <algorithm>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "fracture/pieces.h"
#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/fracture/fracture.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"
#include "test_util.h"

namespace rbsim {
namespace {

// A pair of shapes by ids, sides in a fixed order: (plane + 1 or 0, A's slot, A's generation,
// B's slot, B's generation, child A, child B).
using PairKey = std::tuple<std::int64_t, std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, int, int>;

PairKey keyOf(const ContactPair& p) {
  PairKey k{p.plane + 1, p.bodyA.slot, p.bodyA.generation, p.bodyB.slot, p.bodyB.generation, p.childA, p.childB};
  if (p.plane == kNoPlane && std::make_pair(p.bodyB.slot, p.bodyB.generation) < std::make_pair(p.bodyA.slot, p.bodyA.generation)) {
    k = {0, p.bodyB.slot, p.bodyB.generation, p.bodyA.slot, p.bodyA.generation, p.childB, p.childA};
  }
  return k;
}

std::set<PairKey> touching(const World& w) {
  std::set<PairKey> out;
  for (const Contact& c : w.contacts()) {
    ContactPair p;
    if (c.kind == Contact::Kind::PlaneBody) {
      p.plane = static_cast<std::int64_t>(c.a);
    } else {
      p.bodyA = w.idAt(c.a);
    }
    p.bodyB = w.idAt(c.b);
    p.childA = c.childA;
    p.childB = c.childB;
    out.insert(keyOf(p));
  }
  return out;
}

template <typename Events>
std::set<PairKey> keysOf(const Events& events) {
  std::set<PairKey> out;
  for (const auto& e : events) EXPECT_TRUE(out.insert(keyOf(e.pair)).second) << "a pair reported twice in one step";
  return out;
}

using PileCase = std::tuple<Settings::ContactSolverMethod, double>;
class ContactEventsPile : public testing::TestWithParam<PileCase> {};

TEST_P(ContactEventsPile, EventsAreTheStepToStepDifferenceOfTheContactSets) {
  Settings s;
  s.solver = std::get<0>(GetParam());
  s.timeStep = std::get<1>(GetParam());
  World w(s);
  w.addPlane(Plane{});
  w.addPlane(Plane{Vec3::UnitX(), -1.0});   // two walls keep the pile together
  w.addPlane(Plane{-Vec3::UnitX(), -1.0});
  UniformRandom random(57);
  for (int i = 0; i < 30; ++i) {
    BodyDef d = i % 2 == 0 ? shapeBodyDef(Shape::box(Vec3(0.2, 0.15, 0.25)), 1.0, "b" + std::to_string(i))
                           : shapeBodyDef(Shape::sphere(0.18), 1.0, "b" + std::to_string(i));
    d.position = Vec3(random.between(-0.7, 0.7), 0.3 + 0.45 * i, random.between(-0.3, 0.3));
    d.orientation = random.rotation();
    d.material.restitution = 0.3;
    w.addBody(d);
  }
  std::size_t begins = 0, ends = 0;
  const int steps = static_cast<int>(4.0 / s.timeStep);
  for (int step = 0; step < steps; ++step) {
    const std::set<PairKey> before = touching(w);
    if (step == steps / 3 || step == steps / 2) {  // bodies in the pile go between steps
      w.destroyBodies({w.idAt(3), w.idAt(w.bodies().size() - 2)});
    }
    w.step();
    const std::set<PairKey> after = touching(w);
    std::set<PairKey> began, ended;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::inserter(began, began.end()));
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::inserter(ended, ended.end()));
    ASSERT_EQ(keysOf(contactEvents(w).begin), began) << "step " << step;
    ASSERT_EQ(keysOf(contactEvents(w).end), ended) << "step " << step;
    begins += began.size();
    ends += ended.size();
  }
  EXPECT_GT(begins, 60u);  // the test saw a pile form
  EXPECT_GT(ends, 10u);    // and pairs part, the destroyed bodies' among them
}

INSTANTIATE_TEST_SUITE_P(SolversAndSteps, ContactEventsPile,
                         testing::Combine(testing::Values(Settings::ContactSolverMethod::SoftStep,
                                                          Settings::ContactSolverMethod::Pgs),
                                          testing::Values(1.0 / 60.0, 1.0 / 240.0)));

class ContactEventsStack : public testing::TestWithParam<bool> {};

TEST_P(ContactEventsStack, ARestingStackIsSilentOnceSettledAsleepOrNot) {
  Settings s;
  s.allowSleep = GetParam();
  World w(s);
  w.addPlane(Plane{});
  for (int i = 0; i < 4; ++i) {
    BodyDef d = test::boxDef(Vec3(1.0, 0.5, 1.0), 1.0, "b" + std::to_string(i));
    d.position = Vec3(0, 0.25 + 0.5 * i, 0);
    w.addBody(d);
  }
  const int settle = static_cast<int>(2.0 / s.timeStep);
  for (int step = 0; step < settle; ++step) w.step();
  for (int step = 0; step < settle; ++step) {
    w.step();
    const ContactEvents& e = contactEvents(w);
    ASSERT_TRUE(e.begin.empty() && e.end.empty() && e.hit.empty()) << "step " << settle + step;
  }
  if (GetParam()) {  // it fell asleep, and kept its pairs touching
    for (const RigidBody& b : w.bodies()) EXPECT_FALSE(b.awake());
  }
  EXPECT_EQ(touching(w).size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(SleepOnAndOff, ContactEventsStack, testing::Bool());

TEST(ContactEventsCompound, TheTouchingChildrenAreNamed) {
  Settings s;
  World w(s);
  w.addPlane(Plane{});
  // A static table of two boxes (children 0 at x = -2, 1 at x = +2), a ball dropped on child 1.
  CompoundPart left, right;
  left.shape = right.shape = Shape::box(Vec3(0.5, 0.5, 0.5));
  left.position = Vec3(-2, 0.5, 0);
  right.position = Vec3(2, 0.5, 0);
  BodyDef table = compoundBodyDef({left, right}, "table");
  table.isStatic = true;
  const BodyId t = w.addBody(table);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.25), 1.0, "ball");
  ball.position = Vec3(2, 1.5, 0);
  const BodyId b = w.addBody(ball);
  // A dumbbell of two balls, child 1 lower, dropped on the ground beside it.
  CompoundPart high, low;
  high.shape = low.shape = Shape::sphere(0.2);
  high.position = Vec3(-0.5, 0.3, 0);
  low.position = Vec3(0.5, 0.0, 0);
  const BodyId d = w.addBody([&] {
    BodyDef def = compoundBodyDef({high, low}, "dumbbell");
    def.position = Vec3(6, 1.0, 0);
    return def;
  }());
  std::vector<ContactBeginEvent> begun;
  for (int step = 0; step < 120; ++step) {
    w.step();
    for (const ContactBeginEvent& e : contactEvents(w).begin) begun.push_back(e);
  }
  const auto ballOnTable = std::find_if(begun.begin(), begun.end(), [&](const ContactBeginEvent& e) { return e.pair.bodyB == b; });
  ASSERT_NE(ballOnTable, begun.end());
  EXPECT_EQ(ballOnTable->pair.bodyA, t);
  EXPECT_EQ(ballOnTable->pair.childA, 1);
  EXPECT_EQ(ballOnTable->pair.childB, 0);
  EXPECT_NEAR(ballOnTable->point.x(), 2.0, 1e-9);
  std::vector<int> dumbbellChildren;  // in the order they landed
  for (const ContactBeginEvent& e : begun) {
    if (e.pair.bodyB != d) continue;
    EXPECT_EQ(e.pair.plane, 0);
    EXPECT_EQ(e.pair.childA, 0);
    dumbbellChildren.push_back(e.pair.childB);
  }
  ASSERT_EQ(dumbbellChildren.size(), 2u);
  EXPECT_EQ(dumbbellChildren[0], 1);  // the lower ball first
  EXPECT_EQ(dumbbellChildren[1], 0);
}

TEST(ContactEventsFracture, ABrokenBodyEndsItsPairs) {
  Settings s;
  s.gravity = Vec3::Zero();
  s.timeStep = 1.0 / 240.0;
  s.allowSleep = false;
  World w(s);
  BodyDef slab = test::boxDef(Vec3(0.2, 1.0, 1.0), 3.0, "slab");
  auto pattern = std::make_shared<FracturePattern>();
  pattern->impulseThreshold = 2.0;  // [N s]
  for (Mesh& piece : voronoiPieces(*slab.mesh, sitesInside(*slab.mesh, 10, 1))) {
    pattern->pieces.push_back(std::make_shared<const Mesh>(std::move(piece)));
  }
  slab.fracture = pattern;
  const BodyId target = w.addBody(slab);
  BodyDef projectile = test::boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "projectile");
  projectile.position = Vec3(-0.5, 0.1, 0.05);
  projectile.velocity = Vec3(6.0, 0.0, 0.0);
  const BodyId p = w.addBody(projectile);
  bool touched = false;
  for (int step = 0; step < 120 && fractureEvents(w).empty(); ++step) {
    w.step();
    touched = touched || !contactEvents(w).begin.empty();
  }
  ASSERT_TRUE(touched);
  ASSERT_EQ(fractureEvents(w).size(), 1u);
  const std::vector<ContactEndEvent>& ends = contactEvents(w).end;
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(ends[0].pair.bodyA, target);
  EXPECT_EQ(ends[0].pair.bodyB, p);
  EXPECT_FALSE(contactEvents(w).hit.empty());  // 6 m/s against the slab
}

}  // namespace
}  // namespace rbsim

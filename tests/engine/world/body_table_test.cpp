// The World's body table (world/body_table.h, issue 58: one owner of every per-body column, one
// add and one removal): after batches of removals from a resting pile of mixed shapes, every
// column's row i still describes bodies()[i], checked against what each body's id was made with,
// not against another column; and a copied or moved World's collision pipeline works on its own
// table (a copy reading the original's rows would step the original's bodies).
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/world/world.h"
#include "world/world_access.h"

namespace rbsim {
namespace {

constexpr int kBodies = 48;               // in a 4 x 4 grid of columns, three high
constexpr double kPitch = 0.62;           // [m] between columns: 2 cm gaps between the widest shapes
constexpr double kLayer = 0.6;            // [m] between the layers' centres as dropped
constexpr double kFrictionStep = 0.005;   // [1] each body's static friction is its own: 0.2 + k step
constexpr double kSettleTime = 3.0;       // [s] long enough for most islands to fall asleep
constexpr int kBatches = 4;               // removals, each followed by steps
constexpr int kRemovedPerBatch = 5;
constexpr int kStepsBetween = 20;

Shape shapeOf(int k) {
  // Shapes that come to rest in a pile (a sphere or a capsule on its side would roll on for as
  // long as the test runs, and nothing would sleep).
  switch (k % 3) {
    case 0: return Shape::box(Vec3(0.25, 0.25, 0.25));
    case 1: return Shape::box(Vec3(0.28, 0.12, 0.2));
    default: return Shape::roundedBox(Vec3(0.2, 0.2, 0.2), 0.05);
  }
}

struct Made {
  double friction = 0.0;
  std::string name;
};

// Row by row, every column against what its body was made with (and the pipeline's own index).
// `stepped`: a step ran since the last add (a body is listed awake by the next step's scan).
void expectRowsMatch(const World& world, const std::map<std::uint32_t, Made>& madeBySlot, bool stepped = true) {
  const BodyTable& t = WorldAccess::table(world);
  const CollisionPipeline& collision = WorldAccess::collision(world);
  const std::size_t n = world.bodies().size();
  for (const std::size_t size : {t.materials.size(), t.solids.size(), t.fracturePatterns.size(), t.listed.size(),
                                 t.proxies.size(), t.radius.size(), t.thickness.size(), t.reach.size(), t.start.size(),
                                 t.fast.size(), t.hasGrid.size(), t.meshGround.size(), t.gap.size(), t.boxes.size(),
                                 t.keptContacts.size(), t.keys().size()}) {
    ASSERT_EQ(size, n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const BodyId id = world.idAt(i);
    const Made& made = madeBySlot.at(id.slot);
    const RigidBody& body = world.bodies()[i];
    EXPECT_EQ(body.name(), made.name);
    EXPECT_EQ(t.materials[i].staticFriction, made.friction) << made.name;
    EXPECT_EQ(t.solids[i].sdf, nullptr) << made.name;
    EXPECT_EQ(collision.bodyOfProxy(t.proxies[i]), i) << made.name;
    EXPECT_DOUBLE_EQ(t.radius[i], body.shape().boundingRadius()) << made.name;
    // A sleeping body has not moved since the broad phase boxed it.
    if (!body.awake()) {
      const Aabb bounds = bodyBounds(body);
      EXPECT_TRUE(t.boxes[i].contains(bounds.min) && t.boxes[i].contains(bounds.max)) << made.name;
    }
    if (stepped && body.awake()) {
      EXPECT_EQ(t.listed[i], 1) << made.name << ": awake and not in the awake list";
    }
  }
  // A kept contact's bodies that can move hold it in their lists.
  for (const Contact& c : world.contacts()) {
    const bool plane = c.kind == Contact::Kind::PlaneBody;
    if (world.bodies()[c.b].awake() || (!plane && world.bodies()[c.a].awake())) continue;
    EXPECT_FALSE(t.keptContacts[c.b].empty()) << world.bodies()[c.b].name();
    if (!plane) {
      EXPECT_FALSE(t.keptContacts[c.a].empty()) << world.bodies()[c.a].name();
    }
  }
}

struct Pile {
  World world;
  std::vector<BodyId> ids;
  std::map<std::uint32_t, Made> madeBySlot;
};

Pile pile(double timeStep) {
  Settings s;
  s.timeStep = timeStep;
  Pile p{World(s), {}, {}};
  p.world.addPlane(Plane{});
  for (int k = 0; k < kBodies; ++k) {
    const int column = k % 16, layer = k / 16;
    BodyDef def = shapeBodyDef(shapeOf(k + layer), 1.0, "body_" + std::to_string(k));
    def.position = Vec3((column % 4) * kPitch, 0.3 + kLayer * layer, (column / 4) * kPitch);
    def.material.staticFriction = 0.2 + kFrictionStep * k;
    def.material.kineticFriction = def.material.staticFriction;
    const BodyId id = p.world.addBody(def);
    p.ids.push_back(id);
    p.madeBySlot[id.slot] = {def.material.staticFriction, def.name};
  }
  const int steps = static_cast<int>(kSettleTime / timeStep);
  for (int i = 0; i < steps; ++i) p.world.step();
  return p;
}

class BodyTableRows : public ::testing::TestWithParam<double> {};

TEST_P(BodyTableRows, EveryColumnFollowsItsBodyThroughBatchesOfRemovalsAndAdds) {
  Pile p = pile(GetParam());
  expectRowsMatch(p.world, p.madeBySlot);
  const std::size_t sleeping = std::count_if(p.world.bodies().begin(), p.world.bodies().end(),
                                             [](const RigidBody& b) { return !b.awake(); });
  EXPECT_GT(sleeping, 0u) << "no island fell asleep: the sleeping columns go untested";
  UniformRandom random(58);
  std::vector<BodyId> living = p.ids;
  for (int batch = 0; batch < kBatches; ++batch) {
    std::vector<BodyId> gone;
    for (int r = 0; r < kRemovedPerBatch; ++r) {
      const auto at = static_cast<std::size_t>(random.next() * static_cast<double>(living.size()));
      gone.push_back(living[at]);
      living.erase(living.begin() + static_cast<std::ptrdiff_t>(at));
    }
    p.world.destroyBodies(gone);
    expectRowsMatch(p.world, p.madeBySlot);
    // A new body takes a freed slot: its rows are its own, not the removed body's.
    BodyDef def = shapeBodyDef(shapeOf(batch), 1.0, "added_" + std::to_string(batch));
    def.position = Vec3(0.9, 3.0 + batch, 0.9);
    def.material.staticFriction = 0.9;
    def.material.kineticFriction = 0.9;
    const BodyId added = p.world.addBody(def);
    living.push_back(added);
    p.madeBySlot[added.slot] = {0.9, def.name};
    expectRowsMatch(p.world, p.madeBySlot, false);
    for (int i = 0; i < kStepsBetween; ++i) p.world.step();
    expectRowsMatch(p.world, p.madeBySlot);
  }
}

// The copy's pipeline works on the copy's table: removing from the copy leaves the original
// stepping exactly as a twin that was never copied, and a moved World steps as it would have.
TEST_P(BodyTableRows, ACopyAndAMoveEachWorkOnTheirOwnTable) {
  Pile p = pile(GetParam());
  Pile twin = pile(GetParam());
  World copy(p.world);
  copy.destroyBodies({p.ids[0], p.ids[17], p.ids[40]});
  for (int i = 0; i < kStepsBetween; ++i) {
    copy.step();
    p.world.step();
    twin.world.step();
  }
  EXPECT_EQ(p.world.stateHash(), twin.world.stateHash());
  expectRowsMatch(copy, p.madeBySlot);
  World moved(std::move(p.world));
  for (int i = 0; i < kStepsBetween; ++i) {
    moved.step();
    twin.world.step();
  }
  EXPECT_EQ(moved.stateHash(), twin.world.stateHash());
  expectRowsMatch(moved, twin.madeBySlot);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, BodyTableRows, ::testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const auto& info) { return info.param > 0.01 ? "dt60" : "dt240"; });

}  // namespace
}  // namespace rbsim

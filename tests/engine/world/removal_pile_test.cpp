// Removal on a random pile with contacts (issue 58, "removal costs what it touches";
// world/bodies.cpp World::destroyBodies, body/body_removal.h): whatever the removal path visits,
// what it leaves is checked against what the bodies' ids say it must be, worked out here by brute
// force from the contacts and joints before the removal, and against destroyBody one at a time,
// byte for byte through a World snapshot (contacts, warm starts, touching pairs, joints).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_snapshot.h"
#include "../../sanitized_build.h"

namespace rbsim {
namespace {

constexpr int kPileSide = 5;            // columns a side: 0.5 m boxes, each column 1 to 4 high
constexpr int kPileMaxHeight = 4;
constexpr double kPilePitch = 0.505;    // [m] between columns: 5 mm gaps, within the contact margin
constexpr double kPileJitter = 0.001;   // [m] random horizontal shift of each box
constexpr double kPileYaw = 0.004;      // [rad] largest random turn about the vertical (with the jitter, gaps stay open)
constexpr int kPileJoints = 6;             // each between a box and the one on it
constexpr double kPileSettleTime = 1.0;    // [s] before the removal: settled into one touching pile
constexpr double kPileRemovedShare = 0.3;  // of the boxes, drawn at random
constexpr int kPileStepsAfter = 30;        // stepped after, batch and one by one side by side

struct Pile {
  World world;
  std::vector<BodyId> ids;
};

Pile randomPile(double timeStep, std::uint64_t seed) {
  Settings s;
  s.timeStep = timeStep;
  Pile pile{World(s), {}};
  pile.world.addPlane(Plane{});
  UniformRandom random(seed);
  std::vector<int> columnOf;  // per box
  for (int i = 0; i < kPileSide * kPileSide; ++i) {
    const int height = 1 + static_cast<int>(random.next() * kPileMaxHeight);
    for (int k = 0; k < height; ++k) {
      BodyDef def = shapeBodyDef(Shape::box(Vec3::Constant(0.25)), 1.0, "box_" + std::to_string(pile.ids.size()));
      def.position = Vec3((i % kPileSide) * kPilePitch + random.between(-kPileJitter, kPileJitter), 0.25 + 0.5 * k,
                          (i / kPileSide) * kPilePitch + random.between(-kPileJitter, kPileJitter));
      def.orientation = Quat(Eigen::AngleAxisd(random.between(-kPileYaw, kPileYaw), Vec3::UnitY()));
      pile.ids.push_back(pile.world.addBody(def));
      columnOf.push_back(i);
    }
  }
  // Each joint holds a box to the one dropped above it, pinned midway, where they start.
  for (int made = 0; made < kPileJoints;) {
    const auto below = static_cast<std::size_t>(random.next() * static_cast<double>(pile.ids.size() - 1));
    if (columnOf[below + 1] != columnOf[below]) continue;  // the top of its column
    JointDef joint;
    joint.bodyA = pile.ids[below + 1];
    joint.bodyB = pile.ids[below];
    joint.anchor = 0.5 * (pile.world.body(joint.bodyA).position() + pile.world.body(joint.bodyB).position());
    pile.world.addJoint(joint);
    ++made;
  }
  const int steps = static_cast<int>(kPileSettleTime / timeStep);
  for (int i = 0; i < steps; ++i) pile.world.step();
  return pile;
}

// A contact named by its bodies' ids (a plane's by its index), as the brute force expects it.
struct NamedContact {
  Contact::Kind kind;
  std::int64_t plane;  // -1 for a pair of bodies
  BodyId a, b;
  std::uint16_t part, childA, childB;
  Vec3 normal;
};

// The contacts that must remain once `gone` are destroyed, in their order: those naming no
// removed body, each as it was, its bodies in the same order. A pair is ordered by its bodies'
// stable keys (their ids' slots, CollisionPipeline::bodiesOf), which a removal leaves as they
// were, even where the moves put the second body at the lower index.
std::vector<NamedContact> expectedContacts(const std::vector<NamedContact>& before, const std::vector<BodyId>& gone) {
  std::vector<NamedContact> out;
  for (const NamedContact& c : before) {
    const bool removed = std::find(gone.begin(), gone.end(), c.b) != gone.end() ||
                         (c.plane < 0 && std::find(gone.begin(), gone.end(), c.a) != gone.end());
    if (!removed) out.push_back(c);
  }
  return out;
}

std::vector<NamedContact> namedContacts(const World& world) {
  std::vector<NamedContact> out;
  for (const Contact& c : world.contacts()) {
    const bool plane = c.kind == Contact::Kind::PlaneBody;
    out.push_back({c.kind, plane ? static_cast<std::int64_t>(c.a) : -1, plane ? BodyId{} : world.idAt(c.a),
                   world.idAt(c.b), c.part, c.childA, c.childB, c.manifold.normal});
  }
  return out;
}

struct NamedJoint {
  BodyId a, b;  // b: kWorldAnchor for the world
};

std::vector<NamedJoint> namedJoints(const World& world) {
  std::vector<NamedJoint> out;
  for (const Joint& j : world.joints()) out.push_back({j.def.bodyA, j.def.bodyB});
  return out;
}

class RemovalPile : public testing::TestWithParam<double> {};

TEST_P(RemovalPile, LeavesWhatTheIdsSayAndWhatOneByOneLeft) {
  // One pile at 60 Hz under the sanitizers (38 s at 240 Hz there, for the same code as at 60 Hz,
  // the most of any engine test; tests/sanitized_build.h): the Release suite checks both piles at
  // both steps.
  if (test::kSanitizedBuild && GetParam() < 1.0 / 60.0) GTEST_SKIP() << "the sanitized suite runs the 60 Hz pile alone";
  const std::vector<std::uint64_t> seeds = test::kSanitizedBuild ? std::vector<std::uint64_t>{11u}
                                                                 : std::vector<std::uint64_t>{11u, 12u};
  for (const std::uint64_t seed : seeds) {
    SCOPED_TRACE("dt " + std::to_string(GetParam()) + ", seed " + std::to_string(seed));
    const Pile pile = randomPile(GetParam(), seed);
    const std::vector<NamedContact> before = namedContacts(pile.world);
    const auto onBoxes = std::count_if(before.begin(), before.end(), [](const NamedContact& c) { return c.plane < 0; });
    ASSERT_GT(onBoxes, static_cast<std::ptrdiff_t>(pile.ids.size())) << "a pile: boxes on boxes, not only on the ground";
    for (const NamedContact& c : before) {
      // Each pair is listed lower key first (with no body destroyed yet, also lower index first).
      if (c.plane < 0) {
        ASSERT_LT(c.a.slot, c.b.slot);
        ASSERT_LT(pile.world.indexOf(c.a), pile.world.indexOf(c.b));
      }
    }
    const std::vector<NamedJoint> jointsBefore = namedJoints(pile.world);
    UniformRandom random(seed + 100);
    std::vector<BodyId> gone;
    for (const BodyId id : pile.ids) {
      if (random.next() < kPileRemovedShare) gone.push_back(id);
    }
    std::reverse(gone.begin(), gone.end());  // from the end first too: both moved and unmoved lasts
    ASSERT_GT(gone.size(), 5u);

    World oneByOne(pile.world), batched(pile.world);
    for (const BodyId id : gone) oneByOne.destroyBody(id);
    batched.destroyBodies(gone);

    // The contacts, by ids, against the brute force.
    const std::vector<NamedContact> expected = expectedContacts(before, gone);
    const std::vector<NamedContact> got = namedContacts(oneByOne);
    ASSERT_EQ(got.size(), expected.size());
    // The premise of keeping the order: the removal moved some surviving pair's second body
    // below its first's index (it would have turned, keyed by indices).
    const bool movedBelow = std::any_of(got.begin(), got.end(), [&](const NamedContact& c) {
      return c.plane < 0 && oneByOne.indexOf(c.a) > oneByOne.indexOf(c.b);
    });
    EXPECT_TRUE(movedBelow) << "no pair's order differs from its indices': the case is not exercised";
    for (std::size_t k = 0; k < got.size(); ++k) {
      const NamedContact &x = got[k], &y = expected[k];
      EXPECT_TRUE(x.kind == y.kind && x.plane == y.plane && x.a == y.a && x.b == y.b && x.part == y.part &&
                  x.childA == y.childA && x.childB == y.childB && x.normal == y.normal)
          << "contact " << k;
    }
    // The joints: those of a removed body go, the others keep their bodies, in order.
    std::vector<NamedJoint> jointsExpected;
    for (const NamedJoint& j : jointsBefore) {
      const auto named = [&](BodyId id) { return std::find(gone.begin(), gone.end(), id) != gone.end(); };
      if (!named(j.a) && !(j.b != kWorldAnchor && named(j.b))) jointsExpected.push_back(j);
    }
    const std::vector<NamedJoint> jointsGot = namedJoints(oneByOne);
    ASSERT_EQ(jointsGot.size(), jointsExpected.size());
    for (std::size_t k = 0; k < jointsGot.size(); ++k) {
      EXPECT_TRUE(jointsGot[k].a == jointsExpected[k].a && jointsGot[k].b == jointsExpected[k].b) << "joint " << k;
    }
    // Everything the next step reads, warm starts and touching pairs included: the batch leaves
    // byte for byte what one at a time left, and both step on alike.
    EXPECT_TRUE(saveWorldSnapshot(batched) == saveWorldSnapshot(oneByOne));
    for (int i = 0; i < kPileStepsAfter; ++i) {
      batched.step();
      oneByOne.step();
      ASSERT_EQ(batched.stateHash(), oneByOne.stateHash()) << "step " << i << " after the removal";
    }
    EXPECT_TRUE(saveWorldSnapshot(batched) == saveWorldSnapshot(oneByOne));
  }
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, RemovalPile, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return info.index == 0 ? "dt60" : "dt240"; });

}  // namespace
}  // namespace rbsim

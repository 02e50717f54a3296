// A World snapshot (world/world_snapshot.h, issue 57): a World read from one, with a base World
// built anew from the same scene (as another process would), steps bit for bit as the saved one
// goes on: equal state hashes at every step and equal contacts, on shipped scenes that exercise
// every saved part (sleeping stacks and their kept contacts, both solvers' warm starts, joints,
// compounds, grids, round shapes, fracture, kinematic motions, a spawner and a kill volume, the
// exact integrator's memo, the raw matrix of euler-matrix without drift correction). Saving the
// World read gives the same bytes. A truncated or corrupted snapshot is a std::invalid_argument,
// at every byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../sanitized_build.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/contact_events.h"
#include "rbsim/world/world_snapshot.h"

namespace rbsim::test::snapshot_cases {
namespace {

struct SnapshotCase {
  const char* label;
  const char* scene;
  std::vector<std::string> overrides;
  int before = 0;  // steps before the snapshot
  int after = 0;   // steps both Worlds then take
};

void PrintTo(const SnapshotCase& c, std::ostream* os) { *os << c.label; }

World sceneWorld(const SnapshotCase& c) {
  return buildWorld(loadScene(std::string(RBSIM_ASSET_DIR) + "/scenes/" + c.scene, c.overrides));
}

void stepN(World& world, int n) {
  for (int i = 0; i < n; ++i) world.step();
}

int scaled(int steps) { return kSanitizedBuild ? steps / 10 + 1 : steps; }

void expectSameContacts(const World& a, const World& b) {
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t i = 0; i < a.contacts().size(); ++i) {
    const Contact& x = a.contacts()[i];
    const Contact& y = b.contacts()[i];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.a, y.a);
    EXPECT_EQ(x.b, y.b);
    EXPECT_EQ(x.part, y.part);
    ASSERT_EQ(x.manifold.count, y.manifold.count);
    EXPECT_EQ(x.manifold.normal, y.manifold.normal);
    for (int k = 0; k < x.manifold.count; ++k) {
      EXPECT_EQ(x.manifold.points[k].position, y.manifold.points[k].position);
      EXPECT_EQ(std::memcmp(&x.manifold.points[k].depth, &y.manifold.points[k].depth, sizeof(double)), 0);
    }
  }
  ASSERT_EQ(a.contactPoints().size(), b.contactPoints().size());
  for (std::size_t i = 0; i < a.contactPoints().size(); ++i) {
    EXPECT_EQ(a.contactPoints()[i].normalImpulse, b.contactPoints()[i].normalImpulse);
  }
}

std::size_t firstDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  return static_cast<std::size_t>(std::mismatch(a.begin(), a.begin() + std::min(a.size(), b.size()), b.begin()).first - a.begin());
}

class WorldSnapshot : public ::testing::TestWithParam<SnapshotCase> {};

TEST_P(WorldSnapshot, AWorldReadFromItStepsBitForBitAsTheSavedOne) {
  const SnapshotCase& c = GetParam();
  // The World the snapshot is read into, built anew and never stepped: only its shapes are read.
  // Under the sanitizers the saved World is a copy of it, not a second build from the scene (an
  // implicit solid's meshing took 20 of that test's 40 s there); the Release suite builds twice,
  // as another process would.
  const World base = sceneWorld(c);
  World original = kSanitizedBuild ? World(base) : sceneWorld(c);
  stepN(original, scaled(c.before));
  const std::vector<std::uint8_t> bytes = saveWorldSnapshot(original);

  World read = loadWorldSnapshot(bytes, base);
  EXPECT_EQ(read.stateHash(), original.stateHash());
  EXPECT_EQ(read.stepCount(), original.stepCount());
  EXPECT_EQ(read.time(), original.time());
  ASSERT_EQ(read.bodies().size(), original.bodies().size());
  for (std::size_t i = 0; i < read.bodies().size(); ++i) {
    EXPECT_EQ(read.idAt(i), original.idAt(i));
    EXPECT_EQ(read.bodies()[i].name(), original.bodies()[i].name());
    EXPECT_EQ(read.bodies()[i].rotation(), original.bodies()[i].rotation());
  }
  expectSameContacts(read, original);
  const std::vector<std::uint8_t> again = saveWorldSnapshot(read);
  EXPECT_TRUE(again == bytes) << "snapshot(read(snapshot(w))) differs from snapshot(w) from byte " << firstDifference(again, bytes);

  for (int i = 0; i < scaled(c.after); ++i) {
    original.step();
    read.step();
    ASSERT_EQ(read.stateHash(), original.stateHash()) << "step " << i << " after the snapshot";
    ASSERT_EQ(read.contacts().size(), original.contacts().size()) << "step " << i;
    // The touching pairs are in the snapshot: the read World begins, ends and hits as the saved one.
    const ContactEvents& er = contactEvents(read);
    const ContactEvents& eo = contactEvents(original);
    ASSERT_EQ(er.begin.size(), eo.begin.size()) << "step " << i;
    ASSERT_EQ(er.end.size(), eo.end.size()) << "step " << i;
    ASSERT_EQ(er.hit.size(), eo.hit.size()) << "step " << i;
    for (std::size_t k = 0; k < er.begin.size(); ++k) {
      EXPECT_EQ(er.begin[k].pair.bodyB, eo.begin[k].pair.bodyB) << "step " << i;
      EXPECT_EQ(er.begin[k].point, eo.begin[k].point) << "step " << i;
    }
  }
  expectSameContacts(read, original);
  const std::vector<std::uint8_t> a = saveWorldSnapshot(read), b = saveWorldSnapshot(original);
  EXPECT_TRUE(a == b) << "the snapshots after stepping differ from byte " << firstDifference(a, b);
}

INSTANTIATE_TEST_SUITE_P(
    ShippedScenes, WorldSnapshot,
    ::testing::Values(
        SnapshotCase{"SleepingStacks", "contact_stacking.json", {}, 400, 500},
        SnapshotCase{"SleepingStacksAt60Hz", "contact_stacking.json", {"world.dt=0.016666666666666666"}, 100, 500},
        SnapshotCase{"PgsStacks", "contact_stacking.json", {"world.solver=\"pgs\""}, 200, 300},
        SnapshotCase{"Joints", "assignment2_f_joints.json", {}, 90, 500},
        SnapshotCase{"ExactIntegrator", "assignment2_b_velocity.json", {"world.integrator=\"exact\""}, 90, 300},
        SnapshotCase{"RawEulerMatrix", "assignment2_b_velocity.json",
                     {"world.integrator=\"euler-matrix\"", "world.drift_correction=false"}, 90, 300},
        SnapshotCase{"Fracture", "fracture_wall.json", {}, 60, 200},
        SnapshotCase{"Grids", "sdf_pour.json", {"particles=[]"}, 90, 120},
        SnapshotCase{"ImplicitSolid", "csg_cup.json", {"particles=[]"}, 90, 120},
        SnapshotCase{"MeshGround", "mesh_ground.json", {}, 90, 120},
        SnapshotCase{"RoundShapes", "round_shapes.json", {}, 90, 300},
        SnapshotCase{"RoundedBoxes", "rounded_boxes.json", {}, 90, 300},
        SnapshotCase{"CompoundsAndMotions", "machinery_table.json", {}, 90, 300},
        SnapshotCase{"SpawnerAndKillVolume", "machinery_table.json",
                     {R"(spawn=[{"name": "rock", "count": 2, "period": 0.5, "region": {"min": [-1, 3, -1], "max": [1, 4, 1]},
                                 "body": {"shape": {"type": "box", "extents": [0.2, 0.2, 0.2]}, "mass": 1}}])",
                      R"(kill_volume={"min": [-1, -1, -1], "max": [1, 5, 1]})"},
                     300, 500}),
    [](const ::testing::TestParamInfo<SnapshotCase>& info) { return std::string(info.param.label); });

// The cases above hold what they claim to exercise when the snapshot is taken.
TEST(WorldSnapshotCases, TheStacksSleepTheSpawnerHasSpawnedAndRemovedTheWallBroke) {
  World stacks = sceneWorld({"", "contact_stacking.json", {}, 0, 0});
  stepN(stacks, scaled(400));
  std::size_t asleep = 0;
  for (const RigidBody& b : stacks.bodies()) asleep += !b.isStatic() && !b.awake();
  if (!kSanitizedBuild) {
    EXPECT_GT(asleep, 0u);
  }

  World spawns = sceneWorld({"", "machinery_table.json",
                             {R"(spawn=[{"name": "rock", "count": 2, "period": 0.5, "region": {"min": [-1, 3, -1], "max": [1, 4, 1]},
                                         "body": {"shape": {"type": "box", "extents": [0.2, 0.2, 0.2]}, "mass": 1}}])",
                              R"(kill_volume={"min": [-1, -1, -1], "max": [1, 5, 1]})"},
                             0, 0});
  const std::size_t atStart = spawns.bodies().size();
  stepN(spawns, scaled(300));
  EXPECT_GT(spawners(spawns).front().spawned, 0u);
  EXPECT_NE(spawns.bodies().size(), atStart + spawners(spawns).front().spawned) << "the kill volume removed none";

  World wall = sceneWorld({"", "fracture_wall.json", {}, 0, 0});
  const std::size_t bricks = wall.bodies().size();
  stepN(wall, scaled(60));
  if (!kSanitizedBuild) {
    EXPECT_GT(wall.bodies().size(), bricks) << "nothing broke before the snapshot";
  }
}

// A small World: a box resting on a plane and a ball falling on it.
World smallWorld() {
  Settings settings;
  World world(settings);
  world.addPlane(Plane{});
  BodyDef box = shapeBodyDef(Shape::box(Vec3(0.5, 0.5, 0.5)), 1.0, "box");
  box.position = Vec3(0.0, 0.5, 0.0);
  world.addBody(box);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.25), 1.0, "ball");
  ball.position = Vec3(0.1, 1.5, 0.0);
  world.addBody(ball);
  return world;
}

TEST(WorldSnapshotInput, EveryTruncationIsAnInvalidArgumentNamingTheSnapshot) {
  World world = smallWorld();
  stepN(world, 30);
  ASSERT_FALSE(world.contacts().empty());
  const std::vector<std::uint8_t> bytes = saveWorldSnapshot(world);
  const World base = smallWorld();
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    try {
      loadWorldSnapshot(bytes.data(), size, base, "small.snap");
      ADD_FAILURE() << "a snapshot cut to " << size << " of " << bytes.size() << " bytes was read";
    } catch (const std::invalid_argument& e) {
      ASSERT_EQ(std::string(e.what()).rfind("small.snap: ", 0), 0u) << e.what();
    }
  }
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(loadWorldSnapshot(longer, base), std::invalid_argument);
}

// FNV-1a 64, the checksum the format documents, to forge snapshots with a valid checksum.
void reseal(std::vector<std::uint8_t>& bytes) {
  constexpr std::size_t kHeader = 20, kChecksum = 8;
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = kHeader; i + kChecksum < bytes.size(); ++i) {
    h ^= bytes[i];
    h *= 1099511628211ull;
  }
  for (int k = 0; k < 8; ++k) bytes[bytes.size() - kChecksum + k] = static_cast<std::uint8_t>(h >> (8 * k));
}

TEST(WorldSnapshotInput, AFlippedByteIsCaughtByTheChecksumAndAForgedOneNeverCrashes) {
  World world = smallWorld();
  stepN(world, 30);
  const std::vector<std::uint8_t> bytes = saveWorldSnapshot(world);
  const World base = smallWorld();
  std::size_t refused = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::vector<std::uint8_t> flipped = bytes;
    flipped[i] ^= 0xFF;
    EXPECT_THROW(loadWorldSnapshot(flipped, base), std::invalid_argument) << "byte " << i;
    // The same change with a valid checksum: a blob made to look whole. Doubles may take any
    // value, so it may be read; a count, an index or an id must be refused, not followed.
    if (i >= 20 && i + 8 < bytes.size()) {
      reseal(flipped);
      try {
        loadWorldSnapshot(flipped, base);
      } catch (const std::invalid_argument&) {
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 0u);
}

TEST(WorldSnapshotInput, AHugeCountIsRefusedBeforeAnyAllocation) {
  World world = smallWorld();
  std::vector<std::uint8_t> bytes = saveWorldSnapshot(world);
  // The body count precedes the first body's record: its fingerprint, mesh group, id (slot and
  // generation), its name's length, "box".
  const std::string name = "box";
  const auto found = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
  ASSERT_NE(found, bytes.end());
  const std::size_t at = static_cast<std::size_t>(found - bytes.begin()) - 5 * 8;
  ASSERT_EQ(bytes[at], 2u);
  for (int k = 0; k < 8; ++k) bytes[at + k] = 0xFF;
  reseal(bytes);
  try {
    loadWorldSnapshot(bytes, smallWorld());
    FAIL() << "read";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bytes are left"), std::string::npos) << e.what();
  }
}

TEST(WorldSnapshotInput, WhatCannotBeSavedOrMatchedIsRefusedByName) {
  World particles = sceneWorld({"", "particles_fountain.json", {}, 0, 0});
  try {
    saveWorldSnapshot(particles);
    FAIL() << "saved";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("step listeners"), std::string::npos) << e.what();
  }
  World world = smallWorld();
  const std::vector<std::uint8_t> bytes = saveWorldSnapshot(world);
  World other(Settings{});
  other.addBody(shapeBodyDef(Shape::sphere(0.25), 1.0, "ball"));
  try {
    loadWorldSnapshot(bytes, other);
    FAIL() << "read against a World without a box";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'box'"), std::string::npos) << e.what();
  }
  Settings lcp;
  lcp.solver = Settings::ContactSolverMethod::Lcp;
  EXPECT_THROW(saveWorldSnapshot(World(lcp)), std::invalid_argument);
}

TEST(WorldSnapshotInput, AJointWhoseIndicesDisagreeWithItsBodyIdsIsRefusedByName) {
  // A joint names its bodies by id; the file keeps their indices beside the ids (the format of
  // before), and a load refuses a joint whose indices name other bodies than its ids do.
  const auto jointed = [] {
    World world = smallWorld();
    BodyDef third = shapeBodyDef(Shape::sphere(0.25), 1.0, "third");
    third.position = Vec3(2.0, 2.0, 0.0);
    JointDef rope;
    rope.name = "rope";
    rope.bodyA = world.addBody(third);  // index 2
    rope.bodyB = world.idAt(1);         // the ball
    rope.anchor = Vec3(1.0, 2.0, 0.0);
    world.addJoint(rope);
    return world;
  };
  const World world = jointed();
  const std::vector<std::uint8_t> bytes = saveWorldSnapshot(world);
  EXPECT_NO_THROW(loadWorldSnapshot(bytes, jointed()));
  // After the name, the ids (slot, generation as u32 each) and then the indices (u64 each) read
  // as the same 16 bytes for ids of generation 0: the second such run is the indices.
  std::vector<std::uint8_t> pair(16, 0);
  pair[0] = 2;
  pair[8] = 1;
  const std::uint8_t name[] = {'r', 'o', 'p', 'e'};
  auto at = std::search(bytes.begin(), bytes.end(), std::begin(name), std::end(name));
  ASSERT_NE(at, bytes.end());
  at = std::search(at, bytes.end(), pair.begin(), pair.end());
  ASSERT_NE(at, bytes.end());
  at = std::search(at + 16, bytes.end(), pair.begin(), pair.end());
  ASSERT_NE(at, bytes.end());
  std::vector<std::uint8_t> forged = bytes;
  forged[static_cast<std::size_t>(at - bytes.begin())] = 0;  // index 0: the box, a body, but not A
  reseal(forged);
  try {
    loadWorldSnapshot(forged, jointed());
    ADD_FAILURE() << "a joint whose index names another body was read";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("joint 'rope'"), std::string::npos) << e.what();
  }
}

TEST(WorldSnapshotInput, AFailedReadLeavesTheBaseAsItWas) {
  World world = smallWorld();
  stepN(world, 10);
  std::vector<std::uint8_t> bytes = saveWorldSnapshot(world);
  World base = smallWorld();
  const std::uint64_t before = base.stateHash();
  bytes.resize(bytes.size() / 2);
  EXPECT_THROW(loadWorldSnapshot(bytes, base), std::invalid_argument);
  EXPECT_EQ(base.stateHash(), before);
  EXPECT_EQ(base.stepCount(), 0u);
}

}  // namespace
}  // namespace rbsim::test::snapshot_cases

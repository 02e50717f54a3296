// world/contact_recycling: a pair of polyhedra that has moved little since its manifold was
// computed keeps it (Settings::contactRecycleDistance; Box3D src/physics_world.c). The kept
// manifold must give the separations the bodies' motion gives, be renewed beyond the tolerance or
// a 10 degree turn, leave round shapes alone, and stand the column of soft contacts that buckles
// without it.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"
#include "world/contact_recycling.h"

namespace rbsim {
namespace {

using test::boxDef;

// Two unit cubes, B resting on A with a quarter offset in x: four points on the overlap's corners.
ContactManifold stackedManifold() {
  ContactManifold m;
  m.normal = Vec3::UnitY();
  m.add(Vec3(-0.25, 1.0, -0.5), 0.002);
  m.add(Vec3(0.5, 1.0, -0.5), 0.002);
  m.add(Vec3(0.5, 1.0, 0.5), 0.002);
  m.add(Vec3(-0.25, 1.0, 0.5), 0.002);
  return m;
}

TEST(ContactRecycling, AnUnmovedPairGetsItsManifoldBack) {
  const RecyclePose a{Vec3(0.0, 0.5, 0.0), Quat::Identity(), 0.87}, b{Vec3(0.75, 1.498, 0.0), Quat::Identity(), 0.87};
  const ContactManifold m = stackedManifold();
  const RecycleFrame f = recycleFrame(7, m, a, b);
  const std::optional<ContactManifold> again = recycledManifold(f, a, b, 0.05, 0.01);
  ASSERT_TRUE(again.has_value());
  ASSERT_EQ(again->count, m.count);
  EXPECT_EQ(again->normal, m.normal);
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR((again->points[i].position - m.points[i].position).norm(), 0.0, 1e-15);
    EXPECT_NEAR(again->points[i].depth, m.points[i].depth, 1e-15);
    EXPECT_NEAR(again->points[i].offset.norm(), 0.0, 1e-15);
  }
}

TEST(ContactRecycling, SeparationsFollowTheBodiesAndTheArmsAreKept) {
  const RecyclePose a{Vec3(0.0, 0.5, 0.0), Quat::Identity(), 0.87}, b{Vec3(0.75, 1.498, 0.0), Quat::Identity(), 0.87};
  const RecycleFrame f = recycleFrame(7, stackedManifold(), a, b);
  // B sinks 1 mm and slides 3 mm in z; A is untouched. Every point is 1 mm deeper, and B's copy
  // of each point has gone with B (its lever arm kept): the offset is B's motion.
  RecyclePose moved = b;
  moved.position += Vec3(0.0, -0.001, 0.003);
  const std::optional<ContactManifold> m = recycledManifold(f, a, moved, 0.05, 0.01);
  ASSERT_TRUE(m.has_value());
  for (int i = 0; i < m->count; ++i) {
    EXPECT_NEAR(m->points[i].depth, 0.003, 1e-12);
    EXPECT_NEAR((m->points[i].offset - Vec3(0.0, -0.001, 0.003)).norm(), 0.0, 1e-12);
  }
  // Turning B by 0.01 rad about z lifts its corners on one side and sinks them on the other:
  // each point's depth changes by the material point's drop along the normal.
  RecyclePose turned = b;
  turned.orientation = Quat(Eigen::AngleAxisd(0.01, Vec3::UnitZ()));
  const std::optional<ContactManifold> t = recycledManifold(f, a, turned, 0.05, 0.01);
  ASSERT_TRUE(t.has_value());
  const Mat3 R = turned.orientation.toRotationMatrix();
  for (int i = 0; i < t->count; ++i) {
    const Vec3 arm = stackedManifold().points[i].position - b.position;
    EXPECT_NEAR(t->points[i].depth, 0.002 - (R * arm - arm).y(), 1e-12);
  }
}

TEST(ContactRecycling, APairThatMovedTooFarOrTurnedTooMuchIsCollidedAfresh) {
  const RecyclePose a{Vec3(0.0, 0.5, 0.0), Quat::Identity(), 0.87}, b{Vec3(0.75, 1.498, 0.0), Quat::Identity(), 0.87};
  const RecycleFrame f = recycleFrame(7, stackedManifold(), a, b);
  RecyclePose slid = b;
  slid.position.x() += 0.051;
  EXPECT_FALSE(recycledManifold(f, a, slid, 0.05, 0.01).has_value()) << "5.1 cm against a 5 cm tolerance";
  slid.position.x() = b.position.x() + 0.049;
  EXPECT_TRUE(recycledManifold(f, a, slid, 0.05, 0.01).has_value());
  // A relative turn sweeps the farther body's points: 0.05 rad at 0.87 m is 4.4 cm, which with
  // 1 cm of slide is past 5 cm.
  RecyclePose both = b;
  both.position.x() += 0.01;
  both.orientation = Quat(Eigen::AngleAxisd(0.05, Vec3::UnitY()));
  EXPECT_FALSE(recycledManifold(f, a, both, 0.05, 0.01).has_value());
  // Both bodies turned together by 11 degrees: the relative pose is unchanged, but a world-fixed
  // normal would be 11 degrees off.
  const Quat q(Eigen::AngleAxisd(11.0 * M_PI / 180.0, Vec3::UnitZ()));
  RecyclePose a2 = a, b2 = b;
  a2.orientation = q;
  b2.orientation = q;
  b2.position = a.position + q.toRotationMatrix() * (b.position - a.position);
  EXPECT_FALSE(recycledManifold(f, a2, b2, 0.05, 0.01).has_value());
  // A pair that was not touching uses the smaller tolerance.
  ContactManifold apart = stackedManifold();
  for (int i = 0; i < apart.count; ++i) apart.points[i].depth = -0.004;
  const RecycleFrame g = recycleFrame(8, apart, a, b);
  slid.position.x() = b.position.x() + 0.02;
  EXPECT_FALSE(recycledManifold(g, a, slid, 0.05, 0.01).has_value());
  EXPECT_TRUE(recycledManifold(f, a, slid, 0.05, 0.01).has_value());
}

// A column of `count` unit cubes of 100 kg on a static slab, as Box3D's benchmark stacks them.
World column(int count, double recycle) {
  Settings s;
  s.gravity = Vec3(0.0, -10.0, 0.0);
  s.timeStep = 1.0 / 60.0;
  s.substeps = 4;
  s.contactHertz = 30.0;
  s.contactRecycleDistance = recycle;
  s.allowSleep = false;
  s.threads = 1;
  World world(s);
  BodyDef ground = boxDef(Vec3(40.0, 2.0, 40.0), 1.0, "ground");
  ground.position = Vec3(0.0, -1.0, 0.0);
  ground.isStatic = true;
  world.addBody(ground);
  for (int i = 0; i < count; ++i) {
    BodyDef box = boxDef(Vec3::Ones(), 100.0, "box" + std::to_string(i));
    box.position = Vec3(0.0, 0.5 + i, 0.0);
    box.material.staticFriction = box.material.kineticFriction = 0.6;
    world.addBody(box);
  }
  return world;
}

double topDrift(World& world, int steps) {
  const Vec3 start = world.bodies().back().position();
  for (int i = 0; i < steps; ++i) world.step();
  const Vec3 d = world.bodies().back().position() - start;
  return std::hypot(d.x(), d.z());
}

TEST(ContactRecycling, AColumnOfSoftContactsStandsWithItAndBucklesWithout) {
  // 20 cubes on 30 Hz contacts: each contact's tilt stiffness m_eff omega^2 (0.25 m^2 x 4 points,
  // is 4.4e5 N m/rad, under the 1.1e6 a chain of 20 such links needs against its own weight
  // (docs/speed.md): renewed every step, the manifolds follow the lean and the column buckles,
  // as Box3D's does with its recycling off. Kept, they hold it.
  World kept = column(20, kAutoRecycleDistance);  // 6 |g| h^2 = 1.04 mm
  EXPECT_LT(topDrift(kept, 600), 0.02);
  EXPECT_GT(recycledContacts(kept), 0u);
  World fresh = column(20, 0.0);
  EXPECT_GT(topDrift(fresh, 600), 1.0);
  EXPECT_EQ(recycledContacts(fresh), 0u);
}

TEST(ContactRecycling, RoundShapesAreNeverRecycledAndPolyhedraOnAPlaneAre) {
  Settings s;
  s.gravity = Vec3(0.0, -9.81, 0.0);
  s.threads = 1;
  World world(s);
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  BodyDef ball = shapeBodyDef(Shape::sphere(0.5), 1.0, "ball");
  ball.position = Vec3(0.0, 0.5, 0.0);
  ball.velocity = Vec3(2.0, 0.0, 0.0);
  world.addBody(ball);
  BodyDef box = boxDef(Vec3::Ones(), 1.0, "box");
  box.position = Vec3(5.0, 0.5, 0.0);
  world.addBody(box);
  for (int i = 0; i < 30; ++i) world.step();
  ASSERT_EQ(world.contacts().size(), 2u);
  EXPECT_EQ(recycledContacts(world), 1u) << "the resting box's, not the rolling ball's";
}

}  // namespace
}  // namespace rbsim

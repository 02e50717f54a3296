// Compound bodies (body/compound_body.h): mass properties against a mesh of the same solid,
// resting and rolling against the analytic cases, contacts per child, and the scene keys, at
// dt = 1/60 s and 1/240 s.
#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using test::allNear;

constexpr double kDensity = 700.0;  // [kg/m^3], oak

// An L lying in the xy plane, 0.4 m deep: a foot 1.0 x 0.2 m along x and an upright 0.2 x 0.8 m
// on its left end (corners (0,0) to (1,1)). As one extruded polygon and as two boxes.
Mesh lMesh() {
  return makeExtrudedPolygon({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0.2), Vec2(0.2, 0.2), Vec2(0.2, 1), Vec2(0, 1)}, 0.4);
}
std::vector<CompoundPart> lParts() {
  CompoundPart foot, upright;
  foot.shape = Shape::box(Vec3(0.5, 0.1, 0.2));
  foot.position = Vec3(0.5, 0.1, 0.0);
  upright.shape = Shape::box(Vec3(0.1, 0.4, 0.2));
  upright.position = Vec3(0.1, 0.6, 0.0);
  foot.density = upright.density = kDensity;
  return {foot, upright};
}

TEST(CompoundBody, AnLOfTwoBoxesHasTheLMeshsMassProperties) {
  const MassProperties mesh = polyhedralMassProperties(lMesh(), kDensity);
  const BodyDef l = compoundBodyDef(lParts(), "L");
  EXPECT_NEAR(l.mass, mesh.mass, 1e-9 * mesh.mass);
  EXPECT_TRUE(allNear(l.fileFrame.centre, mesh.centerOfMass, 1e-12));
  EXPECT_TRUE(allNear(l.inertiaBody, mesh.inertia, 1e-9 * mesh.inertia.norm()));
  // The children sit about the centre of mass: the foot's centre is (0.5, 0.1) - c.
  EXPECT_TRUE(allNear(l.children[0].position, Vec3(0.5, 0.1, 0.0) - mesh.centerOfMass, 1e-12));
  // A given total mass scales every density by one factor: the same centre, inertia in proportion.
  const BodyDef heavy = compoundBodyDef(lParts(), "L", 2.0 * mesh.mass);
  EXPECT_NEAR(heavy.mass, 2.0 * mesh.mass, 1e-9 * mesh.mass);
  EXPECT_TRUE(allNear(heavy.inertiaBody, 2.0 * mesh.inertia, 2e-9 * mesh.inertia.norm()));
}

// Parts turned and of different densities: a dumbbell of two spheres on a bar, turned so that the
// bar lies along z, against the sum of the parts' closed forms by hand.
TEST(CompoundBody, TurnedPartsSumByTheParallelAxisTheorem) {
  CompoundPart a, b, bar;
  a.shape = b.shape = Shape::sphere(0.2);
  a.position = Vec3(0, 0, -0.5);
  b.position = Vec3(0, 0, 0.5);
  b.density = 2.0 * a.density;
  bar.shape = Shape::box(Vec3(0.05, 0.4, 0.05));  // along y, turned onto z
  bar.orientation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()));
  const BodyDef def = compoundBodyDef({a, b, bar}, "dumbbell");
  const double ma = a.density * 4.0 / 3.0 * kPi * 0.008, mb = 2.0 * ma, mbar = bar.density * 0.1 * 0.8 * 0.1;
  const double m = ma + mb + mbar;
  EXPECT_NEAR(def.mass, m, 1e-9 * m);
  const double zc = (mb - ma) * 0.5 / m;
  EXPECT_TRUE(allNear(def.fileFrame.centre, Vec3(0, 0, zc), 1e-12));
  const double sphere = 0.4 * 0.04;  // 2/5 r^2
  const double Ixx = ma * (sphere + std::pow(-0.5 - zc, 2)) + mb * (sphere + std::pow(0.5 - zc, 2)) +
                     mbar * ((0.01 + 0.64) / 12.0 + zc * zc);
  const double Izz = (ma + mb) * sphere + mbar * (0.01 + 0.01) / 12.0;
  EXPECT_NEAR(def.inertiaBody(0, 0), Ixx, 1e-9 * Ixx);
  EXPECT_NEAR(def.inertiaBody(1, 1), Ixx, 1e-9 * Ixx);
  EXPECT_NEAR(def.inertiaBody(2, 2), Izz, 1e-9 * Izz);
  EXPECT_NEAR(def.inertiaBody(0, 1), 0.0, 1e-12);
}

TEST(CompoundBody, RefusesWhatItCannotBe) {
  EXPECT_THROW(compoundBodyDef({}, "none"), std::invalid_argument);
  std::vector<CompoundPart> parts = lParts();
  parts[1].density = 0.0;
  EXPECT_THROW(compoundBodyDef(parts, "L"), std::invalid_argument);
  parts = lParts();
  parts[0].shape = Shape::convexHull(makeBox(Vec3::Ones()));  // a hull without its mesh
  EXPECT_THROW(compoundBodyDef(parts, "L"), std::invalid_argument);
  EXPECT_THROW(compoundBodyDef(lParts(), "L", -1.0), std::invalid_argument);
  EXPECT_THROW(compoundBodyDef(std::vector<CompoundPart>(kMaxCompoundChildren + 1, lParts()[0]), "many"),
               std::invalid_argument);
}

class CompoundWorld : public testing::TestWithParam<double> {
 protected:
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam();
    return s;
  }
  int steps(double seconds) const { return static_cast<int>(std::lround(seconds / GetParam())); }
};

// The L compound and a body of the L mesh (its polyhedral mass properties, its vertices against
// the plane) dropped from the same tilted pose come to rest the same way: on the foot's bottom
// face, the centre of mass at its height above the foot.
TEST_P(CompoundWorld, AnLOfTwoBoxesRestsAsTheLMesh) {
  const Mesh mesh = lMesh();
  const MassProperties props = polyhedralMassProperties(mesh, kDensity);
  BodyDef meshDef;
  meshDef.name = "mesh L";
  Mesh centred = mesh;
  for (Vec3& p : centred.vertices) p -= props.centerOfMass;
  meshDef.mesh = std::make_shared<const Mesh>(centred);
  meshDef.mass = props.mass;
  meshDef.inertiaBody = props.inertia;
  BodyDef compound = compoundBodyDef(lParts(), "compound L");
  const Quat tilt(Eigen::AngleAxisd(0.15, Vec3::UnitZ()));
  std::array<Vec3, 2> x;  // where each came to rest
  std::array<Quat, 2> q;
  int k = 0;
  for (BodyDef def : {meshDef, compound}) {
    World w(settings());
    w.addPlane(Plane{});
    def.position = Vec3(0.0, 0.6, 0.0);
    def.orientation = tilt;
    const BodyId id = w.addBody(def);
    for (int i = 0; i < steps(3.0); ++i) w.step();
    x[k] = w.body(id).position();
    q[k] = w.body(id).orientation();
    ++k;
  }
  EXPECT_NEAR(x[1].y(), props.centerOfMass.y(), 1e-3) << "at rest on the foot's bottom face";
  EXPECT_NEAR(x[0].y(), x[1].y(), 1e-3);
  EXPECT_NEAR(x[0].x(), x[1].x(), 5e-3);
  // Lying flat: the body's y axis up (a turn about the vertical, from the landing's friction, is
  // free and differs between the two by under a degree).
  for (const Quat& turned : q) EXPECT_GT((turned * Vec3::UnitY()).y(), std::cos(1e-3)) << "lying flat";
  EXPECT_LT(q[0].angularDistance(q[1]), 0.02);
}

// A dumbbell (two balls on a bar that does not touch the ground) on a 15 degree incline rolls
// without slipping: its centre accelerates at g sin(theta) / (1 + I_axle / (m r^2)), where I_axle
// is the compound's moment about its axle, so 0.5 a t^2 down the slope after t.
TEST_P(CompoundWorld, ADumbbellRollsDownAnInclineAsTheAnalyticCase) {
  const double theta = 15.0 * kPi / 180.0, r = 0.2, g = 9.81;
  World w(settings());
  const Vec3 n(-std::sin(theta), std::cos(theta), 0.0);  // the slope falls towards +x
  w.addPlane(Plane{n, 0.0});
  CompoundPart a, b, bar;
  a.shape = b.shape = Shape::sphere(r);
  a.position = Vec3(0, 0, -0.4);
  b.position = Vec3(0, 0, 0.4);
  bar.shape = Shape::capsule(0.05, 0.6);  // along y, turned onto the axle, z
  bar.orientation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()));
  BodyDef def = compoundBodyDef({a, b, bar}, "dumbbell");
  const Vec3 start = r * n;  // resting on the slope at the origin
  def.position = start;
  const BodyId id = w.addBody(def);
  const double t = 1.0;
  for (int i = 0; i < steps(t); ++i) w.step();
  const double axle = def.inertiaBody(2, 2);
  const double accel = g * std::sin(theta) / (1.0 + axle / (def.mass * r * r));
  const Vec3 down(-std::cos(theta), -std::sin(theta), 0.0);  // along the slope, downhill
  const Vec3 travelled = w.body(id).position() - start;
  EXPECT_NEAR(travelled.dot(down), 0.5 * accel * t * t, 0.01 * 0.5 * accel * t * t);
  EXPECT_NEAR(travelled.dot(n), 0.0, 1e-3) << "on the slope";
  // Rolling without slipping: omega r = v.
  const double v = w.body(id).velocity().norm();
  EXPECT_NEAR(w.body(id).angularVelocity().norm() * r, v, 0.01 * v);
  EXPECT_NEAR(v, accel * t, 0.01 * accel * t);
}

// A table of five boxes (a top on four legs) stands on its four legs, one manifold per leg with
// the ground's normal, and a ball dropped on it rests on the top.
TEST_P(CompoundWorld, ATableStandsOnItsLegsAndHoldsABall) {
  World w(settings());
  w.addPlane(Plane{});
  std::vector<CompoundPart> parts(5);
  parts[0].shape = Shape::box(Vec3(0.6, 0.03, 0.4));
  parts[0].position = Vec3(0, 0.73, 0);
  int leg = 1;
  for (const double x : {-0.55, 0.55}) {
    for (const double z : {-0.35, 0.35}) {
      parts[leg].shape = Shape::box(Vec3(0.03, 0.35, 0.03));
      parts[leg].position = Vec3(x, 0.35, z);
      ++leg;
    }
  }
  BodyDef table = compoundBodyDef(parts, "table");
  const double rise = 0.02;
  table.position = table.fileFrame.centre + Vec3(0, rise, 0);
  const BodyId id = w.addBody(table);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.1), 0.5, "ball");
  ball.position = Vec3(0.2, 1.2, 0.1);
  const BodyId ballId = w.addBody(ball);
  for (int i = 0; i < steps(2.0); ++i) w.step();
  EXPECT_NEAR(w.body(id).position().y(), table.fileFrame.centre.y(), 1e-3);
  EXPECT_LT(w.body(id).orientation().angularDistance(Quat::Identity()), 1e-3);
  EXPECT_NEAR(w.body(ballId).position().y(), 0.76 + 0.1, 1e-3) << "on the top, 0.76 m up";
  int legs = 0;
  for (const Contact& c : w.contacts()) {
    if (c.kind != Contact::Kind::PlaneBody) continue;
    ++legs;
    EXPECT_GE(c.childB, 1);
    EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitY(), 1e-12));
    for (int p = 0; p < c.manifold.count; ++p) {
      const Vec3 foot = w.bodies()[c.b].bodyToWorld(table.children[c.childB].position) - Vec3(0, 0.35, 0);
      EXPECT_LE((c.manifold.points[p].position - foot).cwiseAbs().maxCoeff(), 0.03 + 1e-3) << "under its leg";
    }
  }
  EXPECT_EQ(legs, 4);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, CompoundWorld, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return info.param > 0.01 ? "dt60" : "dt240"; });

}  // namespace
}  // namespace rbsim

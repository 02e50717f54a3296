// mass/mass_properties: the polyhedral integrals against closed forms, and the seed's cube proxy.
#include "rbsim/mass/mass_properties.h"

#include <random>

#include <gtest/gtest.h>

#include "io/obj_loader.h"
#include "rbsim/math/rotation.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::dataPath;

Mesh unitTetrahedron() { return loadObj(dataPath("tetrahedron.obj")); }

// Inertia of the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), density 1, about its centroid.
// About the origin: V = 1/6, int x^2 dV = 1/60, int xy dV = 1/120 (and by symmetry for y, z).
// Parallel axis to the centroid c = (1/4, 1/4, 1/4):
//   int x'^2  = 1/60  - V c_x^2   = 1/60  - 1/96 = 1/160
//   int x'y'  = 1/120 - V c_x c_y = 1/120 - 1/96 = -1/480
// so I_xx = int (y'^2 + z'^2) = 2/160 = 1/80 and I_xy = -int x'y' = +1/480.
Mat3 tetrahedronInertiaAboutCentroid() {
  Mat3 I;
  I << 1.0 / 80, 1.0 / 480, 1.0 / 480,
       1.0 / 480, 1.0 / 80, 1.0 / 480,
       1.0 / 480, 1.0 / 480, 1.0 / 80;
  return I;
}

TEST(CuboidInertia, MatchesTheClosedForm) {
  const Mat3 I = cuboidInertia(12.0, Vec3(1.0, 2.0, 3.0));  // m/12 = 1
  EXPECT_TRUE(allNear(I, Vec3(4.0 + 9.0, 1.0 + 9.0, 1.0 + 4.0).asDiagonal().toDenseMatrix(), 1e-15));
}

TEST(PolyhedralMassProperties, UnitCube) {
  const MassProperties p = polyhedralMassProperties(makeBox(Vec3::Ones()), 1.0);
  EXPECT_NEAR(p.volume, 1.0, 1e-15);
  EXPECT_NEAR(p.mass, 1.0, 1e-15);
  EXPECT_TRUE(allNear(p.centerOfMass, Vec3::Zero(), 1e-15));
  EXPECT_TRUE(allNear(p.inertia, Mat3::Identity() / 6.0, 1e-15)) << "I = m (1 + 1) / 12 = 1/6";
}

TEST(PolyhedralMassProperties, BoxOneByTwoByThreeOfDensitySeven) {
  const Vec3 e(1.0, 2.0, 3.0);
  const MassProperties p = polyhedralMassProperties(makeBox(e), 7.0);
  const double m = 7.0 * 6.0;
  EXPECT_NEAR(p.volume, 6.0, 1e-14);
  EXPECT_NEAR(p.mass, m, 1e-13);
  EXPECT_TRUE(allNear(p.centerOfMass, Vec3::Zero(), 1e-15));
  // I = m/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) = 3.5 diag(13, 10, 5)
  Mat3 expected = Mat3::Zero();
  expected.diagonal() << m / 12 * (4 + 9), m / 12 * (1 + 9), m / 12 * (1 + 4);
  EXPECT_TRUE(allNear(p.inertia, expected, 1e-13));
  EXPECT_TRUE(allNear(p.inertia, cuboidInertia(m, e), 1e-13));
}

TEST(PolyhedralMassProperties, TetrahedronAgainstTheDerivedTensor) {
  const MassProperties p = polyhedralMassProperties(unitTetrahedron(), 1.0);
  EXPECT_NEAR(p.volume, 1.0 / 6.0, 1e-16);
  EXPECT_NEAR(p.mass, 1.0 / 6.0, 1e-16);
  EXPECT_TRUE(allNear(p.centerOfMass, Vec3::Constant(0.25), 1e-16));
  EXPECT_TRUE(allNear(p.inertia, tetrahedronInertiaAboutCentroid(), 1e-16));
  // Back to the origin by the parallel-axis theorem: int x^2 = 1/60 and int xy = 1/120.
  const Vec3 c = p.centerOfMass;
  const Mat3 aboutOrigin = p.inertia + p.mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  EXPECT_NEAR(aboutOrigin(0, 0), 2.0 / 60.0, 1e-16) << "int (y^2 + z^2)";
  EXPECT_NEAR(aboutOrigin(0, 1), -1.0 / 120.0, 1e-16) << "-int xy";
}

TEST(PolyhedralMassProperties, TetrahedronFarFromTheOrigin) {
  const Vec3 offset(1e3, -2e3, 3e3);
  Mesh far = unitTetrahedron();
  for (Vec3& v : far.vertices) v += offset;
  const MassProperties p = polyhedralMassProperties(far, 1.0);
  const Mat3 I0 = tetrahedronInertiaAboutCentroid();
  EXPECT_NEAR(p.volume, 1.0 / 6.0, 1e-9 / 6.0);
  EXPECT_TRUE(allNear(p.centerOfMass, offset + Vec3::Constant(0.25), 1e-12 * offset.norm()));
  EXPECT_LE((p.inertia - I0).norm(), 1e-9 * I0.norm()) << "inertia about the centroid is translation invariant";
}

TEST(PolyhedralMassProperties, RotatedBoxGivesRIRt) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const Vec3 e(1.0, 2.0, 3.0);
  const Mat3 I = cuboidInertia(6.0, e);  // density 1
  for (int trial = 0; trial < 5; ++trial) {
    const Mat3 R = rotationFromAxisAngle(Vec3(u(rng), u(rng), u(rng)));
    Mesh rotated = makeBox(e);
    for (Vec3& v : rotated.vertices) v = R * v;
    const MassProperties p = polyhedralMassProperties(rotated, 1.0);
    EXPECT_NEAR(p.mass, 6.0, 1e-13);
    EXPECT_TRUE(allNear(p.centerOfMass, Vec3::Zero(), 1e-14));
    EXPECT_TRUE(allNear(p.inertia, R * I * R.transpose(), 1e-13)) << "trial " << trial;
  }
}

TEST(PolyhedralMassProperties, InwardWindingGivesNegativeVolume) {
  const MassProperties p = polyhedralMassProperties(loadObj(dataPath("inverted_cube.obj")), 2.0);
  EXPECT_NEAR(p.volume, -1.0, 1e-15);
  EXPECT_NEAR(p.mass, -2.0, 1e-15);
}

TEST(CubeApproximation, IsTheCuboidOfTheBoundingBox) {
  Mesh mesh = unitTetrahedron();
  for (Vec3& v : mesh.vertices) v = Vec3(2.0 * v.x() + 1.0, 0.5 * v.y() - 3.0, 3.0 * v.z());
  const MassProperties p = cubeApproximation(mesh, 5.0);
  EXPECT_EQ(p.mass, 5.0);
  EXPECT_TRUE(allNear(p.centerOfMass, Vec3(2.0, -2.75, 1.5), 1e-15)) << "the bounding-box centre";
  EXPECT_TRUE(allNear(p.inertia, cuboidInertia(5.0, Vec3(2.0, 0.5, 3.0)), 1e-15));
  EXPECT_NEAR(p.volume, 3.0, 1e-15) << "the box's volume, not the tetrahedron's";
}

TEST(InertiaMethodNames, RoundTrip) {
  for (InertiaMethod m : {InertiaMethod::Cube, InertiaMethod::Exact}) {
    InertiaMethod parsed = m == InertiaMethod::Cube ? InertiaMethod::Exact : InertiaMethod::Cube;
    ASSERT_TRUE(parseInertiaMethod(inertiaMethodName(m), parsed));
    EXPECT_EQ(parsed, m);
  }
  InertiaMethod out = InertiaMethod::Exact;
  EXPECT_FALSE(parseInertiaMethod("bounding-box", out));
}

}  // namespace
}  // namespace rbsim

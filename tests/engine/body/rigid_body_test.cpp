// body/rigid_body: manual x and R (seed 004 "TO DO: change x and R and redraw"), the derived
// quantities, and the force/torque accumulators (seed 004 "Force and torque").
#include "rbsim/body/rigid_body.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxDef;

// Coordinates below are O(5), so 1e-14 is a few ulps of each world coordinate.
constexpr double kVertexTol = 1e-14;

void expectWorldVerticesAre(const RigidBody& body, const Mat3& R, const Vec3& x) {
  ASSERT_EQ(body.vertexCount(), body.mesh().vertices.size());
  for (std::size_t i = 0; i < body.vertexCount(); ++i) {
    EXPECT_TRUE(allNear(body.worldVertex(i), R * body.bodyVertex(i) + x, kVertexTol)) << "vertex " << i;
    EXPECT_TRUE(allNear(body.worldVertices()[i], body.worldVertex(i), 0.0));
  }
}

TEST(RigidBody, WorldVerticesFollowSetPositionAndMatrixOrientation) {
  RigidBody body(boxDef(Vec3(1.0, 2.0, 3.0), 2.0));
  expectWorldVerticesAre(body, Mat3::Identity(), Vec3::Zero());
  const Vec3 x(1.5, -2.0, 3.25);
  const Mat3 R = rotationFromAxisAngle(Vec3(0.3, -1.2, 0.8));
  body.setPosition(x);
  expectWorldVerticesAre(body, Mat3::Identity(), x);
  body.setOrientation(R);
  expectWorldVerticesAre(body, R, x);
  EXPECT_TRUE(allNear(body.rotation(), R, 1e-15));
  EXPECT_TRUE(allNear(body.position(), x, 0.0));
}

TEST(RigidBody, WorldVerticesFollowQuaternionOrientation) {
  RigidBody body(boxDef(Vec3(1.0, 0.3, 0.1), 1.0));
  const Quat q = quatFromAxisAngle(Vec3(-2.0, 0.5, 1.0));
  const Vec3 x(-4.0, 0.5, 2.0);
  body.setOrientation(q);
  body.setPosition(x);
  const Mat3 R = q.toRotationMatrix();
  expectWorldVerticesAre(body, R, x);
  for (const Vec3& p : {Vec3(0.1, 0.2, 0.3), Vec3(-1.0, 4.0, 2.0)}) {
    EXPECT_TRUE(allNear(body.bodyToWorld(p), R * p + x, kVertexTol));
  }
}

// World vertices are a cache filled on access: every way the pose changes must show on the next
// access, in the same storage, and a copy of a body must keep a cache of its own.
TEST(RigidBody, WorldVerticesFollowEveryPoseChangeOnTheNextAccess) {
  RigidBody body(boxDef(Vec3(1.0, 2.0, 3.0), 2.0));
  const std::vector<Vec3>* storage = &body.worldVertices();
  const Vec3 x(0.5, -1.0, 2.0);
  body.setPosition(x);
  EXPECT_TRUE(allNear(body.worldVertex(0), body.bodyVertex(0) + x, kVertexTol)) << "setPosition";
  body.setOrientation(quatFromAxisAngle(Vec3(0.0, 0.0, 0.5)));
  expectWorldVerticesAre(body, rotationFromAxisAngle(Vec3(0.0, 0.0, 0.5)), x);

  BodyState next = body.state();  // the integrators' path
  next.position = Vec3(3.0, 1.0, -2.0);
  next.orientation = quatFromAxisAngle(Vec3(0.4, 0.1, -0.7));
  body.setState(next);
  expectWorldVerticesAre(body, next.orientation.toRotationMatrix(), next.position);
  EXPECT_EQ(storage, &body.worldVertices()) << "refilled in place";

  RigidBody copy = body;
  copy.setPosition(Vec3::Zero());
  expectWorldVerticesAre(copy, next.orientation.toRotationMatrix(), Vec3::Zero());
  expectWorldVerticesAre(body, next.orientation.toRotationMatrix(), next.position);
}

TEST(RigidBody, RotationColumnsAreTheBodyAxes) {
  const Vec3 e(2.0, 0.5, 1.0);
  RigidBody body(boxDef(e, 1.0));
  const Mat3 R = rotationFromAxisAngle(Vec3(1.0, 1.0, -0.5));
  body.setOrientation(R);
  body.setPosition(Vec3(3.0, 1.0, -1.0));
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(allNear(body.rotation().col(i), R * Vec3::Unit(i), 1e-15)) << "axis " << i;
    EXPECT_TRUE(allNear(body.bodyToWorld(Vec3::Unit(i)) - body.position(), body.rotation().col(i), 1e-15));
  }
  // p1 - p0 runs along body x for the box's full x extent, p3 - p0 along y, p4 - p0 along z.
  EXPECT_TRUE(allNear(body.worldVertex(1) - body.worldVertex(0), e.x() * body.rotation().col(0), kVertexTol));
  EXPECT_TRUE(allNear(body.worldVertex(3) - body.worldVertex(0), e.y() * body.rotation().col(1), kVertexTol));
  EXPECT_TRUE(allNear(body.worldVertex(4) - body.worldVertex(0), e.z() * body.rotation().col(2), kVertexTol));
}

TEST(RigidBody, RejectsNonRotations) {
  RigidBody body(boxDef(Vec3::Ones(), 1.0));
  EXPECT_THROW(body.setOrientation(Mat3(2.0 * Mat3::Identity())), std::invalid_argument);
  EXPECT_THROW(body.setOrientation(Mat3(Vec3(1.0, 1.0, -1.0).asDiagonal())), std::invalid_argument)
      << "a reflection is orthonormal but not a rotation";
  EXPECT_THROW(body.setOrientation(Quat(1.0, 0.1, 0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(body.setOrientation(Quat(std::nan(""), 0.0, 0.0, 0.0)), std::invalid_argument);
  EXPECT_TRUE(allNear(body.rotation(), Mat3::Identity(), 0.0)) << "a rejected set changes nothing";
}

TEST(RigidBody, ConstructorValidatesTheDefinition) {
  BodyDef noMesh = boxDef(Vec3::Ones(), 1.0);
  noMesh.mesh.reset();
  EXPECT_THROW(RigidBody{noMesh}, std::invalid_argument);
  for (double m : {0.0, -1.0, std::nan("")}) {
    BodyDef def = boxDef(Vec3::Ones(), 1.0);
    def.mass = m;
    EXPECT_THROW(RigidBody{def}, std::invalid_argument) << "mass " << m;
  }
  BodyDef notPositive = boxDef(Vec3::Ones(), 1.0);
  notPositive.inertiaBody(2, 2) = -0.1;
  EXPECT_THROW(RigidBody{notPositive}, std::invalid_argument);
  BodyDef asymmetric = boxDef(Vec3::Ones(), 1.0);
  asymmetric.inertiaBody(0, 1) = 0.01;
  EXPECT_THROW(RigidBody{asymmetric}, std::invalid_argument);
}

TEST(RigidBody, MomentaAndDerivedQuantities) {
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 2.0);
  def.orientation = quatFromAxisAngle(Vec3(0.2, 0.9, -0.4));
  def.velocity = Vec3(1.0, -2.0, 0.5);
  def.angularVelocity = Vec3(0.3, 4.0, -1.0);
  const RigidBody body(def);
  const Mat3 R = def.orientation.toRotationMatrix();
  const Mat3 Iw = R * def.inertiaBody * R.transpose();
  EXPECT_TRUE(allNear(body.state().linearMomentum, 2.0 * def.velocity, 0.0)) << "P = m v";
  EXPECT_TRUE(allNear(body.state().angularMomentum, Iw * def.angularVelocity, 1e-15)) << "L = I(t) omega";
  EXPECT_TRUE(allNear(body.velocity(), def.velocity, 1e-15));
  EXPECT_TRUE(allNear(body.angularVelocity(), def.angularVelocity, 1e-13));
  EXPECT_TRUE(allNear(body.inertiaWorld(), Iw, 1e-15));
  EXPECT_TRUE(allNear(body.inverseInertiaWorld() * body.inertiaWorld(), Mat3::Identity(), 1e-14));
  EXPECT_TRUE(allNear(body.inverseInertiaBody() * body.inertiaBody(), Mat3::Identity(), 1e-14));
  const double ke = 0.5 * 2.0 * def.velocity.squaredNorm() +
                    0.5 * def.angularVelocity.dot(Iw * def.angularVelocity);
  EXPECT_NEAR(body.kineticEnergy(), ke, 1e-14 * ke);
}

TEST(RigidBody, ManualSetsOfVelocityAndOrientation) {
  RigidBody body(boxDef(Vec3(1.0, 0.3, 0.1), 3.0));
  body.setOrientation(rotationFromAxisAngle(Vec3(0.0, 0.0, 0.7)));
  body.setVelocity(Vec3(0.0, 1.0, 2.0));
  EXPECT_TRUE(allNear(body.state().linearMomentum, Vec3(0.0, 3.0, 6.0), 0.0));
  body.setAngularVelocity(Vec3(1.0, 2.0, 3.0));
  EXPECT_TRUE(allNear(body.angularVelocity(), Vec3(1.0, 2.0, 3.0), 1e-13));
  // Re-posing by hand keeps the world-frame L; omega follows the new world inertia.
  const Vec3 L = body.state().angularMomentum;
  body.setOrientation(rotationFromAxisAngle(Vec3(1.0, 0.0, 0.0)));
  EXPECT_TRUE(allNear(body.state().angularMomentum, L, 0.0));
  EXPECT_TRUE(allNear(body.angularVelocity(), body.inverseInertiaWorld() * L, 1e-15));
}

TEST(Forces, ForceAtAPointGivesTorqueAboutTheCentreOfMass) {
  RigidBody body(boxDef(Vec3::Ones(), 1.0));
  const Vec3 x(1.0, 2.0, 3.0);
  body.setPosition(x);
  const Vec3 f(0.5, -2.0, 4.0);
  const Vec3 p(1.5, 2.25, 2.0);
  body.applyForceAtPoint(f, p);
  EXPECT_TRUE(allNear(body.force(), f, 0.0));
  EXPECT_TRUE(allNear(body.torque(), (p - x).cross(f), 0.0)) << "tau = (p - x) x f";
  // A second force accumulates; a force at the centre of mass (or along the line through it)
  // adds no torque.
  const Vec3 tau = body.torque();
  body.applyForceAtPoint(Vec3(1.0, 1.0, 1.0), x);
  body.applyForceAtPoint(Vec3(0.0, 0.0, 2.0), x + Vec3(0.0, 0.0, 5.0));
  body.applyForce(Vec3(-1.0, 0.0, 0.0));
  EXPECT_TRUE(allNear(body.torque(), tau, 0.0));
  EXPECT_TRUE(allNear(body.force(), f + Vec3(0.0, 1.0, 3.0), 0.0));
  body.clearAccumulators();
  EXPECT_TRUE(allNear(body.force(), Vec3::Zero(), 0.0));
  EXPECT_TRUE(allNear(body.torque(), Vec3::Zero(), 0.0));
}

TEST(Forces, APureCoupleHasNoNetForce) {
  RigidBody body(boxDef(Vec3::Ones(), 1.0));
  body.setPosition(Vec3(-3.0, 7.0, 0.5));
  body.setOrientation(rotationFromAxisAngle(Vec3(0.4, 0.4, 0.4)));
  // +f at x + r and -f at x - r: net force 0, torque 2 r x f, wherever the body is.
  const Vec3 r(0.5, 0.0, 0.0);
  const Vec3 f(0.0, 3.0, 0.0);
  body.applyForceAtPoint(f, body.position() + r);
  body.applyForceAtPoint(-f, body.position() - r);
  EXPECT_TRUE(allNear(body.force(), Vec3::Zero(), 0.0));
  EXPECT_TRUE(allNear(body.torque(), Vec3(0.0, 0.0, 3.0), 1e-15)) << "2 r x f = (0, 0, 3)";
  body.applyTorque(Vec3(1.0, 0.0, 0.0));
  EXPECT_TRUE(allNear(body.torque(), Vec3(1.0, 0.0, 3.0), 1e-15));
}

}  // namespace
}  // namespace rbsim

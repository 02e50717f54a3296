// Seed 000's collision impulse and friction, seed 002's K matrices, on cases solved by hand.
#include "rbsim/dynamics/impulse.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

TEST(ImpulseFactor, PointAtTheCentreIsTheInverseMass) {
  const Mat3 inverseInertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
  EXPECT_TRUE(allNear(impulseFactor(0.5, inverseInertia, Vec3::Zero()), 0.5 * Mat3::Identity(), 0.0));
}

TEST(ImpulseFactor, PredictsThePointVelocityChangeOfAnAppliedImpulse) {
  // u_p^new - u_p = dv + domega x r with dv = j / M, domega = I^-1 (r x j): the definition of K.
  const double inverseMass = 1.0 / 3.0;
  const Mat3 R = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  const Mat3 inverseInertia = R * Vec3(2.0, 0.5, 1.25).asDiagonal() * R.transpose();
  const Vec3 r(0.3, -0.2, 0.5);
  const Vec3 j(1.0, -2.0, 0.5);
  const Vec3 dv = inverseMass * j;
  const Vec3 domega = inverseInertia * r.cross(j);
  EXPECT_TRUE(allNear(impulseFactor(inverseMass, inverseInertia, r) * j, dv + domega.cross(r), 1e-14));
}

TEST(CoupledImpulseFactor, IsSymmetricPositiveDefiniteAndItsTopLeftIsK) {
  const Mat3 inverseInertia = Vec3(2.0, 0.5, 1.25).asDiagonal();
  const Vec3 r(0.3, -0.2, 0.5);
  const Mat6 k = coupledImpulseFactor(0.25, inverseInertia, r);
  EXPECT_TRUE(allNear(k, k.transpose(), 1e-15));
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat6>(k).eigenvalues().minCoeff(), 0.0);
  EXPECT_TRUE(allNear(Mat3(k.topLeftCorner<3, 3>()), impulseFactor(0.25, inverseInertia, r), 0.0));
  // A pure angular impulse changes omega by I^-1 j_tau, and the point's velocity by that x r.
  Vec6 angular = Vec6::Zero();
  angular.tail<3>() = Vec3(0.0, 0.0, 2.0);
  const Vec6 change = k * angular;
  const Vec3 domega = inverseInertia * Vec3(0.0, 0.0, 2.0);
  EXPECT_TRUE(allNear(Vec3(change.tail<3>()), domega, 1e-15));
  EXPECT_TRUE(allNear(Vec3(change.head<3>()), domega.cross(r), 1e-15));
}

// The solver's friction factor is seed 002's 6x6 K seen through the friction coordinates.
TEST(FrictionImpulseFactor, EqualsTheCoupledFactorRestrictedToTangentsAndTwist) {
  const Mat3 inverseInertia = Mat3(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -1.0).normalized())) *
                              Vec3(2.0, 0.5, 1.25).asDiagonal() *
                              Mat3(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -1.0).normalized())).transpose();
  const Vec3 r(0.3, -0.2, 0.5);
  const Vec3 n = Vec3(0.2, 1.0, -0.3).normalized();
  const Vec3 t1 = n.cross(Vec3::UnitX()).normalized();
  const Vec3 t2 = n.cross(t1);
  Eigen::Matrix<double, 6, 3> s = Eigen::Matrix<double, 6, 3>::Zero();
  s.block<3, 1>(0, 0) = t1;
  s.block<3, 1>(0, 1) = t2;
  s.block<3, 1>(3, 2) = n;
  const Mat3 expected = s.transpose() * coupledImpulseFactor(0.25, inverseInertia, r) * s;
  EXPECT_TRUE(allNear(frictionImpulseFactor(0.25, inverseInertia, r, t1, t2, n), expected, 1e-14));
}

// Two unit point masses, head on: j_n = -(1 + c_R) u_N / (1/m1 + 1/m2).
TEST(CollisionImpulse, HeadOnPointMassesReverseTheApproachTimesRestitution) {
  for (double e : {0.0, 0.5, 1.0}) {
    Material m;
    m.restitution = e;
    const Mat3 k = (1.0 / 2.0 + 1.0 / 3.0) * Mat3::Identity();
    const Vec3 u(0.0, -4.0, 0.0);  // body 1 moving towards body 2 along -N
    const CollisionImpulse out = collisionImpulse(k, u, Vec3::UnitY(), m);
    ASSERT_TRUE(out.colliding);
    EXPECT_NEAR((u + k * out.impulse).y(), 4.0 * e, 1e-14) << "e = " << e;
    EXPECT_NEAR(out.impulse.y(), (1.0 + e) * 4.0 / (1.0 / 2.0 + 1.0 / 3.0), 1e-12);
  }
}

TEST(CollisionImpulse, SeparatingOrRestingBodiesGetNoImpulse) {
  const Mat3 k = Mat3::Identity();
  for (const Vec3& u : {Vec3(1.0, 2.0, 0.0), Vec3(3.0, 0.0, -1.0)}) {
    const CollisionImpulse out = collisionImpulse(k, u, Vec3::UnitY(), Material{});
    EXPECT_FALSE(out.colliding);
    EXPECT_EQ(out.impulse, Vec3::Zero());
  }
}

TEST(CollisionImpulse, InsideTheConeTheContactSticks) {
  // u_T / |u_N| = 0.2 < mu_s: the sticking impulse stops the tangential motion entirely.
  Material m;
  m.staticFriction = 0.5;
  m.kineticFriction = 0.3;
  const Mat3 k = Mat3::Identity();  // a unit point mass against the ground
  const Vec3 u(0.2, -1.0, 0.0);
  const CollisionImpulse out = collisionImpulse(k, u, Vec3::UnitY(), m);
  EXPECT_TRUE(out.sticking);
  EXPECT_TRUE(allNear(Vec3(u + k * out.impulse), Vec3::Zero(), 1e-15));
}

TEST(CollisionImpulse, OutsideTheConeKineticFrictionActsAgainstTheSlip) {
  // Unit point mass, u = (2, -1, 0), mu_k = 0.3, c_R = 0: j_n = 1, j_T = -0.3, so the slip drops
  // from 2 to 1.7 and the normal velocity becomes exactly 0.
  Material m;
  m.staticFriction = 0.5;
  m.kineticFriction = 0.3;
  const Mat3 k = Mat3::Identity();
  const Vec3 u(2.0, -1.0, 0.0);
  const CollisionImpulse out = collisionImpulse(k, u, Vec3::UnitY(), m);
  EXPECT_FALSE(out.sticking);
  EXPECT_TRUE(allNear(out.impulse, Vec3(-0.3, 1.0, 0.0), 1e-15));
  EXPECT_TRUE(allNear(Vec3(u + k * out.impulse), Vec3(1.7, 0.0, 0.0), 1e-15));
}

TEST(CollisionImpulse, KineticImpulseHonoursRestitutionWithARotatingBody) {
  // Off-centre hit on a box-like body: the normal condition -c_R u_N = u_N^new must hold exactly
  // with the coupled K, and the tangential impulse is mu_k times the normal one.
  Material m;
  m.restitution = 0.5;
  m.staticFriction = 0.2;
  m.kineticFriction = 0.1;
  const Mat3 k = impulseFactor(1.0, Vec3(6.0, 3.0, 4.0).asDiagonal(), Vec3(0.4, -0.5, 0.1));
  const Vec3 n = Vec3::UnitY();
  const Vec3 u(3.0, -2.0, 1.0);
  const CollisionImpulse out = collisionImpulse(k, u, n, m);
  ASSERT_FALSE(out.sticking);
  EXPECT_NEAR((u + k * out.impulse).dot(n), 0.5 * 2.0, 1e-13);
  const double jn = out.impulse.dot(n);
  EXPECT_NEAR((out.impulse - jn * n).norm(), 0.1 * jn, 1e-13);
  EXPECT_LT((out.impulse - jn * n).dot(u - u.dot(n) * n), 0.0);  // against the slip
}

}  // namespace
}  // namespace rbsim

// The weld's six rows as one block (issue 55, item 3; engine/src/dynamics/joints/weld.cpp): the
// block is seed 002 2.2.1's K_A + K_B, it equals a dense J M^-1 J^T, and one rigid sweep of it
// removes the anchor's relative velocity and the relative angular velocity exactly, which Box2D
// v3's split form (three angular rows, then the point's three) does not.
#include <gtest/gtest.h>

#include <cstdio>

#include <Eigen/LU>

#include "dynamics/joints/joint_rows.h"
#include "rbsim/dynamics/impulse.h"
#include "rbsim/math/rotation.h"
#include "test_util.h"

namespace rbsim {
namespace {

// (Named for this file alone: the suite is a unity build.)
using WeldMat12 = Eigen::Matrix<double, 12, 12>;
using WeldVec12 = Eigen::Matrix<double, 12, 1>;
using WeldJacobian = Eigen::Matrix<double, 6, 12>;

// Two bodies of unequal mass whose inverse inertias are off-diagonal in world frame, joined at
// an anchor off both centres (and off their principal axes), moving and spinning apart.
struct WeldCase {
  Mat3 iA, iB;  // world inverse inertias [1/(kg m^2)]
  joint_rows::Pair p;  // its iA, iB point at the WeldCase's own: bind() after every copy
  joint_rows::Frame f;
  Joint joint;
  WeldCase& bind() {
    p.iA = &iA;
    p.iB = &iB;
    return *this;
  }
};

WeldCase makeWeldCase() {
  WeldCase c;
  const Mat3 RA = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  const Mat3 RB = Quat(Eigen::AngleAxisd(-1.1, Vec3(-2, 1, 0.5).normalized())).toRotationMatrix();
  c.iA = RA * Vec3(2.0, 0.5, 1.25).asDiagonal() * RA.transpose();  // [1/(kg m^2)]
  c.iB = RB * Vec3(0.8, 3.0, 1.5).asDiagonal() * RB.transpose();
  c.p = joint_rows::Pair{Vec3(0.3, -1.0, 0.2), Vec3(0.5, 0.1, -0.7), Vec3(-0.4, 0.6, 1.1), Vec3(-1.3, 0.2, 0.9), 0.5, 1.0 / 3.0,
             nullptr, nullptr};
  c.f.rA = Vec3(0.3, -0.2, 0.5);  // [m]
  c.f.rB = Vec3(-0.45, 0.1, -0.25);
  c.f.xA = Vec3(1.0, 2.0, 0.0);
  c.f.xB = c.f.xA + c.f.rA - c.f.rB;  // the anchors meet
  c.f.axis = Vec3::UnitZ();
  c.f.base = c.f.moving = Quat::Identity();
  c.joint.def.type = JointDef::Type::Weld;  // 0 Hz: the sweep's own softness
  return c;  // unbound: the caller binds its copy
}

// J for u = (vA, wA, vB, wB): Cdot = ((vB + wB x rB) - (vA + wA x rA), wB - wA).
WeldJacobian weldJacobian(const joint_rows::Frame& f) {
  WeldJacobian J = WeldJacobian::Zero();
  J.block<3, 3>(0, 0) = -Mat3::Identity();
  J.block<3, 3>(0, 3) = star(f.rA);  // -(wA x rA) = rA x wA
  J.block<3, 3>(0, 6) = Mat3::Identity();
  J.block<3, 3>(0, 9) = -star(f.rB);
  J.block<3, 3>(3, 3) = -Mat3::Identity();
  J.block<3, 3>(3, 9) = Mat3::Identity();
  return J;
}

WeldMat12 weldInverseMass(const WeldCase& c) {
  WeldMat12 m = WeldMat12::Zero();
  m.block<3, 3>(0, 0) = c.p.mA * Mat3::Identity();
  m.block<3, 3>(3, 3) = c.iA;
  m.block<3, 3>(6, 6) = c.p.mB * Mat3::Identity();
  m.block<3, 3>(9, 9) = c.iB;
  return m;
}

WeldVec12 weldVelocities(const joint_rows::Pair& p) {
  WeldVec12 u;
  u << p.vA, p.wA, p.vB, p.wB;
  return u;
}

Vec6 weldRelativeMotion(const WeldCase& c, const joint_rows::Pair& p) { return weldJacobian(c.f) * weldVelocities(p); }

TEST(WeldBlock, IsTheSumOfTheTwoBodiesSixBySixFactorsAndJMinvJt) {
  WeldCase c = makeWeldCase();
  c.bind();
  const Mat6 block = joint_rows::weldBlock(c.p, c.f);
  const Mat6 seed002 = coupledImpulseFactor(c.p.mA, c.iA, c.f.rA) + coupledImpulseFactor(c.p.mB, c.iB, c.f.rB);
  const WeldJacobian J = weldJacobian(c.f);
  const Mat6 dense = J * weldInverseMass(c) * J.transpose();
  EXPECT_TRUE(test::allNear(block, seed002, 0.0));
  EXPECT_TRUE(test::allNear(block, dense, 1e-14));
  // The coupling is what the split form leaves out: here it is of the order of the blocks.
  EXPECT_GT((block.topRightCorner<3, 3>().cwiseAbs().maxCoeff()), 0.1);
}

TEST(WeldBlock, OneRigidSweepRemovesTheRelativeMotionWhereTheSplitFormDoesNot) {
  WeldCase c = makeWeldCase();
  c.bind();
  const Softness rigid;  // the relax: no bias, mass scale 1, impulse scale 0
  WeldCase coupled = c;
  coupled.bind();
  joint_rows::solveWeld(coupled.joint, joint_rows::Extra{}, coupled.f, rigid, coupled.p);
  const Vec6 residual = weldRelativeMotion(c, coupled.p);

  // The dense reference: lambda = -(J M^-1 J^T)^-1 J u, u' = u + M^-1 J^T lambda.
  const WeldJacobian J = weldJacobian(c.f);
  const WeldMat12 Minv = weldInverseMass(c);
  const Vec6 lambda = -(J * Minv * J.transpose()).fullPivLu().solve(J * weldVelocities(c.p));
  const WeldVec12 reference = weldVelocities(c.p) + Minv * J.transpose() * lambda;

  WeldCase split = c;
  split.bind();
  joint_rows::solveWeldSplit(split.joint, split.f, rigid, rigid, split.p);
  const Vec6 splitResidual = weldRelativeMotion(c, split.p);
  std::printf("one rigid weld sweep: relative motion %.3g before, %.3g coupled, %.3g split (3 + 3)\n",
              weldRelativeMotion(c, c.p).norm(), residual.norm(), splitResidual.norm());

  EXPECT_LT(residual.norm(), 1e-12);
  EXPECT_TRUE(test::allNear(weldVelocities(coupled.p), reference, 1e-12));
  EXPECT_TRUE(test::allNear(Vec3(coupled.joint.linearImpulse), Vec3(lambda.head<3>()), 1e-12));
  EXPECT_TRUE(test::allNear(Vec3(coupled.joint.angularImpulse), Vec3(lambda.tail<3>()), 1e-12));
  // The split form's point rows turn the bodies after the angular rows have stopped them.
  EXPECT_GT(splitResidual.tail<3>().norm(), 0.1);
}

TEST(WeldBlock, SoftWithOneSoftnessTheBlockIsBox2DsSoftRowOnTheCoupledMass) {
  // b2MakeSoft's update lambda = -s_m K^-1 (Cdot + beta C) - s_i lambda_acc is the soft row of
  // compliance K / a2: (K + K / a2) lambda = -(Cdot + beta C + (K / a2) lambda_acc).
  WeldCase c = makeWeldCase();
  c.bind();
  c.f.xB += Vec3(0.01, -0.02, 0.005);  // the anchors 2.3 cm apart
  c.joint.linearImpulse = Vec3(0.2, -0.1, 0.3);
  c.joint.angularImpulse = Vec3(-0.05, 0.1, 0.02);
  constexpr double kHertz = 30.0, kDampingRatio = 0.7, kSubstep = 1.0 / 600.0;  // [Hz], [1], [s]
  const Softness soft = makeSoftness(kHertz, kDampingRatio, kSubstep);
  const double omega = 2.0 * M_PI * kHertz;
  const double a2 = kSubstep * omega * (2.0 * kDampingRatio + kSubstep * omega);
  Vec6 cdot = weldRelativeMotion(c, c.p), error, accumulated;
  error << (c.f.xB + c.f.rB) - (c.f.xA + c.f.rA), Vec3::Zero();
  accumulated << c.joint.linearImpulse, c.joint.angularImpulse;
  const Mat6 K = joint_rows::weldBlock(c.p, c.f);
  const Vec6 expected = -(K + K / a2).fullPivLu().solve(cdot + soft.biasRate * error + (K / a2) * accumulated);
  const Vec3 linear0 = c.joint.linearImpulse, angular0 = c.joint.angularImpulse;
  joint_rows::solveWeldCoupled(c.joint, c.f, soft, c.p);
  EXPECT_TRUE(test::allNear(Vec3(c.joint.linearImpulse - linear0), Vec3(expected.head<3>()), 1e-12));
  EXPECT_TRUE(test::allNear(Vec3(c.joint.angularImpulse - angular0), Vec3(expected.tail<3>()), 1e-12));
}

TEST(WeldBlock, DifferingLinearAndAngularSoftnessKeepsTheSplitForm) {
  WeldCase c = makeWeldCase();
  c.joint.def.linearHertz = 8.0;  // [Hz]; the angular rows keep the sweep's softness
  joint_rows::Extra extra;
  extra.weldLinear = makeSoftness(8.0, 1.0, 1.0 / 600.0);
  c.bind();
  WeldCase split = c;
  split.bind();
  const Softness rigid;
  joint_rows::solveWeld(c.joint, extra, c.f, rigid, c.p);
  joint_rows::solveWeldSplit(split.joint, split.f, extra.weldLinear, rigid, split.p);
  EXPECT_TRUE(test::allNear(weldVelocities(c.p), weldVelocities(split.p), 0.0));
}

}  // namespace
}  // namespace rbsim

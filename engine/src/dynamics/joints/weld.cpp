// A weld (fixed) joint: A's anchor held at the base's and A's orientation at the one it was
// added in. Its six rows (the point's three, the orientation's three) are one block, solved as
// seed 002 2.2.1 exchanges a linear and an angular impulse between two bodies: the impulse
// (j, j_tau) changes the relative velocity of the anchor and the relative angular velocity by
// (K_A + K_B)(j, j_tau), each K the body's 6x6 coupledImpulseFactor at its own anchor arm, so the
// block's solve removes both at once. A weld of 0 Hz has the joints' softness in the biased
// sweep and is rigid in the relax, as every joint; given hertz, it is that spring in both sweeps.
#include <Eigen/Cholesky>

#include "dynamics/joints/joint_rows.h"
#include "rbsim/dynamics/impulse.h"

namespace rbsim::joint_rows {

Mat6 weldBlock(const Pair& p, const Frame& f) {
  // Rows (linear, angular) as the Jacobians J_A = -[[1, -[rA]], [0, 1]] and J_B = [[1, -[rB]], [0, 1]]
  // order them: J_A M_A^-1 J_A^T is seed 002's K of body A at rA, and the same of B.
  return coupledImpulseFactor(p.mA, *p.iA, f.rA) + coupledImpulseFactor(p.mB, *p.iB, f.rB);
}

void solveWeldCoupled(Joint& joint, const Frame& f, const Softness& soft, Pair& p) {
  Vec6 cdot, error, accumulated;
  cdot << (p.vB + p.wB.cross(f.rB)) - (p.vA + p.wA.cross(f.rA)), p.wB - p.wA;
  error << (f.xB + f.rB) - (f.xA + f.rA), relativeRotation(joint, f.base, f.moving);
  accumulated << joint.linearImpulse, joint.angularImpulse;
  // Factored once per sweep: rA, rB and the world inverse inertias move with every substep's
  // positions (the relax follows integratePositions), so a sweep is where the Jacobians are fixed.
  // Cholesky (LLT), no pivoting: the block is SPD for any side of finite mass (seed 002 2.2.1). A
  // singular inverse inertia leaves it semidefinite: LDLT then, which gives the rows that cannot
  // move zero impulse.
  const Mat6 K = weldBlock(p, f);
  const Vec6 rhs = cdot + soft.biasRate * error;
  const Eigen::LLT<Mat6> cholesky(K);
  const Vec6 solved = cholesky.info() == Eigen::Success ? Vec6(cholesky.solve(rhs)) : Vec6(K.ldlt().solve(rhs));
  // Box2D v3's soft constraint (solver.c b2MakeSoft) on the block as a whole.
  const Vec6 lambda = -soft.massScale * solved - soft.impulseScale * accumulated;
  const Vec3 linear = lambda.head<3>(), angular = lambda.tail<3>();
  joint.linearImpulse += linear;
  joint.angularImpulse += angular;
  p.vA -= p.mA * linear;
  p.wA -= *p.iA * (f.rA.cross(linear) + angular);
  p.vB += p.mB * linear;
  p.wB += *p.iB * (f.rB.cross(linear) + angular);
}

void solveWeldSplit(Joint& joint, const Frame& f, const Softness& linear, const Softness& angular, Pair& p) {
  // Box2D v3's src/weld_joint.c: the three angular rows, then the point's three, each block with
  // its own softness. K = (mA + mB) 1 - [rA] iA [rA] - [rB] iB [rB], as the ball joint's.
  solveAngularSpring(rotationMass(p), relativeRotation(joint, f.base, f.moving), angular, joint.angularImpulse, p);
  const Mat3 K = impulseFactor(p.mA, *p.iA, f.rA) + impulseFactor(p.mB, *p.iB, f.rB);
  const Vec3 cdot = (p.vB + p.wB.cross(f.rB)) - (p.vA + p.wA.cross(f.rA));
  const Vec3 error = (f.xB + f.rB) - (f.xA + f.rA);
  const Vec3 lambda =
      -linear.massScale * K.ldlt().solve(cdot + linear.biasRate * error) - linear.impulseScale * joint.linearImpulse;
  joint.linearImpulse += lambda;
  p.vA -= p.mA * lambda;
  p.wA -= *p.iA * f.rA.cross(lambda);
  p.vB += p.mB * lambda;
  p.wB += *p.iB * f.rB.cross(lambda);
}

void solveWeld(Joint& joint, const Extra& extra, const Frame& f, const Softness& soft, Pair& p) {
  const JointDef& def = joint.def;
  const Softness linear = def.linearHertz > 0.0 ? extra.weldLinear : soft;
  const Softness angular = def.angularHertz > 0.0 ? extra.weldAngular : soft;
  // b2MakeSoft's update is the soft row of compliance K / a2 (a2 = h omega (2 zeta + h omega)): one
  // a2 per block. Differing a2 would need the non-symmetric K diag(1 / a2), so weld_joint.c's split.
  const bool shared = linear.biasRate == angular.biasRate && linear.massScale == angular.massScale &&
                      linear.impulseScale == angular.impulseScale;
  if (shared) {
    solveWeldCoupled(joint, f, linear, p);
  } else {
    solveWeldSplit(joint, f, linear, angular, p);
  }
}

}  // namespace rbsim::joint_rows

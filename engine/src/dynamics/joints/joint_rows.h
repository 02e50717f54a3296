#pragma once
// The pieces the soft step's joints share (soft_step_joints.cpp, joints/*.cpp): one scalar row of
// a joint (a spring, a friction, a motor, a limit) and the velocities a joint's rows update. A
// row's impulse lambda acts +lambda on the moving side (body A of the JointDef, slot "B" here as
// in Box2D) and -lambda on the base (its body B or the world):
//   Cdot = linear . (vB - vA) + angularB . wB - angularA . wA,
//   vA -= mA lambda linear, wA -= lambda iA angularA, vB += mB lambda linear, wB += lambda iB angularB.
// Box2D v3 src/revolute_joint.c and prismatic_joint.c solve their axial rows this way.
#include <algorithm>

#include "rbsim/dynamics/impulse.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/dynamics/softness.h"
#include "rbsim/math/types.h"

namespace rbsim::joint_rows {

// The two sides' velocities while a joint is solved, and what they resist with.
struct Pair {
  Vec3 vA, wA, vB, wB;
  double mA = 0.0, mB = 0.0;   // [1/kg]
  const Mat3* iA = nullptr;    // world inverse inertia [1/(kg m^2)]
  const Mat3* iB = nullptr;
};

struct Row {
  Vec3 linear = Vec3::Zero();
  Vec3 angularA = Vec3::Zero();
  Vec3 angularB = Vec3::Zero();
  double mass = 0.0;  // 1 / (J M^-1 J^T); 0 when neither side can move along it

  double cdot(const Pair& p) const { return linear.dot(p.vB - p.vA) + angularB.dot(p.wB) - angularA.dot(p.wA); }
  void apply(Pair& p, double lambda) const {
    p.vA -= (p.mA * lambda) * linear;
    p.wA -= lambda * (*p.iA * angularA);
    p.vB += (p.mB * lambda) * linear;
    p.wB += lambda * (*p.iB * angularB);
  }
};

inline Row makeRow(const Pair& p, const Vec3& linear, const Vec3& angularA, const Vec3& angularB) {
  Row r{linear, angularA, angularB, 0.0};
  const double k = (p.mA + p.mB) * linear.squaredNorm() + angularA.dot(*p.iA * angularA) + angularB.dot(*p.iB * angularB);
  r.mass = k > 0.0 ? 1.0 / k : 0.0;
  return r;
}

// An angular row about a unit axis, the same on both sides (a hinge's axis, a cone's swing axis).
inline Row angularRow(const Pair& p, const Vec3& axis) { return makeRow(p, Vec3::Zero(), axis, axis); }

// A spring row toward C = 0 (C the angle or the translation now): a soft constraint of the
// spring's own softness in both sweeps, as Box2D v3's revolute spring. `accumulated` is the
// row's impulse so far.
inline void solveSpring(const Row& row, double C, const Softness& soft, double& accumulated, Pair& p) {
  const double lambda = -soft.massScale * row.mass * (row.cdot(p) + soft.biasRate * C) - soft.impulseScale * accumulated;
  accumulated += lambda;
  row.apply(p, lambda);
}

// A motor of target speed `speed` whose impulse over the substep h stays within +-maxImpulse
// (= h times the largest torque or force); joint friction is the motor of speed 0.
inline void solveMotor(const Row& row, double speed, double maxImpulse, double& accumulated, Pair& p) {
  const double old = accumulated;
  accumulated = std::clamp(old - row.mass * (row.cdot(p) - speed), -maxImpulse, maxImpulse);
  row.apply(p, accumulated - old);
}

// One side of a limit, C >= 0 with the row's sign already in it (sign -1 for an upper limit).
// Not reached, it is speculative (the gap may close within the substep, no further); reached, it
// is soft with bias and rigid in the relax, as the hinge's limits (Box2D v3's revolute_joint.c).
inline void solveLimit(const Row& row, double sign, double C, double inverseH, const Softness& soft, bool useBias,
                       double& accumulated, Pair& p) {
  double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
  if (C > 0.0) {
    bias = C * inverseH;
  } else if (useBias) {
    bias = soft.biasRate * C;
    massScale = soft.massScale;
    impulseScale = soft.impulseScale;
  }
  const double old = accumulated;
  accumulated = std::max(old - massScale * row.mass * (sign * row.cdot(p) + bias) - impulseScale * old, 0.0);
  row.apply(p, sign * (accumulated - old));
}

// The inverse of the angular effective mass iA + iB, or zero when neither side can turn.
inline Mat3 rotationMass(const Pair& p) {
  const Mat3 k = *p.iA + *p.iB;
  // A sum of inverse inertias is zero or positive definite: a determinant this small is zero.
  constexpr double kSingular = 1e-300;  // [1/(kg m^2)^3]
  return k.determinant() > kSingular ? Mat3(k.inverse()) : Mat3::Zero();
}

// An angular spring toward the rotation the joint was added in (C the relative rotation vector,
// world frame), the ball's spring; Box3D's src/spherical_joint.c.
inline void solveAngularSpring(const Mat3& mass, const Vec3& C, const Softness& soft, Vec3& accumulated, Pair& p) {
  const Vec3 lambda = -soft.massScale * (mass * (p.wB - p.wA + soft.biasRate * C)) - soft.impulseScale * accumulated;
  accumulated += lambda;
  p.wA -= *p.iA * lambda;
  p.wB += *p.iB * lambda;
}

// The ball's friction: a motor holding omega_B - omega_A at zero, its impulse within a ball of
// radius maxImpulse (Box3D's spherical motor).
inline void solveAngularFriction(const Mat3& mass, double maxImpulse, Vec3& accumulated, Pair& p) {
  Vec3 next = accumulated - mass * (p.wB - p.wA);
  const double length = next.norm();
  if (length > maxImpulse) next *= maxImpulse / length;
  const Vec3 lambda = next - accumulated;
  accumulated = next;
  p.wA -= *p.iA * lambda;
  p.wB += *p.iB * lambda;
}

// What a joint's prepare gives the solve of the features beyond a plain ball or hinge, one per
// such joint and step (SoftStepSolver::jointExtras_).
struct Extra {
  Softness spring;        // the joint's spring, for h
  Softness weldLinear;    // the weld's, when its hertz > 0
  Softness weldAngular;
  // Ball: the swing axis (cone x twist axis, unit, or zero when they are aligned) and the twist
  // limit's Jacobian, fixed over the step as Box3D's spherical joint does.
  Vec3 swingAxis = Vec3::Zero();
  Vec3 twistJacobian = Vec3::Zero();
};

// Where a joint is in this substep, world frame.
struct Frame {
  Vec3 xA, xB;        // the sides' centres of mass (the ground slot's origin for a slotless base) [m]
  Vec3 rA, rB;        // each side's anchor from its centre [m]
  Vec3 axis;          // the base's copy of the axis, unit
  Quat base, moving;  // orientations for the angles (a slotless static base's own)
};

// Each joint type's rows beyond the shared ones, on the pair's velocities (joints/*.cpp).
// `soft` is the joints' softness in the biased sweep and rigid in the relax; h the substep [s].
void solveHingeExtras(Joint& joint, const Extra& extra, const Frame& f, double h, Pair& p);      // spring, friction
void solveBallAngular(Joint& joint, const Extra& extra, const Frame& f, double h, const Softness& soft, bool useBias,
                      Pair& p);  // spring, friction, twist and cone limits
void solvePrismatic(Joint& joint, const Extra& extra, const Frame& f, double h, const Softness& soft, bool useBias, Pair& p);
void solveWeld(Joint& joint, const Extra& extra, const Frame& f, const Softness& soft, Pair& p);
// The weld's parts (joints/weld.cpp): its 6x6 block K_A + K_B (seed 002 2.2.1) in (linear at the
// anchor, angular) rows; the block solved as one with one softness; Box2D v3's split 3 + 3 form.
Mat6 weldBlock(const Pair& p, const Frame& f);
void solveWeldCoupled(Joint& joint, const Frame& f, const Softness& soft, Pair& p);
void solveWeldSplit(Joint& joint, const Frame& f, const Softness& linear, const Softness& angular, Pair& p);
// The ball's swing axis and twist Jacobian for a step (Extra), from the sides' world axes.
void prepareBallLimits(const Vec3& coneAxis, const Vec3& twistAxis, Extra& extra);

}  // namespace rbsim::joint_rows

// A ball joint's angular rows, before its point (soft_step_joints.cpp): a spring toward the
// rotation it was added in, friction, and the twist and cone limits, after Box3D's
// src/spherical_joint.c (spring, motor, twist, cone, then the point). The cone holds the swing,
// the angle between the base's axis and A's copy of it; the twist is A's turning about its axis
// in the swing-twist split of the relative rotation (hingeAngle).
#include <cmath>

#include "dynamics/joints/joint_rows.h"

namespace rbsim::joint_rows {

void prepareBallLimits(const Vec3& coneAxis, const Vec3& twistAxis, Extra& extra) {
  const Vec3 normal = coneAxis.cross(twistAxis);
  const double sine = normal.norm();
  // Aligned axes have no swing direction: the cone is far from binding and gets no row, and the
  // twist's Jacobian is the axis itself.
  constexpr double kAlignedSine = 1e-9;  // [1]
  if (sine < kAlignedSine) {
    extra.swingAxis.setZero();
    extra.twistJacobian = coneAxis;
    return;
  }
  extra.swingAxis = normal / sine;
  // The twist's rate is (omega_B - omega_A) . (cone + tan(swing / 2) (swing axis x cone)):
  // turning about the swing axis moves the twist by that much (Box3D's twistJacobian).
  const double swing = std::atan2(sine, coneAxis.dot(twistAxis));
  extra.twistJacobian = coneAxis + std::tan(0.5 * swing) * extra.swingAxis.cross(coneAxis);
}

void solveBallAngular(Joint& joint, const Extra& extra, const Frame& f, double h, const Softness& soft, bool useBias,
                      Pair& p) {
  const JointDef& def = joint.def;
  const double inverseH = 1.0 / h;
  if (def.spring || def.friction > 0.0) {
    const Mat3 mass = rotationMass(p);
    if (def.spring) solveAngularSpring(mass, relativeRotation(joint, f.base, f.moving), extra.spring, joint.springImpulse, p);
    if (def.friction > 0.0) solveAngularFriction(mass, h * def.friction, joint.frictionImpulse, p);
  }
  if (def.limits) {
    const Row row = angularRow(p, extra.twistJacobian);
    if (row.mass > 0.0) {
      const double twist = hingeAngle(joint, f.base, f.moving);
      solveLimit(row, 1.0, twist - def.lowerAngle, inverseH, soft, useBias, joint.lowerImpulse, p);
      solveLimit(row, -1.0, def.upperAngle - twist, inverseH, soft, useBias, joint.upperImpulse, p);
    }
  }
  if (def.coneLimit) {
    // C = cone - swing >= 0; the swing grows with (omega_B - omega_A) . swing axis, so the row
    // is the swing axis negated.
    const Row row = angularRow(p, -extra.swingAxis);
    if (row.mass > 0.0) {
      const double C = def.coneAngle - swingAngle(joint, f.base, f.moving);
      solveLimit(row, 1.0, C, inverseH, soft, useBias, joint.swingImpulse, p);
    }
  }
}

}  // namespace rbsim::joint_rows

// A hinge's spring and friction, before its motor, limits and block (soft_step_joints.cpp): Box2D
// v3's src/revolute_joint.c solves the spring first, then the motor; friction is a motor of speed
// 0 (Box3D's shared/human.c sets a ragdoll's joint friction that way).
#include "dynamics/joints/joint_rows.h"

namespace rbsim::joint_rows {

void solveHingeExtras(Joint& joint, const Extra& extra, const Frame& f, double h, Pair& p) {
  const JointDef& def = joint.def;
  const Row row = angularRow(p, f.axis);
  if (row.mass == 0.0) return;
  if (def.spring) {
    double accumulated = f.axis.dot(joint.springImpulse);
    solveSpring(row, hingeAngle(joint, f.base, f.moving), extra.spring, accumulated, p);
    joint.springImpulse = accumulated * f.axis;
  }
  if (def.friction > 0.0) {
    double accumulated = f.axis.dot(joint.frictionImpulse);
    solveMotor(row, 0.0, h * def.friction, accumulated, p);
    joint.frictionImpulse = accumulated * f.axis;
  }
}

}  // namespace rbsim::joint_rows

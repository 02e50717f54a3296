// A prismatic (slider) joint: A's anchor moves along the base's axis only and A keeps its
// orientation relative to the base. After Box2D v3's src/prismatic_joint.c, in 3D: per sweep the
// spring, friction, motor and limits along the axis, then the two rows across the axis and the
// three angular rows as one 5 x 5 block, solved exactly like the hinge's.
#include <Eigen/Dense>

#include "dynamics/contact_key.h"
#include "dynamics/joints/joint_rows.h"

namespace rbsim::joint_rows {

void solvePrismatic(Joint& joint, const Extra& extra, const Frame& f, double h, const Softness& soft, bool useBias,
                    Pair& p) {
  const JointDef& def = joint.def;
  // d: B's anchor from A's. A linear row along n has the Jacobian [-n, -(d + rA) x n; n, rB x n]:
  // the base's copy of the axis turns with it, so its lever arm reaches B's anchor.
  const Vec3 d = (f.xB + f.rB) - (f.xA + f.rA);
  const Vec3 armA = d + f.rA;
  const auto linearRow = [&](const Vec3& n) { return makeRow(p, n, armA.cross(n), f.rB.cross(n)); };
  const Row axial = linearRow(f.axis);
  const double translation = f.axis.dot(d);
  if (axial.mass > 0.0) {
    if (def.spring) {
      double accumulated = f.axis.dot(joint.springImpulse);
      solveSpring(axial, translation, extra.spring, accumulated, p);
      joint.springImpulse = accumulated * f.axis;
    }
    if (def.friction > 0.0) {
      double accumulated = f.axis.dot(joint.frictionImpulse);
      solveMotor(axial, 0.0, h * def.friction, accumulated, p);
      joint.frictionImpulse = accumulated * f.axis;
    }
    if (def.motor) {
      // As the hinge's motor: at a stop it drives into, it lets go and the stop alone acts.
      const bool intoStop = def.limits && ((translation <= def.lowerTranslation && def.motorSpeed < 0.0) ||
                                           (translation >= def.upperTranslation && def.motorSpeed > 0.0));
      if (intoStop) {
        axial.apply(p, -joint.motorImpulse);
        joint.motorImpulse = 0.0;
      } else {
        solveMotor(axial, def.motorSpeed, h * def.maxMotorForce, joint.motorImpulse, p);
      }
    }
    if (def.limits) {
      const double inverseH = 1.0 / h;
      solveLimit(axial, 1.0, translation - def.lowerTranslation, inverseH, soft, useBias, joint.lowerImpulse, p);
      solveLimit(axial, -1.0, def.upperTranslation - translation, inverseH, soft, useBias, joint.upperImpulse, p);
    }
  }

  // Rows 0-1: across the axis (C = t_k . d); rows 2-4: the relative rotation (C = its rotation
  // vector, Cdot = omega_B - omega_A). K = J_A M_A^-1 J_A^T + J_B M_B^-1 J_B^T, fixed sizes.
  using Jacobian = Eigen::Matrix<double, 5, 6>;
  using Vec5 = Eigen::Matrix<double, 5, 1>;
  Jacobian jA = Jacobian::Zero(), jB = Jacobian::Zero();
  Vec5 error, accumulated;
  Vec3 tangents[2];
  tangentBasis(f.axis, tangents[0], tangents[1]);
  for (int k = 0; k < 2; ++k) {
    const Vec3& t = tangents[k];
    jA.block<1, 3>(k, 0) = -t.transpose();
    jA.block<1, 3>(k, 3) = -armA.cross(t).transpose();
    jB.block<1, 3>(k, 0) = t.transpose();
    jB.block<1, 3>(k, 3) = f.rB.cross(t).transpose();
    error(k) = t.dot(d);
    accumulated(k) = t.dot(joint.linearImpulse);
  }
  jA.block<3, 3>(2, 3) = -Mat3::Identity();
  jB.block<3, 3>(2, 3) = Mat3::Identity();
  error.tail<3>() = relativeRotation(joint, f.base, f.moving);
  accumulated.tail<3>() = joint.angularImpulse;
  Eigen::Matrix<double, 6, 6> inverseMassA = Eigen::Matrix<double, 6, 6>::Zero(), inverseMassB = inverseMassA;
  inverseMassA.block<3, 3>(0, 0) = p.mA * Mat3::Identity();
  inverseMassA.block<3, 3>(3, 3) = *p.iA;
  inverseMassB.block<3, 3>(0, 0) = p.mB * Mat3::Identity();
  inverseMassB.block<3, 3>(3, 3) = *p.iB;
  Eigen::Matrix<double, 6, 1> uA, uB;
  uA << p.vA, p.wA;
  uB << p.vB, p.wB;
  const Eigen::Matrix<double, 5, 5> K = jA * inverseMassA * jA.transpose() + jB * inverseMassB * jB.transpose();
  const Vec5 cdot = jA * uA + jB * uB;
  const Vec5 impulse = -soft.massScale * K.ldlt().solve(cdot + soft.biasRate * error) - soft.impulseScale * accumulated;
  uA += inverseMassA * jA.transpose() * impulse;
  uB += inverseMassB * jB.transpose() * impulse;
  p.vA = uA.head<3>();
  p.wA = uA.tail<3>();
  p.vB = uB.head<3>();
  p.wB = uB.tail<3>();
  const Vec5 total = accumulated + impulse;
  joint.linearImpulse = total(0) * tangents[0] + total(1) * tangents[1];
  joint.angularImpulse = total.tail<3>();
}

}  // namespace rbsim::joint_rows

#include "rbsim/dynamics/joint.h"

#include <cmath>

#include "rbsim/math/types.h"

namespace rbsim {

double hingeAngle(const Joint& joint, const Quat& base, const Quat& moving) {
  // The rotation, in the base's frame, from the pose the joint was added in to the pose now; its
  // twist about the axis is the angle (the swing off the axis is what the hinge holds at zero):
  // the swing-twist split of a quaternion, the 3D form of Box2D v3's b2RelativeAngle.
  const Quat d = base.conjugate() * moving * joint.referenceRotation.conjugate();
  double angle = 2.0 * std::atan2(d.vec().dot(joint.localAxisBase), d.w());
  if (angle > kPi) angle -= 2.0 * kPi;
  if (angle <= -kPi) angle += 2.0 * kPi;
  return angle;
}

Vec3 relativeRotation(const Joint& joint, const Quat& base, const Quat& moving) {
  // q_A (q_base q_ref)^-1 = q_base d q_base^-1 with d as in hingeAngle: d's rotation vector, taken
  // into world frame by the base. The short way round (w >= 0), so the angle is at most pi.
  Quat d = base.conjugate() * moving * joint.referenceRotation.conjugate();
  if (d.w() < 0.0) d.coeffs() = -d.coeffs();
  const double sine = d.vec().norm();
  // Below sin(angle / 2) ~ 1e-8 the log is 2 v to double precision (the next term is v^3 / 3).
  constexpr double kSmallHalfAngle = 1e-8;  // [1]
  const Vec3 local = sine < kSmallHalfAngle ? Vec3(2.0 * d.vec()) : Vec3(d.vec() * (2.0 * std::atan2(sine, d.w()) / sine));
  return base * local;
}

double swingAngle(const Joint& joint, const Quat& base, const Quat& moving) {
  const Vec3 a = base * joint.localAxisBase, b = moving * joint.localAxisMoving;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace rbsim

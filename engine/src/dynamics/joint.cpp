#include "rbsim/dynamics/joint.h"

#include <cmath>

namespace rbsim {

double hingeAngle(const Joint& joint, const Quat& base, const Quat& moving) {
  // The rotation, in the base's frame, from the pose the joint was added in to the pose now; its
  // twist about the axis is the angle (the swing off the axis is what the hinge holds at zero):
  // the swing-twist split of a quaternion, the 3D form of Box2D v3's b2RelativeAngle.
  const Quat d = base.conjugate() * moving * joint.referenceRotation.conjugate();
  double angle = 2.0 * std::atan2(d.vec().dot(joint.localAxisBase), d.w());
  if (angle > M_PI) angle -= 2.0 * M_PI;
  if (angle <= -M_PI) angle += 2.0 * M_PI;
  return angle;
}

}  // namespace rbsim

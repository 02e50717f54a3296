#include "rbsim/math/rotation.h"

#include <cmath>

namespace rbsim {

Mat3 star(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(),
       a.z(), 0.0, -a.x(),
       -a.y(), a.x(), 0.0;
  return s;
}

Mat3 orthonormalize(const Mat3& R) {
  Vec3 cx = R.col(0).normalized();
  Vec3 cy = R.col(2).cross(cx).normalized();
  Vec3 cz = cx.cross(cy).normalized();
  Mat3 out;
  out.col(0) = cx;
  out.col(1) = cy;
  out.col(2) = cz;
  return out;
}

Mat3 rotationFromAxisAngle(const Vec3& axisAngle) {
  return quatFromAxisAngle(axisAngle).toRotationMatrix();
}

Quat quatFromAxisAngle(const Vec3& axisAngle) {
  const double angle = axisAngle.norm();
  if (angle == 0.0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(angle, axisAngle / angle));
}

double rotationAngleBetween(const Mat3& A, const Mat3& B) {
  // For D = A^T B: trace(D) = 1 + 2 cos(angle) and |skew(D)| = sin(angle). atan2 of the pair
  // keeps full precision near 0 and pi, where acos of the trace alone loses half the digits.
  const Mat3 D = A.transpose() * B;
  const double c = 0.5 * (D.trace() - 1.0);
  const double s = 0.5 * Vec3(D(2, 1) - D(1, 2), D(0, 2) - D(2, 0), D(1, 0) - D(0, 1)).norm();
  return std::atan2(s, c);
}

double orthonormalityError(const Mat3& R) {
  return (R.transpose() * R - Mat3::Identity()).norm();
}

}  // namespace rbsim

#include "rbsim/math/rotation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace rbsim {

namespace {
// Below this cos(pitch) [1] yaw and roll turn about one axis (gimbal lock) and only their
// difference is defined; atan2 of the rounding left in the other entries would be noise.
constexpr double kGimbalLockCosine = 1e-12;
}  // namespace

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

Quat quatFromEulerZyx(const Vec3& yawPitchRoll) {
  const Quat yaw(Eigen::AngleAxisd(yawPitchRoll.x(), Vec3::UnitZ()));
  const Quat pitch(Eigen::AngleAxisd(yawPitchRoll.y(), Vec3::UnitY()));
  const Quat roll(Eigen::AngleAxisd(yawPitchRoll.z(), Vec3::UnitX()));
  return (yaw * pitch * roll).normalized();
}

Vec3 eulerZyxFromRotation(const Mat3& R) {
  // R = Rz(psi) Ry(theta) Rx(phi): R(2,0) = -sin(theta), R(2,1) = cos(theta) sin(phi),
  // R(2,2) = cos(theta) cos(phi), R(1,0) = sin(psi) cos(theta), R(0,0) = cos(psi) cos(theta).
  const double sinPitch = std::clamp(-R(2, 0), -1.0, 1.0);
  const double cosPitch = std::hypot(R(0, 0), R(1, 0));
  const double pitch = std::atan2(sinPitch, cosPitch);
  if (cosPitch > kGimbalLockCosine) {
    return {std::atan2(R(1, 0), R(0, 0)), pitch, std::atan2(R(2, 1), R(2, 2))};
  }
  // Gimbal lock: R(0,1) = -sin(psi -+ phi) etc.; phi = 0 leaves psi from the first two columns.
  return {std::atan2(-R(0, 1), R(1, 1)), pitch, 0.0};
}

double orthonormalityError(const Mat3& R) {
  return (R.transpose() * R - Mat3::Identity()).norm();
}

}  // namespace rbsim

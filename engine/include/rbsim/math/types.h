#pragma once
// Vector and matrix aliases over Eigen: all engine maths is in double precision, SI units.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

namespace rbsim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // unit quaternion (w, x, y, z); Eigen stores x, y, z, w

}  // namespace rbsim

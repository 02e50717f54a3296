#pragma once
// Vector and matrix aliases over Eigen: all engine maths is in double precision, SI units.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

namespace rbsim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // unit quaternion (w, x, y, z); Eigen stores x, y, z, w

inline constexpr double kPi = 3.14159265358979323846;  // [rad] the half turn; C++17 has no std::numbers::pi, and M_PI is POSIX, not standard C++
// A direction given as unit (a normalised input) is accepted when its length is within this of 1,
// the rounding a normalisation leaves. [1]
inline constexpr double kUnitTolerance = 1e-9;

}  // namespace rbsim

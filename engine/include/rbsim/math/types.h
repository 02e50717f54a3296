#pragma once
// Vector and matrix aliases over Eigen: all engine maths is in double precision, SI units.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

namespace rbsim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // unit quaternion (w, x, y, z); Eigen stores x, y, z, w

// The layout the hot structs' sizes are stated for (each asserts its size in bytes and cache lines
// beside its definition, docs/architecture.md "Hot structs"): 64-bit pointers and Eigen's 16-byte
// aligned quaternion, as on x86-64 (SSE2) and arm64 (NEON). Elsewhere the same code builds with
// other sizes, unchecked: WebAssembly (issue 59) has 4-byte pointers, and Eigen 3.4 does not
// vectorise there, so a quaternion is 8-byte aligned and BodyState 104 bytes, not 112.
inline constexpr bool kStatedLayout = sizeof(void*) == 8 && alignof(Quat) == 16;

inline constexpr double kPi = 3.14159265358979323846;  // [rad] the half turn; C++17 has no std::numbers::pi, and M_PI is POSIX, not standard C++
// A direction given as unit (a normalised input) is accepted when its length is within this of 1,
// the rounding a normalisation leaves. [1]
inline constexpr double kUnitTolerance = 1e-9;

}  // namespace rbsim

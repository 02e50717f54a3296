#pragma once
// Rotation helpers shared by the integrators, the scene loader and the tests.
#include "rbsim/math/types.h"

namespace rbsim {

// The star (cross-product) matrix: star(a) * b == a.cross(b) (seed 004 "RB rotational update",
// seed 000 "angular velocity").
Mat3 star(const Vec3& a);

// The world-frame form R T R^T of a body-frame tensor T, as I^-1(t) = R I_body^-1 R^T (seed 004).
// RigidBody derives omega = I^-1(t) L with it and symplectic-euler reuses that omega, so both
// evaluate it here, alike to the bit.
inline Mat3 toWorldFrame(const Mat3& R, const Mat3& bodyTensor) {
  // Assigned, not constructed: Eigen evaluates `M = A * B * C` through a temporary, summing in
  // another order than `Mat3 M = A * B * C`; this is the order the simulator has always used.
  Mat3 world;
  world = R * bodyTensor * R.transpose();
  return world;
}

// Drift correction of seed 004 ("Drift correction"): normalise C_x, C_y = C_z x C_x normalised,
// C_z = C_x x C_y normalised, on the columns of R. Returns a proper rotation when R is near one.
Mat3 orthonormalize(const Mat3& R);

// The rotation of angle |axisAngle| about axisAngle's direction (Rodrigues' formula); the
// identity for a zero vector.
Mat3 rotationFromAxisAngle(const Vec3& axisAngle);
Quat quatFromAxisAngle(const Vec3& axisAngle);

// Euler angles (seed 000 lists them among the orientation choices), one convention, stated:
// yaw psi about z, then pitch theta about the new y, then roll phi about the newest x (intrinsic
// z-y'-x'', the aerospace "ZYX" angles), R = Rz(psi) Ry(theta) Rx(phi); angles [rad] as
// (psi, theta, phi). From a rotation: theta in [-pi/2, pi/2], psi and phi in (-pi, pi]; at
// theta = +-pi/2 (gimbal lock) only psi -+ phi is defined, and phi is taken as 0.
Quat quatFromEulerZyx(const Vec3& yawPitchRoll);
Vec3 eulerZyxFromRotation(const Mat3& R);

// Angle [rad] of the relative rotation A^T B, in [0, pi]: the orientation error used by tests.
double rotationAngleBetween(const Mat3& A, const Mat3& B);

// Frobenius norm of R^T R - I: how far a matrix is from orthonormal.
double orthonormalityError(const Mat3& R);

}  // namespace rbsim

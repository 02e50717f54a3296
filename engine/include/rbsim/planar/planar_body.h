#pragma once
// Rigid bodies in 2D, seed 002 section 2: position x and angle theta, R = [[cos, -sin], [sin, cos]];
// velocity v = P / m and the scalar angular velocity omega = theta' = L / I, with the scalar
// inertia I = sum m_i r_i . r_i about the centre of mass; the torque of a force f at x + r is the
// scalar tau = r x f = r_x f_y - r_y f_x. It is the 3D formulation restricted to the xy plane
// (omega = (0, 0, omega), L = (0, 0, L), I = I_33), which the tests check against the 3D engine.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "rbsim/dynamics/impulse.h"
#include "rbsim/body/material.h"

namespace rbsim {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// The 2D cross product r x f, the z component of the 3D one.
inline double cross2(const Vec2& r, const Vec2& f) { return r.x() * f.y() - r.y() * f.x(); }
// omega x r for omega along z: (-omega r_y, omega r_x).
inline Vec2 cross2(double omega, const Vec2& r) { return Vec2(-omega * r.y(), omega * r.x()); }
inline Mat2 rotation2(double theta) {
  Mat2 R;
  R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return R;
}

struct PlanarState {
  Vec2 position = Vec2::Zero();        // x, centre of mass [m]
  double angle = 0.0;                  // theta [rad]
  Vec2 linearMomentum = Vec2::Zero();  // P [kg m/s]
  double angularMomentum = 0.0;        // L = I omega [kg m^2/s]
};

// A convex polygon of uniform density: its mass properties, its state and the forces on it.
class PlanarBody {
 public:
  // `polygon`: counter-clockwise corners in the body frame (any origin; the body is re-centred on
  // its centroid). Throws std::invalid_argument for fewer than 3 corners, zero or negative
  // area, or a non-positive mass.
  PlanarBody(std::string name, std::vector<Vec2> polygon, double mass, const Material& material = {});

  const std::string& name() const { return name_; }
  double mass() const { return mass_; }
  double inertia() const { return inertia_; }  // about the centre of mass [kg m^2]
  const std::vector<Vec2>& polygon() const { return polygon_; }  // about the centre of mass
  const Material& material() const { return material_; }
  PlanarState& state() { return state_; }
  const PlanarState& state() const { return state_; }
  Vec2 velocity() const { return state_.linearMomentum / mass_; }
  double angularVelocity() const { return state_.angularMomentum / inertia_; }
  Vec2 corner(std::size_t i) const { return state_.position + rotation2(state_.angle) * polygon_[i]; }
  Vec2 pointVelocity(const Vec2& worldPoint) const {  // v + omega x r
    return velocity() + cross2(angularVelocity(), Vec2(worldPoint - state_.position));
  }
  double kineticEnergy() const;

  void applyForceAtPoint(const Vec2& force, const Vec2& worldPoint);  // F += f, tau += r x f
  // Semi-implicit Euler: P and L from the forces and gravity, then x and theta with the new v
  // and omega (theta advances exactly for a constant omega). Clears the forces.
  void step(double dt, const Vec2& gravity);
  // An impulse j at a world point: P += j, L += r x j (seed 002 2.2).
  void applyImpulse(const Vec2& impulse, const Vec2& worldPoint);

 private:
  std::string name_;
  std::vector<Vec2> polygon_;
  double mass_;
  double inertia_ = 0.0;
  Material material_;
  PlanarState state_;
  Vec2 force_ = Vec2::Zero();
  double torque_ = 0.0;
};

// The 2D impulse factor: the velocity change of the point at r per unit impulse there,
// K = (1/m) 1 + (1/I) r_perp r_perp^T with r_perp = (-r_y, r_x) (seed 002: the 6x6 K is 3x3 in
// 2D with the angular impulse; this is its point-impulse block). Static bodies give K = 0.
Mat2 planarImpulseFactor(double inverseMass, double inverseInertia, const Vec2& r);

// Seed 000's collision impulse in 2D: collisionImpulse<2> of dynamics/impulse.h, the same
// algorithm as in 3D (nothing unless u_rel . N < 0; the sticking impulse if it lies in the mu_s
// cone, otherwise the kinetic impulse (N - mu_k T) j_n).
using PlanarImpulse = CollisionImpulseIn<2>;

}  // namespace rbsim

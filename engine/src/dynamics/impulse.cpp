#include "rbsim/dynamics/impulse.h"

#include "rbsim/math/rotation.h"

namespace rbsim {

Mat3 impulseFactor(double inverseMass, const Mat3& inverseInertiaWorld, const Vec3& r) {
  const Mat3 rStar = star(r);
  return inverseMass * Mat3::Identity() + rStar.transpose() * inverseInertiaWorld * rStar;
}

Mat6 coupledImpulseFactor(double inverseMass, const Mat3& inverseInertiaWorld, const Vec3& r) {
  // K = A^T diag(1/m, I^-1) A with A = [[1, 0], [r*, 1]] (seed 002 eq. for K).
  const Mat3 rStar = star(r);
  Mat6 k;
  k.topLeftCorner<3, 3>() = impulseFactor(inverseMass, inverseInertiaWorld, r);
  k.topRightCorner<3, 3>() = rStar.transpose() * inverseInertiaWorld;
  k.bottomLeftCorner<3, 3>() = inverseInertiaWorld * rStar;
  k.bottomRightCorner<3, 3>() = inverseInertiaWorld;
  return k;
}

Mat3 frictionImpulseFactor(double inverseMass, const Mat3& inverseInertiaWorld, const Vec3& r, const Vec3& t1,
                           const Vec3& t2, const Vec3& n) {
  // The angular impulse of each coordinate: r x t1, r x t2 (a force at r) and n (a pure torque).
  Mat3 angular;
  angular << r.cross(t1), r.cross(t2), n;
  Mat3 k = angular.transpose() * inverseInertiaWorld * angular;
  k.topLeftCorner<2, 2>() += inverseMass * Eigen::Matrix2d::Identity();  // t1, t2 orthonormal
  return k;
}

template <int Dim>
CollisionImpulseIn<Dim> collisionImpulse(const Eigen::Matrix<double, Dim, Dim>& totalFactor,
                                         const ImpulseVector<Dim>& relativeVelocity, const ImpulseVector<Dim>& normal,
                                         const Material& material) {
  using Vector = Eigen::Matrix<double, Dim, 1>;
  CollisionImpulseIn<Dim> out;
  const double normalVelocity = relativeVelocity.dot(normal);
  if (!(normalVelocity < 0.0)) return out;  // separating or resting: no collision impulse
  out.colliding = true;
  const double restitution = material.restitution;

  // Sticking: u_rel^new = -c_R u_rel,N N, solved for the full impulse.
  const Vector sticking = totalFactor.ldlt().solve(Vector(-restitution * normalVelocity * normal - relativeVelocity));
  const double stickingNormal = sticking.dot(normal);
  if ((sticking - stickingNormal * normal).norm() <= material.staticFriction * stickingNormal) {
    out.impulse = sticking;
    out.sticking = true;
    return out;
  }

  // Kinetic friction along T, the direction of the tangential relative velocity. When there is
  // none (the sticking impulse left the cone through the coupling in K_T alone), friction opposes
  // the tangential part of the sticking impulse's direction instead.
  Vector tangential = relativeVelocity - normalVelocity * normal;
  if (tangential.norm() == 0.0) tangential = -(sticking - stickingNormal * normal);
  const Vector direction = tangential.norm() > 0.0 ? Vector(tangential.normalized()) : Vector(Vector::Zero());
  const Vector axis = normal - material.kineticFriction * direction;
  const double denominator = normal.dot(totalFactor * axis);
  // N^T K_T (N - mu_k T) <= 0 happens only for mu_k large against a strongly coupled K_T (the
  // Painleve configurations); there the kinetic formula has no repulsive solution, and the
  // frictionless impulse is the one that still satisfies the normal condition.
  const Vector used = denominator > 0.0 ? axis : normal;
  const double normalMagnitude = -(1.0 + restitution) * normalVelocity / normal.dot(totalFactor * used);
  out.impulse = normalMagnitude * used;
  return out;
}

template CollisionImpulseIn<2> collisionImpulse<2>(const Eigen::Matrix2d&, const ImpulseVector<2>&, const ImpulseVector<2>&,
                                                   const Material&);
template CollisionImpulseIn<3> collisionImpulse<3>(const Eigen::Matrix3d&, const ImpulseVector<3>&, const ImpulseVector<3>&,
                                                   const Material&);

}  // namespace rbsim

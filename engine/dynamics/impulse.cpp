#include "dynamics/impulse.h"

#include "math/rotation.h"

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

CollisionImpulse collisionImpulse(const Mat3& totalFactor, const Vec3& relativeVelocity, const Vec3& normal,
                                  const Material& material) {
  CollisionImpulse out;
  const double normalVelocity = relativeVelocity.dot(normal);
  if (!(normalVelocity < 0.0)) return out;  // separating or resting: no collision impulse
  out.colliding = true;
  const double restitution = material.restitution;

  // Sticking: u_rel^new = -c_R u_rel,N N, solved for the full 3D impulse.
  const Vec3 sticking = totalFactor.ldlt().solve(-restitution * normalVelocity * normal - relativeVelocity);
  const double stickingNormal = sticking.dot(normal);
  if ((sticking - stickingNormal * normal).norm() <= material.staticFriction * stickingNormal) {
    out.impulse = sticking;
    out.sticking = true;
    return out;
  }

  // Kinetic friction along T, the direction of the tangential relative velocity. When there is
  // none (the sticking impulse left the cone through the coupling in K_T alone), friction opposes
  // the tangential part of the sticking impulse's direction instead.
  Vec3 tangential = relativeVelocity - normalVelocity * normal;
  if (tangential.norm() == 0.0) tangential = -(sticking - stickingNormal * normal);
  const Vec3 direction = tangential.norm() > 0.0 ? Vec3(tangential.normalized()) : Vec3::Zero();
  const Vec3 axis = normal - material.kineticFriction * direction;
  const double denominator = normal.dot(totalFactor * axis);
  // N^T K_T (N - mu_k T) <= 0 happens only for mu_k large against a strongly coupled K_T (the
  // Painleve configurations); there the kinetic formula has no repulsive solution, and the
  // frictionless impulse is the one that still satisfies the normal condition.
  const Vec3 used = denominator > 0.0 ? axis : normal;
  const double normalMagnitude = -(1.0 + restitution) * normalVelocity / normal.dot(totalFactor * used);
  out.impulse = normalMagnitude * used;
  return out;
}

}  // namespace rbsim

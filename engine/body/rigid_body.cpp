#include "body/rigid_body.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "math/rotation.h"

namespace rbsim {

RigidBody::RigidBody(const BodyDef& def)
    : name_(def.name), mesh_(def.mesh), mass_(def.mass), inertiaBody_(def.inertiaBody),
      color_(def.color) {
  if (!mesh_) throw std::invalid_argument("body '" + name_ + "': no mesh");
  if (!(mass_ > 0.0) || !std::isfinite(mass_)) {
    throw std::invalid_argument("body '" + name_ + "': mass must be a positive finite number");
  }
  // A physical inertia tensor is symmetric positive definite; anything else cannot be inverted
  // meaningfully, so it is rejected here rather than producing NaN angular velocities later.
  Eigen::SelfAdjointEigenSolver<Mat3> eig(inertiaBody_);
  if (!inertiaBody_.allFinite() || (inertiaBody_ - inertiaBody_.transpose()).norm() > 1e-9 * inertiaBody_.norm() ||
      !(eig.eigenvalues().minCoeff() > 0.0)) {
    throw std::invalid_argument("body '" + name_ + "': inertia tensor must be symmetric positive definite");
  }
  principalMoments_ = eig.eigenvalues();
  principalAxes_ = eig.eigenvectors();
  if (principalAxes_.determinant() < 0.0) principalAxes_.col(2) *= -1.0;  // a rotation, not a reflection
  inverseMass_ = 1.0 / mass_;
  inverseInertiaBody_ = inertiaBody_.inverse();
  worldVertices_.resize(mesh_->vertices.size());
  state_.position = def.position;
  setOrientation(def.orientation);  // validates and derives
  state_.linearMomentum = mass_ * def.velocity;
  state_.angularMomentum = inertiaWorld() * def.angularVelocity;
  updateDerived();
}

void RigidBody::setState(const BodyState& state) {
  state_ = state;
  updateDerived();
}

void RigidBody::setPosition(const Vec3& x) {
  state_.position = x;
  wake();
  updateDerived();
}

void RigidBody::setOrientation(const Mat3& R) {
  if (!R.allFinite() || orthonormalityError(R) > kRotationTolerance || R.determinant() < 0.0) {
    throw std::invalid_argument("body '" + name_ + "': orientation matrix is not a rotation");
  }
  // Angular momentum is a world-frame quantity: turning the body by hand keeps L, so omega
  // changes with the world inertia, exactly as for an instantaneous re-pose of a real body.
  state_.orientation = Quat(R).normalized();
  wake();
  updateDerived();
}

void RigidBody::setOrientation(const Quat& q) {
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > kRotationTolerance) {
    throw std::invalid_argument("body '" + name_ + "': orientation quaternion is not unit length");
  }
  state_.orientation = q.normalized();
  wake();
  updateDerived();
}

void RigidBody::setVelocity(const Vec3& v) {
  state_.linearMomentum = mass_ * v;
  wake();
  updateDerived();
}

void RigidBody::setAngularVelocity(const Vec3& omega) {
  state_.angularMomentum = inertiaWorld() * omega;
  wake();
  updateDerived();
}

Mat3 RigidBody::inertiaWorld() const {
  return rotation_ * inertiaBody_ * rotation_.transpose();
}

double RigidBody::kineticEnergy() const {
  return 0.5 * (state_.linearMomentum.dot(velocity_) + state_.angularMomentum.dot(angularVelocity_));
}

void RigidBody::applyForce(const Vec3& force) { force_ += force; }

void RigidBody::applyForceAtPoint(const Vec3& force, const Vec3& worldPoint) {
  force_ += force;
  torque_ += (worldPoint - state_.position).cross(force);  // seed 004: tau_i = (p_i - x) x f_i
}

void RigidBody::applyTorque(const Vec3& torque) { torque_ += torque; }

void RigidBody::clearAccumulators() {
  force_.setZero();
  torque_.setZero();
}

void RigidBody::wake() {
  awake_ = true;
  restingTime_ = 0.0;
}

void RigidBody::sleep() {
  awake_ = false;
  state_.linearMomentum.setZero();
  state_.angularMomentum.setZero();
  updateDerived();
}

void RigidBody::updateDerived() {
  rotation_ = state_.orientation.toRotationMatrix();
  velocity_ = inverseMass_ * state_.linearMomentum;
  inverseInertiaWorld_ = rotation_ * inverseInertiaBody_ * rotation_.transpose();
  angularVelocity_ = inverseInertiaWorld_ * state_.angularMomentum;
  const std::vector<Vec3>& body = mesh_->vertices;
  for (std::size_t i = 0; i < body.size(); ++i) worldVertices_[i] = rotation_ * body[i] + state_.position;
}

}  // namespace rbsim

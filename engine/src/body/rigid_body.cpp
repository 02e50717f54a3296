#include "rbsim/body/rigid_body.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "rbsim/math/rotation.h"

namespace rbsim {

namespace {

// A compound's children: each convex or round (a grid body is one body of its own), posed by a
// rotation, with a display mesh, and few enough to name a pair of them in a contact key.
void checkChildren(const BodyDef& def) {
  if (def.children.size() > static_cast<std::size_t>(kMaxCompoundChildren)) {
    throw std::invalid_argument("body '" + def.name + "': " + std::to_string(def.children.size()) +
                                " shapes; expected at most " + std::to_string(kMaxCompoundChildren));
  }
  if (!def.children.empty() && (def.sdf || def.implicit || def.fracture)) {
    throw std::invalid_argument("body '" + def.name + "': a compound body cannot have a grid, an implicit solid or a fracture pattern");
  }
  for (std::size_t i = 0; i < def.children.size(); ++i) {
    const ChildShape& c = def.children[i];
    const std::string where = "body '" + def.name + "', shape " + std::to_string(i) + ": ";
    if (c.shape.type == ShapeType::Mesh) throw std::invalid_argument(where + "a non-convex mesh cannot be a compound's part");
    if (!c.mesh) throw std::invalid_argument(where + "no display mesh");
    if (!c.position.allFinite()) throw std::invalid_argument(where + "position must be finite");
    if (!(std::abs(c.orientation.norm() - 1.0) <= kRotationTolerance)) {
      throw std::invalid_argument(where + "orientation must be a unit quaternion");
    }
    const std::string material = checkMaterial(c.material);
    if (!material.empty()) throw std::invalid_argument(where + material);
  }
}

}  // namespace

RigidBody::RigidBody(const BodyDef& def) : isStatic_(def.isStatic), isKinematic_(def.isKinematic), mass_(def.mass) {
  if (def.isStatic && def.isKinematic) {
    throw std::invalid_argument("body '" + def.name + "': static and kinematic at once; expected one");
  }
  auto cold = std::make_shared<ColdConstants>();
  cold->name = def.name;
  cold->mesh = def.mesh;
  cold->fileFrame = def.fileFrame;
  if (def.fileFrame.mesh && def.fileFrame.mesh->vertices.size() != def.mesh->vertices.size()) {
    throw std::invalid_argument("body '" + def.name + "': its file mesh and its mesh differ in vertex count");
  }
  const std::string& name = cold->name;
  if (!cold->mesh) throw std::invalid_argument("body '" + name + "': no mesh");
  cold->shape = def.shape ? *def.shape : shapeOfMesh(*cold->mesh, def.sdf != nullptr);
  cold->filter = def.filter;
  checkChildren(def);
  cold->children = def.children;
  setMassConstants(def.mass, def.inertiaBody, *cold);
  inputs_.inertia = &cold->inertia;  // the block is never moved: copies of the body share it
  cold_ = std::move(cold);
  worldVertices_.resize(cold_->mesh->vertices.size());
  state_.position = def.position;
  setOrientation(def.orientation);  // validates and derives
  state_.linearMomentum = mass_ * def.velocity;
  state_.angularMomentum = inertiaWorld() * def.angularVelocity;
  if (isStatic_) {
    if (!def.velocity.isZero(0.0) || !def.angularVelocity.isZero(0.0)) {
      throw std::invalid_argument("body '" + name + "': a static body cannot have a velocity");
    }
    awake_ = false;
  }
  updateDerived();
}

void RigidBody::setMassConstants(double mass, const Mat3& inertia, ColdConstants& cold) {
  const std::string& name = cold.name;
  if (!(mass > 0.0) || !std::isfinite(mass)) {
    throw std::invalid_argument("body '" + name + "': mass must be a positive finite number");
  }
  // A physical inertia tensor is symmetric positive definite; anything else cannot be inverted
  // meaningfully, so it is rejected here rather than producing NaN angular velocities later.
  Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  if (!inertia.allFinite() || (inertia - inertia.transpose()).norm() > 1e-9 * inertia.norm() ||
      !(eig.eigenvalues().minCoeff() > 0.0)) {
    throw std::invalid_argument("body '" + name + "': inertia tensor must be symmetric positive definite");
  }
  Mat3 axes = eig.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) *= -1.0;  // a rotation, not a reflection
  // Inverted in the principal frame, A diag(1/lambda) A^T, not by cofactors: the determinant
  // lambda^3 under- or overflows for moments beyond about 1e-103 or 1e103 kg m^2 (a 1 m box of
  // 1e-102 kg), while each 1/lambda stays exact wherever it is a finite number.
  const Mat3 inverse = axes * eig.eigenvalues().cwiseInverse().asDiagonal() * axes.transpose();
  if (!inverse.allFinite() || !std::isfinite(1.0 / mass)) {
    throw std::invalid_argument("body '" + name + "': the inverse of its mass or inertia overflows a double");
  }
  cold.inertia.inertiaBody = inertia;
  cold.inertia.principalMoments = eig.eigenvalues();
  cold.inertia.principalAxes = axes;
  mass_ = mass;
  inputs_.inverseMass = 1.0 / mass;
  inputs_.inverseInertiaBody = inverse;
}

void RigidBody::setMassProperties(double mass, const Mat3& inertiaBody) {
  // The constants are shared with the body's copies (a saved World): this body takes its own.
  auto cold = std::make_shared<ColdConstants>(*cold_);
  const Vec3 v = velocity(), omega = angularVelocity();
  setMassConstants(mass, inertiaBody, *cold);  // throws before it changes anything
  inputs_.inertia = &cold->inertia;
  cold_ = std::move(cold);
  // The motion stays and the momenta follow (P = m v, L = I(t) omega), as Box2D's
  // b2Body_SetMassData, Jolt's SetMassProperties and Bullet keep velocities.
  state_.linearMomentum = mass_ * v;
  state_.angularMomentum = inertiaWorld() * omega;
  // exact and exact4's kept flow restarts by itself: L (or the moments) differ from its own.
  wake();
  updateDerived();
}

void RigidBody::setFilter(const CollisionFilter& filter) {
  auto cold = std::make_shared<ColdConstants>(*cold_);
  cold->filter = filter;
  inputs_.inertia = &cold->inertia;
  cold_ = std::move(cold);
  wake();
}

void RigidBody::setState(const BodyState& state) {
  state_ = state;
  updateDerived();
}

void RigidBody::setState(const BodyState& state, const Mat3& rotation) {
  state_ = state;
  updateDerived();
  inputs_.rotation = rotation;
  inputs_.angularVelocity = inverseInertiaWorld() * state_.angularMomentum;
}

void RigidBody::setPosition(const Vec3& x) {
  state_.position = x;
  wake();
  updateDerived();
}

void RigidBody::setOrientation(const Mat3& R) {
  if (!R.allFinite() || orthonormalityError(R) > kRotationTolerance || R.determinant() < 0.0) {
    throw std::invalid_argument("body '" + name() + "': orientation matrix is not a rotation");
  }
  // Angular momentum is a world-frame quantity: turning the body by hand keeps L, so omega
  // changes with the world inertia, exactly as for an instantaneous re-pose of a real body.
  state_.orientation = Quat(R).normalized();
  wake();
  updateDerived();
}

void RigidBody::setOrientation(const Quat& q) {
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > kRotationTolerance) {
    throw std::invalid_argument("body '" + name() + "': orientation quaternion is not unit length");
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

Mat3 RigidBody::inverseInertiaWorld() const { return toWorldFrame(inputs_.rotation, inputs_.inverseInertiaBody); }

Mat3 RigidBody::inertiaWorld() const {
  return inputs_.rotation * cold_->inertia.inertiaBody * inputs_.rotation.transpose();
}

double RigidBody::kineticEnergy() const {
  return 0.5 * (state_.linearMomentum.dot(inputs_.velocity) + state_.angularMomentum.dot(inputs_.angularVelocity));
}

void RigidBody::applyForce(const Vec3& force) { inputs_.force += force; }

void RigidBody::applyForceAtPoint(const Vec3& force, const Vec3& worldPoint) {
  inputs_.force += force;
  inputs_.torque += (worldPoint - state_.position).cross(force);  // seed 004: tau_i = (p_i - x) x f_i
}

void RigidBody::applyTorque(const Vec3& torque) { inputs_.torque += torque; }

void RigidBody::applyBodyTorque(const Vec3& torque) { inputs_.bodyTorque += torque; }

void RigidBody::clearAccumulators() {
  inputs_.force.setZero();
  inputs_.torque.setZero();
  inputs_.bodyTorque.setZero();
}

void RigidBody::wake() {
  if (isStatic_) return;
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
  inputs_.rotation = state_.orientation.toRotationMatrix();
  inputs_.velocity = inputs_.inverseMass * state_.linearMomentum;
  inputs_.angularVelocity = inverseInertiaWorld() * state_.angularMomentum;
  worldVerticesStale_ = true;
}

// Every member but the vertex cache: one added to RigidBody must be added here (and the size).
static_assert(!kStatedLayout || sizeof(RigidBody) == 512, "a new member of RigidBody: copy it in RigidBody(const RigidBody&)");
RigidBody::RigidBody(const RigidBody& other)
    : awake_(other.awake_),
      isStatic_(other.isStatic_),
      isKinematic_(other.isKinematic_),
      worldVerticesStale_(true),
      mass_(other.mass_),
      state_(other.state_),
      inputs_(other.inputs_),
      restingTime_(other.restingTime_),
      cold_(other.cold_),
      freeFlow_(other.freeFlow_) {}

RigidBody& RigidBody::operator=(const RigidBody& other) {
  if (this != &other) {
    std::vector<Vec3> cache = std::move(worldVertices_);  // this body's storage, reused
    *this = RigidBody(other);
    worldVertices_ = std::move(cache);
    worldVerticesStale_ = true;
  }
  return *this;
}

void RigidBody::updateWorldVertices() const {
  // R, x and the vertex arrays are copied to locals: stores into worldVertices_ might alias any
  // member as far as the compiler can tell, and it would reload them all for every vertex.
  const Mat3 R = inputs_.rotation;
  const Vec3 x = state_.position;
  const Vec3* body = cold_->mesh->vertices.data();
  worldVertices_.resize(cold_->mesh->vertices.size());  // a copy starts without them
  Vec3* world = worldVertices_.data();
  const std::size_t count = worldVertices_.size();
  for (std::size_t i = 0; i < count; ++i) world[i] = R * body[i] + x;
  worldVerticesStale_ = false;
}

}  // namespace rbsim

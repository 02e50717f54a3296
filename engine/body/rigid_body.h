#pragma once
// A rigid body: constants (m, I_body, I_body^-1, body-space vertices), state Y(t), the quantities
// derived from it (seed 004 "Rigid body representation"; seed 000 "auxiliary quantities"), and
// the force and torque accumulators (seed 004 "Force and torque").
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "body/body_def.h"
#include "body/body_state.h"
#include "geometry/mesh.h"
#include "integrate/integrator.h"

namespace rbsim {

class RigidBody {
 public:
  explicit RigidBody(const BodyDef& def);  // throws std::invalid_argument on an invalid def

  // Constants.
  const std::string& name() const { return name_; }
  const Mesh& mesh() const { return *mesh_; }
  double mass() const { return mass_; }
  const Mat3& inertiaBody() const { return inputs_.inertiaBody; }
  const Mat3& inverseInertiaBody() const { return inputs_.inverseInertiaBody; }
  const Vec3& color() const { return color_; }
  bool isStatic() const { return isStatic_; }  // never moves, never awake (BodyDef::isStatic)
  const std::optional<Vec3>& boxHalfExtents() const { return boxHalfExtents_; }

  // State Y(t).
  const BodyState& state() const { return state_; }
  void setState(const BodyState& state);  // the integrators' entry point; updates all derived

  // Manual set (seed 004 "TO DO: change x and R and redraw"): each updates every derived
  // quantity and every world vertex. Orientation must be a rotation (checked, never normalised).
  void setPosition(const Vec3& x);
  void setOrientation(const Mat3& R);
  void setOrientation(const Quat& q);
  void setVelocity(const Vec3& v);             // P = m v
  void setAngularVelocity(const Vec3& omega);  // L = I(t) omega

  // Derived quantities.
  const Vec3& position() const { return state_.position; }
  const Quat& orientation() const { return state_.orientation; }
  const Mat3& rotation() const { return inputs_.rotation; }  // R(t); its columns are the body axes
  const Vec3& velocity() const { return inputs_.velocity; }  // v = P / m
  const Vec3& angularVelocity() const { return inputs_.angularVelocity; }  // omega = I^-1 L
  const Mat3& inverseInertiaWorld() const { return inverseInertiaWorld_; }  // R I_body^-1 R^T
  Mat3 inertiaWorld() const;                          // R I_body R^T
  double kineticEnergy() const;                       // (P.v + L.omega) / 2 [J]

  // Transformed vertices p' = R p + x (seed 004 "you MUST have access to each individual vertex").
  std::size_t vertexCount() const { return worldVertices_.size(); }
  const Vec3& bodyVertex(std::size_t i) const { return mesh_->vertices[i]; }
  const Vec3& worldVertex(std::size_t i) const { return worldVertices_[i]; }
  const std::vector<Vec3>& worldVertices() const { return worldVertices_; }
  Vec3 bodyToWorld(const Vec3& p) const { return inputs_.rotation * p + state_.position; }

  // Accumulators, cleared by the World after each step.
  void applyForce(const Vec3& force);                          // at the centre of mass
  void applyForceAtPoint(const Vec3& force, const Vec3& worldPoint);  // tau += (p - x) x f
  void applyTorque(const Vec3& torque);
  const Vec3& force() const { return inputs_.force; }
  const Vec3& torque() const { return inputs_.torque; }
  void clearAccumulators();

  // Sleeping (World's UpdateSleep stage). A sleeping body has zero momenta and is not integrated.
  // Every manual set above wakes it; setState does not (it is the integrators' path).
  bool awake() const { return awake_; }
  double restingTime() const { return restingTime_; }  // [s] spent below the sleep speeds
  void setRestingTime(double seconds) { restingTime_ = seconds; }
  void wake();   // no effect on a static body
  void sleep();  // P = L = 0, so the state read back is the state the body keeps

  // Principal axes: I_body = E diag(principalMoments) E^T with E a rotation (det +1).
  const Vec3& principalMoments() const { return inputs_.principalMoments; }  // ascending [kg m^2]
  const Mat3& principalAxes() const { return inputs_.principalAxes; }        // E, columns in body frame

  // Everything an integrator step reads besides the state, kept together so World::step hands
  // it over in place.
  const StepInputs& stepInputs() const { return inputs_; }

 private:
  void updateDerived();

  // Hot: what World::step reads and writes, first and together, so that a step over many bodies
  // streams through few cache lines. The flags lead, so a pass that only tests awake_ touches one
  // line per body; the principal moments and axes, which only dlm reads, end StepInputs and so
  // come last, where the other integrators leave their lines alone.
  bool awake_ = true;
  bool isStatic_ = false;
  double restingTime_ = 0.0;
  double mass_ = 1.0;
  const Vec3* bodyVertices_ = nullptr;  // mesh_->vertices.data(): spares the step a hop through
                                        // the Mesh; a body's mesh never changes
  std::vector<Vec3> worldVertices_;
  BodyState state_;
  Mat3 inverseInertiaWorld_ = Mat3::Identity();
  StepInputs inputs_{Vec3::Zero(),     Vec3::Zero(),     Mat3::Identity(), Vec3::Zero(),
                     Vec3::Zero(),     1.0,              Mat3::Identity(), Mat3::Identity(),
                     Vec3::Ones(),     Mat3::Identity()};  // v, omega, R, F, tau, constants

  // Cold: never read by a step.
  std::string name_;
  std::shared_ptr<const Mesh> mesh_;
  Vec3 color_ = Vec3::Ones();
  std::optional<Vec3> boxHalfExtents_;
};

// Tolerance for accepting a matrix or quaternion as a rotation: ||R^T R - I||_F and | |q| - 1 |.
// Loose enough for values typed with 9 significant digits, tight enough to reject real errors.
inline constexpr double kRotationTolerance = 1e-6;

}  // namespace rbsim

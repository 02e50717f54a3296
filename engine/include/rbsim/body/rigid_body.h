#pragma once
// A rigid body: constants (m, I_body, I_body^-1, body-space vertices), state Y(t), the quantities
// derived from it (seed 004 "Rigid body representation"; seed 000 "auxiliary quantities"), and
// the force and torque accumulators (seed 004 "Force and torque").
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/integrate/body_state.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/integrate/integrator.h"

namespace rbsim {

// A RigidBody is laid out for World::step's pass over many bodies: the fields a step reads and
// writes fill its first 408 bytes, 7 of its 8 cache lines (see the members; 512 bytes, asserted
// below the class), the constants no step of the forward-Euler family reads live in a block of
// their own, and world vertices are computed only when asked for.
class alignas(64) RigidBody {
 public:
  explicit RigidBody(const BodyDef& def);  // throws std::invalid_argument on an invalid def
  // A copy leaves the transformed vertices behind (a cache, filled again on the copy's first
  // access): a World copied to undo a step that removes bodies copied 230 MB of them for 3,000
  // ragdolls, 0.24 s against the step's 0.4 s (issue 56).
  RigidBody(const RigidBody& other);
  RigidBody& operator=(const RigidBody& other);
  RigidBody(RigidBody&&) noexcept = default;
  RigidBody& operator=(RigidBody&&) noexcept = default;
  ~RigidBody() = default;

  // Constants.
  const std::string& name() const { return cold_->name; }
  const Mesh& mesh() const { return *cold_->mesh; }
  // The same mesh, shared by every body made from one template (a spawn block): its owner.
  const std::shared_ptr<const Mesh>& sharedMesh() const { return cold_->mesh; }
  double mass() const { return mass_; }
  const Mat3& inertiaBody() const { return cold_->inertia.inertiaBody; }
  const Mat3& inverseInertiaBody() const { return inputs_.inverseInertiaBody; }
  bool isStatic() const { return isStatic_; }  // never moves, never awake (BodyDef::isStatic)
  bool isKinematic() const { return isKinematic_; }  // moves as prescribed (BodyDef::isKinematic)
  bool isDynamic() const { return !isStatic_ && !isKinematic_; }  // moved by forces and contacts
  const Shape& shape() const { return cold_->shape; }  // collision shape, body frame
  const CollisionFilter& filter() const { return cold_->filter; }  // the shape's (BodyDef::filter)
  // A compound body's shapes (BodyDef::children); empty for a body of one shape.
  const std::vector<ChildShape>& children() const { return cold_->children; }
  bool isCompound() const { return !cold_->children.empty(); }

  // State Y(t).
  const BodyState& state() const { return state_; }
  void setState(const BodyState& state);  // the integrators' entry point; updates all derived
  // The state with R as given rather than R(q): euler-matrix without drift correction (Settings::
  // driftCorrection), whose matrix is no longer a rotation. I(t)^-1 = R I_body^-1 R^T, omega and
  // the world vertices then all use that R, as seed 004 computes them; q is R's nearest rotation.
  void setState(const BodyState& state, const Mat3& rotation);

  // Manual set (seed 004 "TO DO: change x and R and redraw"): each updates every derived
  // quantity and every world vertex. Orientation must be a rotation (checked, never normalised).
  void setPosition(const Vec3& x);
  void setOrientation(const Mat3& R);
  void setOrientation(const Quat& q);
  void setVelocity(const Vec3& v);             // P = m v
  void setAngularVelocity(const Vec3& omega);  // L = I(t) omega
  // A change of the constants (setBodyMass, setBodyFilter go through here). The velocity
  // and angular velocity stay, P = m v and L = I(t) omega follow (as Box2D's b2Body_SetMassData
  // and Jolt's SetMassProperties keep velocities); the inertia is about the centre of mass in the
  // body frame. Throws std::invalid_argument, changing nothing, as the constructor would.
  void setMassProperties(double mass, const Mat3& inertiaBody);
  void setFilter(const CollisionFilter& filter);

  // Derived quantities.
  const Vec3& position() const { return state_.position; }
  const Quat& orientation() const { return state_.orientation; }
  const Mat3& rotation() const { return inputs_.rotation; }  // R(t); its columns are the body axes
  const Vec3& velocity() const { return inputs_.velocity; }  // v = P / m
  const Vec3& angularVelocity() const { return inputs_.angularVelocity; }  // omega = I^-1 L
  Mat3 inverseInertiaWorld() const;                   // R I_body^-1 R^T, computed on each call
  Mat3 inertiaWorld() const;                          // R I_body R^T
  double kineticEnergy() const;                       // (P.v + L.omega) / 2 [J]

  // Transformed vertices p' = R p + x (seed 004 "you MUST have access to each individual vertex").
  // Computed on the first access after the pose changed, not by every step: a step over bodies
  // nobody looks at (free flight, collisions off) need not rewrite them. The storage stays where
  // it is for the body's life, but a reference kept across a pose change shows the new pose only
  // once worldVertex() or worldVertices() has been called again: read through them.
  std::size_t vertexCount() const { return cold_->mesh->vertices.size(); }
  const Vec3& bodyVertex(std::size_t i) const { return cold_->mesh->vertices[i]; }
  // The same vertex in the coordinates of the file (or program) the body came from, exactly as
  // given there, and where the body frame sits in them (seed 000's diagonalisation).
  Vec3 fileVertex(std::size_t i) const {
    const FileFrame& f = cold_->fileFrame;
    return f.mesh ? f.mesh->vertices[i] : Vec3(f.axes * cold_->mesh->vertices[i] + f.centre);
  }
  const FileFrame& fileFrame() const { return cold_->fileFrame; }
  const Vec3& worldVertex(std::size_t i) const { return worldVertices()[i]; }
  const std::vector<Vec3>& worldVertices() const {
    if (worldVerticesStale_) updateWorldVertices();
    return worldVertices_;
  }
  Vec3 bodyToWorld(const Vec3& p) const { return inputs_.rotation * p + state_.position; }

  // Accumulators, cleared by the World after each step.
  void applyForce(const Vec3& force);                          // at the centre of mass
  void applyForceAtPoint(const Vec3& force, const Vec3& worldPoint);  // tau += (p - x) x f
  void applyTorque(const Vec3& torque);
  // A torque fixed in the body (body frame) [N m]: the splitting integrators turn it with the body
  // within a step; to the others it is R tau_body at the step's start.
  void applyBodyTorque(const Vec3& torque);
  const Vec3& bodyTorque() const { return inputs_.bodyTorque; }
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
  const Vec3& principalMoments() const { return cold_->inertia.principalMoments; }  // ascending [kg m^2]
  const Mat3& principalAxes() const { return cold_->inertia.principalAxes; }        // E, columns in body frame

  // Everything an integrator step reads besides the state, kept together so World::step hands
  // it over in place.
  const StepInputs& stepInputs() const { return inputs_; }
  // What exact and exact4 keep between this body's steps (integrator.h), made when first asked for.
  FreeFlowMemo& freeFlowMemo() { return freeFlow_.get(); }
  const FreeFlowMemo* freeFlowMemoIfMade() const { return freeFlow_.find(); }  // null: none yet

  // Starts fetching the lines a step reads and writes (engine/src/body/step_prefetch.h): the
  // compiler's prefetch stays out of the public headers, and inline in World's Integrate pass.
  friend struct StepPrefetch;

 private:
  static constexpr std::size_t kCacheLineBytes = 64;  // x86-64 and most ARM cores

  // Constants no step of the forward-Euler family reads; copies of a body share them, so a change
  // (setMassProperties, setFilter) gives the body a block of its own.
  struct ColdConstants {
    std::string name;
    std::shared_ptr<const Mesh> mesh;
    Shape shape;
    CollisionFilter filter;
    std::vector<ChildShape> children;
    FileFrame fileFrame;
    BodyInertia inertia;  // what implicit-gyro and dlm read besides StepInputs' own fields
  };

  // Checks m and I_body and sets mass_, the inverses and cold's inertia; throws before it changes anything.
  void setMassConstants(double mass, const Mat3& inertiaBody, ColdConstants& cold);
  void updateDerived();              // R, v, omega from the state; marks the world vertices stale
  void updateWorldVertices() const;  // p' = R p + x for every vertex

  // Hot: what an Integrate pass over awake bodies reads and writes, in the first 408 bytes (the
  // flags and m in 16, x q P L in 112 with q aligned to 16, the step's inputs in 280; the class is
  // aligned to a 64-byte line, so a pass touches 7 lines of a body). The flags lead, so a pass
  // that only tests awake_ touches one line per body.
  static_assert(!kStatedLayout || (sizeof(BodyState) == 112 && sizeof(StepInputs) == 280), "the hot fields' size in the comment above");
  bool awake_ = true;
  bool isStatic_ = false;
  bool isKinematic_ = false;
  mutable bool worldVerticesStale_ = true;  // the pose changed since worldVertices_ was filled
  double mass_ = 1.0;                       // for gravity, m g
  BodyState state_;
  StepInputs inputs_{Vec3::Zero(), Vec3::Zero(), Mat3::Identity(), Vec3::Zero(), Vec3::Zero(),
                     1.0,          Mat3::Identity(), nullptr,   Vec3::Zero()};  // v, omega, R, F, tau, constants, tau_b

  // After them, from byte 408: what only UpdateSleep and the accessors above read.
  double restingTime_ = 0.0;
  std::shared_ptr<const ColdConstants> cold_;
  mutable std::vector<Vec3> worldVertices_;  // a cache, filled by worldVertices() on demand
  FreeFlowMemoSlot freeFlow_;
};
// 8 cache lines of 64 bytes: the hot 408 bytes (7 lines), then the resting time, the cold block's
// pointer, the world vertices' cache and the free-flow memo up to byte 464, padded to the line by
// alignas(64). A field added to the hot part pushes it into the eighth line; up to 48 bytes
// more after it keep the body at 8 lines, more make it 9.
static_assert(!kStatedLayout || sizeof(RigidBody) == 8 * 64, "RigidBody's size in cache lines: see the comment above");

// Tolerance for accepting a matrix or quaternion as a rotation: ||R^T R - I||_F and | |q| - 1 |.
// Loose enough for values typed with 9 significant digits, tight enough to reject real errors.
inline constexpr double kRotationTolerance = 1e-6;

}  // namespace rbsim

#pragma once
// Time integrators for the rigid-body state Y = (x, q, P, L) (seed 004 "Automatic state update",
// seed 000 "forward Euler"), and better ones. Forces and torques are those accumulated at t_n and
// are held over the step (exact for torque-free motion and constant forces).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rbsim/integrate/body_state.h"
#include "rbsim/integrate/free_rigid_body.h"
#include "rbsim/math/types.h"

namespace rbsim {

enum class Integrator {
  EulerMatrix,  // R += dt omega* R, then seed 004's drift correction (re-orthonormalise)
  EulerQuat,    // q += dt/2 [0, omega] q, then renormalise (seed 001 "quaternions")
  ExpMap,       // q = exp(dt omega / 2) q: the exact rotation by angle |omega| dt (seed 004
                // "alternatives": rotation about an arbitrary axis)
  SymplecticEuler,  // momenta first, then x and q (expmap) with the new v and omega
                    // (Hairer, Lubich, Wanner, "Geometric Numerical Integration", VI.3)
  Rk4,              // classical Runge-Kutta 4 on (x, q, P, L), q renormalised once per step
  ImplicitGyro,     // body-frame implicit gyroscopic step, one Newton iteration, then expmap
                    // (Catto, "Numerical Methods", GDC 2015)
  Dlm,              // symplectic splitting of the free rigid body, torque as half kicks
                    // (Dullweber, Leimkuhler, McLachlan, J. Chem. Phys. 107, 5840, 1997)
  Exact,            // the exact torque-free flow (free_rigid_body.h), torque as half kicks
                    // around it (Strang splitting; Celledoni et al., SIAM J. Sci. Comput. 2008)
  Exact4,           // Yoshida's fourth-order composition of exact's step (Phys. Lett. A 150,
                    // 262, 1990); without torque one exact flow, as the composition would be
  Newmark,          // Newmark's average acceleration (beta = 1/4, gamma = 1/2; seed 000: "Newmark
                    // for better accuracy and stability"), Euler's equations in the body frame
};

// Whether the integrator keeps a FreeFlowMemo per body.
bool usesFreeFlow(Integrator integrator);

const char* integratorName(Integrator integrator);
bool parseIntegrator(const std::string& name, Integrator& out);
std::vector<std::string> integratorNames();

// One rotation step of each method for a constant angular velocity omega [rad/s] over dt [s].
Mat3 eulerMatrixStep(const Mat3& R, const Vec3& omega, double dt);
// The same update without the drift correction: R + dt omega* R, no longer a rotation.
Mat3 eulerMatrixUpdate(const Mat3& R, const Vec3& omega, double dt);
Quat eulerQuatStep(const Quat& q, const Vec3& omega, double dt);
Quat expMapStep(const Quat& q, const Vec3& omega, double dt);

// The inertia constants only implicit-gyro and dlm read. A body keeps them out of line, with its
// other constants no step reads, so that a step of the other integrators streams fewer bytes.
struct BodyInertia {
  Mat3 inertiaBody;          // I_body [kg m^2]
  Vec3 principalMoments;     // I_body = E diag(principalMoments) E^T [kg m^2]
  Mat3 principalAxes;        // E, a rotation; its columns are the principal axes in body frame
};

// The quantities at t_n an explicit step needs besides the state itself.
struct StepInputs {
  Vec3 velocity;             // v = P / m [m/s]
  Vec3 angularVelocity;      // omega = I^-1 L [rad/s]
  Mat3 rotation;             // R(q)
  Vec3 force;                // net F [N]
  Vec3 torque;               // net tau about x [N m], world frame, held over the step
  double inverseMass;        // 1 / m [1/kg]
  Mat3 inverseInertiaBody;   // I_body^-1
  const BodyInertia* inertia;  // never null
  Vec3 bodyTorque;           // net tau fixed in the body [N m], body frame: rk4, dlm, exact and
                             // exact4 turn it with the body within the step, the others hold
                             // R(t_n) tau. Last: the forward-Euler family's step reads it only to
                             // see that it is zero.
};

// What exact and exact4 keep of one body between steps: the flow from an epoch, so that step n
// evaluates it at n dt and a torque-free run accumulates no error. It restarts from the state
// whenever the state is not the one its last step left (a contact, a torque, a pose set by hand).
struct FreeFlowMemo {
  std::optional<FreeRigidBodyFlow> flow;
  double dt = 0.0;                   // [s]
  long steps = 0;                    // since the epoch
  Quat lastOrientation = Quat::Identity();  // the body orientation the last step wrote
  Quat bodyToPrincipal = Quat::Identity();  // E^T of BodyInertia, as a quaternion
};

// A FreeFlowMemo that a body copies with itself (each copy goes on alone), made when first used.
class FreeFlowMemoSlot {
 public:
  FreeFlowMemoSlot() = default;
  FreeFlowMemoSlot(const FreeFlowMemoSlot& other) : memo_(other.memo_ ? std::make_unique<FreeFlowMemo>(*other.memo_) : nullptr) {}
  FreeFlowMemoSlot& operator=(const FreeFlowMemoSlot& other) {
    memo_ = other.memo_ ? std::make_unique<FreeFlowMemo>(*other.memo_) : nullptr;
    return *this;
  }
  FreeFlowMemoSlot(FreeFlowMemoSlot&&) noexcept = default;
  FreeFlowMemoSlot& operator=(FreeFlowMemoSlot&&) noexcept = default;
  FreeFlowMemo& get() {
    if (!memo_) memo_ = std::make_unique<FreeFlowMemo>();
    return *memo_;
  }
  const FreeFlowMemo* find() const { return memo_.get(); }  // null until first used

 private:
  std::unique_ptr<FreeFlowMemo> memo_;
};

// One step of the chosen integrator. The first three are forward Euler: x += dt v, the rotation
// step, P += dt F, L += dt tau (seed 004 "Applying force and torque"). memo: the body's own, for
// exact and exact4 (without one they restart the flow every step, exact still).
BodyState integrate(Integrator integrator, const BodyState& y, const StepInputs& in, double dt,
                    FreeFlowMemo* memo = nullptr);

// A kinematic body's step (seed 000's infinite-mass objects, moved by what the program prescribes):
// x += dt v and the rotation by omega dt, exact for constant v and omega, whatever the forces;
// P = m v kept, L = I(t+dt) omega, so v and omega stay what was prescribed.
BodyState integrateKinematic(const BodyState& y, const StepInputs& in, double dt);

}  // namespace rbsim

#pragma once
// Time integrators for the rigid-body state Y = (x, q, P, L) (seed 004 "Automatic state update",
// seed 000 "forward Euler"). All three are explicit: every derivative is taken at t_n.
#include <string>
#include <vector>

#include "body/body_state.h"
#include "math/types.h"

namespace rbsim {

enum class Integrator {
  EulerMatrix,  // R += dt omega* R, then seed 004's drift correction (re-orthonormalise)
  EulerQuat,    // q += dt/2 [0, omega] q, then renormalise (seed 001 "quaternions")
  ExpMap,       // q = exp(dt omega / 2) q: the exact rotation by angle |omega| dt (seed 004
                // "alternatives": rotation about an arbitrary axis)
};

const char* integratorName(Integrator integrator);
bool parseIntegrator(const std::string& name, Integrator& out);
std::vector<std::string> integratorNames();

// One rotation step of each method for a constant angular velocity omega [rad/s] over dt [s].
Mat3 eulerMatrixStep(const Mat3& R, const Vec3& omega, double dt);
Quat eulerQuatStep(const Quat& q, const Vec3& omega, double dt);
Quat expMapStep(const Quat& q, const Vec3& omega, double dt);

// The quantities at t_n an explicit step needs besides the state itself.
struct StepInputs {
  Vec3 velocity;         // v = P / m [m/s]
  Vec3 angularVelocity;  // omega = I^-1 L [rad/s]
  Mat3 rotation;         // R(q) (used by the matrix method)
  Vec3 force;            // net F [N]
  Vec3 torque;           // net tau about x [N m]
};

// Forward Euler on Y: x += dt v, orientation by the chosen rotation step, P += dt F,
// L += dt tau (seed 004 "Applying force and torque").
BodyState integrate(Integrator integrator, const BodyState& y, const StepInputs& in, double dt);

}  // namespace rbsim

#pragma once
// Time integrators for the rigid-body state Y = (x, q, P, L) (seed 004 "Automatic state update",
// seed 000 "forward Euler"), and better ones. Forces and torques are those accumulated at t_n and
// are held over the step (exact for torque-free motion and constant forces).
#include <string>
#include <vector>

#include "rbsim/integrate/body_state.h"
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
};

const char* integratorName(Integrator integrator);
bool parseIntegrator(const std::string& name, Integrator& out);
std::vector<std::string> integratorNames();

// One rotation step of each method for a constant angular velocity omega [rad/s] over dt [s].
Mat3 eulerMatrixStep(const Mat3& R, const Vec3& omega, double dt);
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
  Vec3 torque;               // net tau about x [N m]
  double inverseMass;        // 1 / m [1/kg]
  Mat3 inverseInertiaBody;   // I_body^-1
  const BodyInertia* inertia;  // never null
};

// One step of the chosen integrator. The first three are forward Euler: x += dt v, the rotation
// step, P += dt F, L += dt tau (seed 004 "Applying force and torque").
BodyState integrate(Integrator integrator, const BodyState& y, const StepInputs& in, double dt);

// A kinematic body's step (seed 000's infinite-mass objects, moved by what the program prescribes):
// x += dt v and the rotation by omega dt, exact for constant v and omega, whatever the forces;
// P = m v kept, L = I(t+dt) omega, so v and omega stay what was prescribed.
BodyState integrateKinematic(const BodyState& y, const StepInputs& in, double dt);

}  // namespace rbsim

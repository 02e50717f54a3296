#include "integrate/integrator.h"

#include "math/rotation.h"

namespace rbsim {

namespace {
struct NamedIntegrator {
  Integrator integrator;
  const char* name;
};
constexpr NamedIntegrator kIntegrators[] = {
    {Integrator::EulerMatrix, "euler-matrix"},
    {Integrator::EulerQuat, "euler-quat"},
    {Integrator::ExpMap, "expmap"},
};
}  // namespace

const char* integratorName(Integrator integrator) {
  for (const NamedIntegrator& entry : kIntegrators) {
    if (entry.integrator == integrator) return entry.name;
  }
  return "unknown";
}

bool parseIntegrator(const std::string& name, Integrator& out) {
  for (const NamedIntegrator& entry : kIntegrators) {
    if (name == entry.name) {
      out = entry.integrator;
      return true;
    }
  }
  return false;
}

std::vector<std::string> integratorNames() {
  std::vector<std::string> names;
  for (const NamedIntegrator& entry : kIntegrators) names.emplace_back(entry.name);
  return names;
}

Mat3 eulerMatrixStep(const Mat3& R, const Vec3& omega, double dt) {
  // Seed 004 "RB rotational update": R(t + dt) = R(t) + omega* R(t) dt, then "Drift correction".
  return orthonormalize(R + dt * star(omega) * R);
}

Quat eulerQuatStep(const Quat& q, const Vec3& omega, double dt) {
  // Seed 001 (Baraff, quaternions): dq/dt = 1/2 [0, omega] q, forward Euler, then renormalise.
  const Quat omegaQuat(0.0, omega.x(), omega.y(), omega.z());
  Quat dq = omegaQuat * q;
  Quat next(q.w() + 0.5 * dt * dq.w(), q.x() + 0.5 * dt * dq.x(), q.y() + 0.5 * dt * dq.y(),
            q.z() + 0.5 * dt * dq.z());
  return next.normalized();
}

Quat expMapStep(const Quat& q, const Vec3& omega, double dt) {
  return (quatFromAxisAngle(dt * omega) * q).normalized();
}

BodyState integrate(Integrator integrator, const BodyState& y, const StepInputs& in, double dt) {
  BodyState next;
  next.position = y.position + dt * in.velocity;
  switch (integrator) {
    case Integrator::EulerMatrix:
      next.orientation = Quat(eulerMatrixStep(in.rotation, in.angularVelocity, dt)).normalized();
      break;
    case Integrator::EulerQuat:
      next.orientation = eulerQuatStep(y.orientation, in.angularVelocity, dt);
      break;
    case Integrator::ExpMap:
      next.orientation = expMapStep(y.orientation, in.angularVelocity, dt);
      break;
  }
  next.linearMomentum = y.linearMomentum + dt * in.force;
  next.angularMomentum = y.angularMomentum + dt * in.torque;
  return next;
}

}  // namespace rbsim

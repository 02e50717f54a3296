#include "rbsim/integrate/integrator.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "rbsim/math/rotation.h"

namespace rbsim {

namespace {
// Newton iterations of the implicit gyroscopic step stop when the update is below this fraction
// of |omega| [1], or after this many: rounding limits the first, the second never binds on the
// cases measured (convergence in at most 6 at |omega| dt = 17 rad).
constexpr double kImplicitGyroTolerance = 1e-14;
constexpr int kImplicitGyroMaxIterations = 50;
// Newmark's parameters (Newmark, "A method of computation for structural dynamics", J. Eng. Mech.
// Div. ASCE 85, 1959): the average acceleration, unconditionally stable for linear problems and
// second order, without numerical damping [1]. Its Newton iterations stop as implicit-gyro's.
constexpr double kNewmarkBeta = 0.25;
constexpr double kNewmarkGamma = 0.5;
constexpr int kNewmarkHalvings = 40;  // of a Newton step that does not lower the residual
// The midpoint's root is taken when |residual| <= this fraction of |I w| [1], a few roundings.
constexpr double kNewmarkResidual = 1e-13;
// A step whose solve stalls is split in two, up to this many times (2^10 pieces) [1].
constexpr int kNewmarkMaxSplits = 10;

struct NamedIntegrator {
  Integrator integrator;
  const char* name;
};
constexpr NamedIntegrator kIntegrators[] = {
    {Integrator::EulerMatrix, "euler-matrix"},
    {Integrator::EulerQuat, "euler-quat"},
    {Integrator::ExpMap, "expmap"},
    {Integrator::SymplecticEuler, "symplectic-euler"},
    {Integrator::Rk4, "rk4"},
    {Integrator::ImplicitGyro, "implicit-gyro"},
    {Integrator::Dlm, "dlm"},
    {Integrator::Exact, "exact"},
    {Integrator::Exact4, "exact4"},
    {Integrator::Newmark, "newmark"},
};

// Yoshida's triple jump: S(w1 h) S(w0 h) S(w1 h) is fourth order for a symmetric second-order
// step S (Yoshida, Phys. Lett. A 150, 262, 1990, eq. 5.19): w1 = 1 / (2 - 2^(1/3)),
// w0 = 1 - 2 w1 [1].
const double kCubeRootTwo = std::cbrt(2.0);
const double kYoshidaOuter = 1.0 / (2.0 - kCubeRootTwo);
const double kYoshidaInner = 1.0 - 2.0 * kYoshidaOuter;

// dY/dt of seed 004 "Rigid body representation": (v, 1/2 [0, omega] q, F, tau), with
// omega = R(q) I_body^-1 R(q)^T L evaluated at the given state. In the world frame: L moves only
// by torque, so |L| of a free body is exact to the bit and the step stays bounded at any spin
// (|omega| dt = 17 rad included), but the energy drifts at O(dt^4), and near the separatrix the
// ratio |L|^2 / 2E decides the motion: a box spun near its intermediate axis flips 23 % early at
// dt = 1/60 s (docs/accuracy.md). RK4 on Euler's equations in the body frame keeps the energy
// instead, and diverges once |omega| dt passes RK4's stability limit (about 2.8): dlm, exact and
// exact4 do both.
struct Derivative {
  Vec3 position;
  Eigen::Vector4d orientation;  // (x, y, z, w), Eigen's coefficient order
  Vec3 linearMomentum;
  Vec3 angularMomentum;
};

Derivative derivative(const BodyState& y, const StepInputs& in) {
  const Mat3 R = y.orientation.normalized().toRotationMatrix();
  const Vec3 omega = R * in.inverseInertiaBody * R.transpose() * y.angularMomentum;
  const Quat qdot = Quat(0.0, omega.x(), omega.y(), omega.z()) * y.orientation;
  const Vec3 torque = in.bodyTorque.isZero(0.0) ? in.torque : Vec3(in.torque + R * in.bodyTorque);
  return {in.inverseMass * y.linearMomentum, 0.5 * qdot.coeffs(), in.force, torque};
}

BodyState advance(const BodyState& y, const Derivative& d, double h) {
  BodyState out;
  out.position = y.position + h * d.position;
  out.orientation.coeffs() = y.orientation.coeffs() + h * d.orientation;
  out.linearMomentum = y.linearMomentum + h * d.linearMomentum;
  out.angularMomentum = y.angularMomentum + h * d.angularMomentum;
  return out;
}

BodyState rk4Step(const BodyState& y, const StepInputs& in, double dt) {
  const Derivative k1 = derivative(y, in);
  const Derivative k2 = derivative(advance(y, k1, dt / 2), in);
  const Derivative k3 = derivative(advance(y, k2, dt / 2), in);
  const Derivative k4 = derivative(advance(y, k3, dt), in);
  Derivative sum;
  sum.position = k1.position + 2 * k2.position + 2 * k3.position + k4.position;
  sum.orientation = k1.orientation + 2 * k2.orientation + 2 * k3.orientation + k4.orientation;
  sum.linearMomentum = k1.linearMomentum + 2 * k2.linearMomentum + 2 * k3.linearMomentum + k4.linearMomentum;
  sum.angularMomentum = k1.angularMomentum + 2 * k2.angularMomentum + 2 * k3.angularMomentum + k4.angularMomentum;
  BodyState next = advance(y, sum, dt / 6);
  next.orientation.normalize();  // the only projection: RK4 leaves |q| = 1 + O(dt^5)
  return next;
}

// Catto 2015: solve I (w2 - w1) + dt w2 x (I w2) = 0 for the body-frame angular velocity w2 by
// Newton's method from w1. Catto stops after one iteration; at large |omega| dt that iterate can
// gain energy (a 1:100:1000 body at 100 rad/s and dt = 1/60 s gained 16 % in one step), so we
// iterate to convergence: the exact root satisfies w2 . I w2 = w2 . I w1 (dot the equation with
// w2), so by Cauchy-Schwarz in the I inner product its energy never exceeds w1's.
Vec3 implicitGyroscopicOmega(const Vec3& omegaBody, const Mat3& inertia, double dt) {
  const Vec3 momentum = inertia * omegaBody;
  Vec3 w = omegaBody;
  for (int i = 0; i < kImplicitGyroMaxIterations; ++i) {
    const Vec3 residual = inertia * w - momentum + dt * w.cross(inertia * w);
    const Mat3 jacobian = inertia + dt * (star(w) * inertia - star(inertia * w));
    const Vec3 delta = jacobian.lu().solve(residual);
    w -= delta;
    if (delta.norm() <= kImplicitGyroTolerance * w.norm()) break;
  }
  return w;
}
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

Mat3 eulerMatrixUpdate(const Mat3& R, const Vec3& omega, double dt) {
  // Seed 004 "RB rotational update": R(t + dt) = R(t) + omega* R(t) dt.
  return R + dt * star(omega) * R;
}

Mat3 eulerMatrixStep(const Mat3& R, const Vec3& omega, double dt) {
  return orthonormalize(eulerMatrixUpdate(R, omega, dt));  // then seed 004's "Drift correction"
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

BodyState integrateKinematic(const BodyState& y, const StepInputs& in, double dt) {
  BodyState next = y;
  next.position = y.position + dt * in.velocity;
  next.orientation = expMapStep(y.orientation, in.angularVelocity, dt);
  const Mat3 R = next.orientation.toRotationMatrix();
  next.angularMomentum = R * (in.inertia->inertiaBody * (R.transpose() * in.angularVelocity));
  return next;
}

namespace {

// Seed 004 "Automatic state update": every derivative at t_n, the rotation by the chosen method.
BodyState forwardEulerStep(Integrator integrator, const BodyState& y, const StepInputs& in, double dt) {
  BodyState next;
  next.position = y.position + dt * in.velocity;
  if (integrator == Integrator::EulerMatrix) {
    next.orientation = Quat(eulerMatrixStep(in.rotation, in.angularVelocity, dt)).normalized();
  } else if (integrator == Integrator::EulerQuat) {
    next.orientation = eulerQuatStep(y.orientation, in.angularVelocity, dt);
  } else {
    next.orientation = expMapStep(y.orientation, in.angularVelocity, dt);
  }
  next.linearMomentum = y.linearMomentum + dt * in.force;
  next.angularMomentum = y.angularMomentum + dt * in.torque;
  return next;
}

// Semi-implicit Euler: momenta first, then x and q with the new v and omega = I^-1(t_n) L_{n+1}.
// Without torque its rotation is expmap's; it differs from forward Euler under forces.
BodyState symplecticStep(const BodyState& y, const StepInputs& in, double dt) {
  BodyState next;
  next.linearMomentum = y.linearMomentum + dt * in.force;
  next.angularMomentum = y.angularMomentum + dt * in.torque;
  // omega = I^-1(t_n) L_{n+1}, evaluated as RigidBody evaluates omega(t_n) = I^-1(t_n) L_n.
  // Without torque L_{n+1} = L_n, so omega(t_n) is that very value: free-flying bodies are spared
  // a second 3x3 triple product.
  Vec3 omega = in.angularVelocity;
  if (!in.torque.isZero(0.0)) omega = toWorldFrame(in.rotation, in.inverseInertiaBody) * next.angularMomentum;
  next.position = y.position + dt * in.inverseMass * next.linearMomentum;
  next.orientation = expMapStep(y.orientation, omega, dt);
  return next;
}

// Catto 2015: explicit torque, implicit gyroscopic term in the body frame, then the rotation by
// the new omega. Catto keeps omega, not L, across the rotation; with omega_body = w2 fixed the
// kinetic energy w2.I w2/2 is exactly what the implicit step left, which never exceeds the
// energy before it: spins about the intermediate axis cannot gain energy.
BodyState implicitGyroStep(const BodyState& y, const StepInputs& in, double dt) {
  BodyState next;
  next.linearMomentum = y.linearMomentum + dt * in.force;
  next.position = y.position + dt * in.inverseMass * next.linearMomentum;
  const Vec3 angularMomentum = y.angularMomentum + dt * in.torque;
  const Vec3 omegaBody = in.inverseInertiaBody * (in.rotation.transpose() * angularMomentum);
  const Vec3 omegaBodyNext = implicitGyroscopicOmega(omegaBody, in.inertia->inertiaBody, dt);
  next.orientation = expMapStep(y.orientation, in.rotation * omegaBodyNext, dt);
  next.angularMomentum = next.orientation.toRotationMatrix() * (in.inertia->inertiaBody * omegaBodyNext);
  return next;
}

// Newmark's average acceleration on the rigid body. Translation: a = F / m held over the step, so
// x += dt v + dt^2 (1/2 - beta + beta) a and v += dt a, exact for a constant force. Rotation:
// Euler's equations in the body frame, I w' = tau_b - w x I w, tau_b = R_n^T tau held. For a
// linear system the average acceleration is the implicit midpoint rule; for Euler's equations we
// take the midpoint form, Simo and Wong's Newmark-type rigid-body step (Int. J. Numer. Meth. Eng.
// 31, 19, 1991): I (w_{n+1} - w_n) + dt w_m x I w_m = dt tau_b with w_m = (w_n + w_{n+1}) / 2,
// which keeps the kinetic energy and |I w| of a torque-free body exactly (dot it with w_m, or
// with I w_m), where the trapezoidal average of the two end accelerations gained 3.5x its energy
// at 100 rad/s and dt = 1/60 s (stress_tests). The body turns by Newmark's displacement,
// theta = dt w_n + dt^2 ((1/2 - beta) alpha_n + beta alpha_{n+1}) = dt w_m for beta = 1/4,
// gamma = 1/2. w_m solves I u + (dt/2) u x I u = I w_n + (dt/2) tau_b, implicit-gyro's equation
// at half the step, by the same Newton iterations.
// One midpoint step of the rotation over h: w_m from I u + (h/2) u x I u = I w + (h/2) tau_b by
// damped Newton, then q turned by h w_m (body frame) and w = 2 w_m - w. False when Newton did
// not reach the root (at |omega| h of several radians it can stall): the caller splits the step.
bool newmarkRotation(Quat& q, Vec3& w, const Vec3& torqueBody, const Mat3& inertia, double h) {
  const Vec3 target = inertia * w + 0.5 * h * torqueBody;
  const auto residualAt = [&](const Vec3& v) { return Vec3(inertia * v + 0.5 * h * v.cross(inertia * v) - target); };
  Vec3 u = w;
  Vec3 residual = residualAt(u);
  for (int i = 0; i < kImplicitGyroMaxIterations; ++i) {
    if (residual.norm() <= kNewmarkResidual * target.norm()) break;
    const Mat3 jacobian = inertia + 0.5 * h * (star(u) * inertia - star(inertia * u));
    const Vec3 delta = jacobian.lu().solve(residual);
    double fraction = 1.0;  // damped: a full step may overshoot
    Vec3 tried = residualAt(u - delta);
    for (int halving = 0; halving < kNewmarkHalvings && !(tried.norm() < residual.norm()); ++halving) {
      fraction *= 0.5;
      tried = residualAt(u - fraction * delta);
    }
    // Stalled: no step along delta lowers the residual, and the next iteration would find the same
    // delta. At absurd spins (stress_tests' 1e80 rad/s) going on cost 20 ms a step for nothing.
    if (!(tried.norm() < residual.norm())) break;
    u -= fraction * delta;
    residual = tried;
  }
  q = (q * quatFromAxisAngle(h * u)).normalized();
  w = 2.0 * u - w;
  return residual.norm() <= kNewmarkResidual * target.norm();
}

BodyState newmarkStep(const BodyState& y, const StepInputs& in, double dt) {
  static_assert(kNewmarkBeta == 0.25 && kNewmarkGamma == 0.5, "theta = dt w_m holds for the average acceleration");
  BodyState next;
  const Vec3 acceleration = in.inverseMass * in.force;
  next.position = y.position + dt * in.velocity + dt * dt * 0.5 * acceleration;
  next.linearMomentum = y.linearMomentum + dt * in.force;
  const Mat3& inertia = in.inertia->inertiaBody;
  const Vec3 torqueBody = in.rotation.transpose() * in.torque;
  Quat q = y.orientation;
  Vec3 w = in.inverseInertiaBody * (in.rotation.transpose() * y.angularMomentum);
  // Where the solve stalls (1000 rad/s at 1/60 s: |omega| dt = 17 rad), the step is taken as 2,
  // 4, ... midpoint steps, each of which keeps the energy and |L| all the same.
  int pieces = 1;
  for (int level = 0;; ++level, pieces *= 2) {
    Quat trialQ = q;
    Vec3 trialW = w;
    bool converged = true;
    // A level that stalls in one piece is split again, so its other pieces need not be taken.
    for (int k = 0; k < pieces && (converged || level == kNewmarkMaxSplits); ++k) {
      converged = newmarkRotation(trialQ, trialW, torqueBody, inertia, dt / pieces) && converged;
    }
    if (converged || level == kNewmarkMaxSplits) {
      q = trialQ;
      w = trialW;
      break;
    }
  }
  next.orientation = q;
  // L = R_{n+1} I w_{n+1}: its length and the energy are the midpoint's, exact without torque; its
  // direction in the world drifts O(dt^2) over a run. Taking L += dt tau instead (Euler's law in
  // the world, exact for the direction) lost the energy: 1.1e-3 at 1/60 s on the box spun near
  // its intermediate axis, whose flips then came at the wrong times (bench/accuracy_sweep).
  next.angularMomentum = next.orientation.toRotationMatrix() * (inertia * w);
  return next;
}

// Dullweber, Leimkuhler & McLachlan 1997: H = sum_i Pi_i^2 / (2 I_i) in principal axes splits
// into three flows each solved exactly, a rotation about one principal axis by
// theta = t Pi_i / I_i (R <- R Rot_i(theta), Pi <- Rot_i(-theta) Pi). Composed symmetrically
// (1, 2, 3, 2, 1 with half steps outside) the step is second order, symplectic and
// time-reversible: world L is untouched, so |L| is exact and the energy error stays bounded.
// Torque enters as two half kicks of L around the free flow; constant F moves x exactly.
BodyState dlmStep(const BodyState& y, const StepInputs& in, double dt) {
  BodyState next;
  next.position = y.position + dt * in.inverseMass * (y.linearMomentum + 0.5 * dt * in.force);
  next.linearMomentum = y.linearMomentum + dt * in.force;
  const Vec3 angularMomentum = y.angularMomentum + 0.5 * dt * (in.torque + in.rotation * in.bodyTorque);

  const Quat principalToBody(in.inertia->principalAxes);
  Quat principalToWorld = y.orientation * principalToBody;
  Vec3 pi = principalToWorld.conjugate() * angularMomentum;  // Pi, principal frame
  const auto flow = [&](int axis, double h) {
    const double theta = h * pi[axis] / in.inertia->principalMoments[axis];
    principalToWorld = principalToWorld * Quat(Eigen::AngleAxisd(theta, Vec3::Unit(axis)));
    pi = Eigen::AngleAxisd(-theta, Vec3::Unit(axis)) * pi;
  };
  flow(0, 0.5 * dt);
  flow(1, 0.5 * dt);
  flow(2, dt);
  flow(1, 0.5 * dt);
  flow(0, 0.5 * dt);
  next.orientation = (principalToWorld * principalToBody.conjugate()).normalized();
  next.angularMomentum = angularMomentum + 0.5 * dt * (in.torque + next.orientation * in.bodyTorque);
  return next;
}

// The body's orientation after h [s] of the exact torque-free flow with world momentum L. With a
// memo, a step that continues the last one (same orientation to the bit, same L, same h) evaluates
// the memo's flow at (steps + 1) h instead of restarting it.
Quat freeRotation(const Quat& orientation, const Vec3& L, const StepInputs& in, double h, FreeFlowMemo* memo) {
  if (memo == nullptr) {
    const Quat principalToBody(in.inertia->principalAxes);
    const FreeRigidBodyFlow flow(orientation * principalToBody, L, in.inertia->principalMoments);
    return (flow.principalToWorld(h) * principalToBody.conjugate()).normalized();
  }
  const bool continues = memo->flow && memo->dt == h && memo->lastOrientation.coeffs() == orientation.coeffs() &&
                         memo->flow->angularMomentum() == L &&
                         memo->flow->principalMoments() == in.inertia->principalMoments;
  if (continues) {
    ++memo->steps;
  } else {
    memo->bodyToPrincipal = Quat(in.inertia->principalAxes).conjugate();
    memo->flow.emplace(orientation * memo->bodyToPrincipal.conjugate(), L, in.inertia->principalMoments);
    memo->dt = h;
    memo->steps = 1;
  }
  const double t = static_cast<double>(memo->steps) * h;
  memo->lastOrientation = (memo->flow->principalToWorld(t) * memo->bodyToPrincipal).normalized();
  return memo->lastOrientation;
}

// Strang splitting of the rotation: half kick, exact flow, half kick. The body-fixed torque is
// turned with the body to each kick: second order for torques fixed in the world or the body.
void strangRotation(Quat& orientation, Vec3& L, const Mat3& rotation, const StepInputs& in, double h) {
  L += 0.5 * h * (in.torque + rotation * in.bodyTorque);
  orientation = freeRotation(orientation, L, in, h, nullptr);
  L += 0.5 * h * (in.torque + orientation * in.bodyTorque);
}

// exact and exact4. Constant F moves x and P exactly (x += dt (P + dt F / 2) / m), so only the
// rotation is composed.
BodyState exactStep(Integrator integrator, const BodyState& y, const StepInputs& in, double dt, FreeFlowMemo* memo) {
  BodyState next;
  next.position = y.position + dt * in.inverseMass * (y.linearMomentum + 0.5 * dt * in.force);
  next.linearMomentum = y.linearMomentum + dt * in.force;
  next.angularMomentum = y.angularMomentum;
  if (in.torque.isZero(0.0) && in.bodyTorque.isZero(0.0)) {
    next.orientation = freeRotation(y.orientation, y.angularMomentum, in, dt, memo);
    return next;
  }
  next.orientation = y.orientation;
  if (integrator == Integrator::Exact) {
    strangRotation(next.orientation, next.angularMomentum, in.rotation, in, dt);
    return next;
  }
  strangRotation(next.orientation, next.angularMomentum, in.rotation, in, kYoshidaOuter * dt);
  strangRotation(next.orientation, next.angularMomentum, next.orientation.toRotationMatrix(), in, kYoshidaInner * dt);
  strangRotation(next.orientation, next.angularMomentum, next.orientation.toRotationMatrix(), in, kYoshidaOuter * dt);
  return next;
}

}  // namespace

bool usesFreeFlow(Integrator integrator) { return integrator == Integrator::Exact || integrator == Integrator::Exact4; }

BodyState integrate(Integrator integrator, const BodyState& y, const StepInputs& in, double dt, FreeFlowMemo* memo) {
  const bool splitting = integrator == Integrator::Dlm || usesFreeFlow(integrator) || integrator == Integrator::Rk4;
  if (!splitting && !in.bodyTorque.isZero(0.0)) {
    // The others hold the torque of t_n: tau = tau_world + R(t_n) tau_body.
    StepInputs held = in;
    held.torque += in.rotation * in.bodyTorque;
    held.bodyTorque.setZero();
    return integrate(integrator, y, held, dt, memo);
  }
  switch (integrator) {
    case Integrator::EulerMatrix:
    case Integrator::EulerQuat:
    case Integrator::ExpMap:
      return forwardEulerStep(integrator, y, in, dt);
    case Integrator::SymplecticEuler:
      return symplecticStep(y, in, dt);
    case Integrator::ImplicitGyro:
      return implicitGyroStep(y, in, dt);
    case Integrator::Rk4:
      return rk4Step(y, in, dt);
    case Integrator::Dlm:
      return dlmStep(y, in, dt);
    case Integrator::Exact:
    case Integrator::Exact4:
      return exactStep(integrator, y, in, dt, memo);
    case Integrator::Newmark:
      return newmarkStep(y, in, dt);
  }
  return y;
}

}  // namespace rbsim

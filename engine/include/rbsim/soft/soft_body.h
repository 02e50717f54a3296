#pragma once
// A deformable body: the nodes of a tetrahedral mesh moving under the finite-volume forces of
// seed 002 1.2. Per tetrahedron the rest-shape matrix D_m^-1 and the area-weighted normals b_i
// are precomputed; F = D_s D_m^-1, f_i = P(F) b_i for nodes 1-3 and f_0 = -(f_1 + f_2 + f_3).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/collision/contact.h"
#include "rbsim/body/material.h"
#include "rbsim/soft/constitutive.h"
#include "rbsim/soft/tet_mesh.h"

namespace rbsim {

enum class SoftIntegrator {
  SymplecticEuler,  // explicit: v += dt f(x, v) / m, then x += dt v; stable below stableTimeStep()
  BackwardEuler,    // implicit, one Newton step solved by conjugate gradients (Baraff and Witkin 1998)
};
const char* softIntegratorName(SoftIntegrator integrator);
bool parseSoftIntegrator(const std::string& name, SoftIntegrator& integrator);

struct SoftBodyDef {
  std::string name = "soft";
  TetMesh mesh;                          // rest shape, body frame [m]
  Vec3 position = Vec3::Zero();          // where the rest shape's origin is placed [m]
  Vec3 velocity = Vec3::Zero();          // of every node at the start [m/s]
  double density = 1000.0;               // rho [kg/m^3]
  double youngsModulus = 1e5;            // E [Pa]
  double poissonRatio = 0.3;             // nu, in (-1, 0.5)
  ConstitutiveModel model = ConstitutiveModel::Corotated;
  // Viscosity of the Green strain rate: P_damping = 2 eta F sym(F^T dF/dt), which no rigid motion
  // excites (Green strain does not change under rotation).
  double damping = 0.0;                  // eta [Pa s]
  SoftIntegrator integrator = SoftIntegrator::BackwardEuler;
  std::vector<std::uint32_t> pinned;     // nodes held in place (a clamped end)
  Material material;                     // against planes: restitution and friction
  Vec3 color = Vec3(0.3, 0.8, 0.5);      // linear RGB in [0, 1]
};

// Conjugate gradients of the implicit step (Shewchuk, "An Introduction to the Conjugate Gradient
// Method Without the Agonizing Pain", 1994): stop when the residual falls below this fraction of
// the right-hand side, or after the iteration cap.
inline constexpr double kConjugateGradientTolerance = 1e-8;  // [1] relative residual
inline constexpr int kConjugateGradientMaxIterations = 500;
// The explicit step's stability estimate: a fraction of the time the fastest (pressure) wave
// needs to cross the thinnest tetrahedron (Courant, Friedrichs, Lewy).
inline constexpr double kCourantNumber = 0.5;  // [1]

class SoftBody {
 public:
  explicit SoftBody(const SoftBodyDef& def);  // throws std::invalid_argument on a bad definition

  // One step of dt [s] under gravity, then the nodes are kept out of the planes. Throws
  // std::domain_error when a node's state or the internal forces stop being finite, or an element
  // inverts under a model that cannot (neo-Hookean).
  void step(double dt, const Vec3& gravity, const std::vector<Plane>& planes, const std::vector<Material>& planeMaterials);

  // Internal forces (elastic and damping) on every node [N], for the current state.
  void internalForces(std::vector<Vec3>& forces) const;
  double elasticEnergy() const;  // sum of psi(F) V_0 [J]
  double kineticEnergy() const;  // [J]
  Vec3 linearMomentum() const;   // [kg m/s]
  double mass() const;           // [kg]
  double stableTimeStep() const; // kCourantNumber h_min / c_p, c_p = sqrt((lambda + 2 mu) / rho) [s]

  const std::string& name() const { return name_; }
  const std::vector<Vec3>& positions() const { return x_; }
  std::vector<Vec3>& positions() { return x_; }
  const std::vector<Vec3>& velocities() const { return v_; }
  std::vector<Vec3>& velocities() { return v_; }
  const std::vector<double>& nodeMasses() const { return m_; }
  const TetMesh& mesh() const { return mesh_; }
  const Elasticity& elasticity() const { return elasticity_; }
  SoftIntegrator integrator() const { return integrator_; }
  const Vec3& color() const { return color_; }
  const Material& material() const { return material_; }
  std::size_t tetCount() const { return mesh_.tets.size(); }
  int lastIterations() const { return lastIterations_; }  // CG iterations of the last implicit step

  // The area-weighted normals of tetrahedron t, b_1..b_3 as columns (b_0 = -(b_1 + b_2 + b_3)).
  const Mat3& areaWeightedNormals(std::size_t t) const { return b_[t]; }
  Mat3 deformationGradient(std::size_t t) const;

 private:
  Mat3 shape(const std::vector<Vec3>& x, const std::size_t t) const;  // D_s = [x1-x0, x2-x0, x3-x0]
  void addForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& forces) const;
  void linearize();  // linearized_ at the current positions
  // The change of the internal forces for a change dx of positions and dv of velocities, at the
  // positions of the last linearize().
  void forceDifferential(const std::vector<Vec3>& dx, const std::vector<Vec3>& dv, std::vector<Vec3>& df) const;
  void stepSymplectic(double dt, const Vec3& gravity);
  void stepBackwardEuler(double dt, const Vec3& gravity);
  void collidePlanes(const std::vector<Plane>& planes, const std::vector<Material>& planeMaterials);
  // Throws std::domain_error naming the body, `what` stopped being finite, and the likely cause.
  [[noreturn]] void throwNonFinite(const std::string& what, double dt) const;

  std::string name_;
  TetMesh mesh_;
  Elasticity elasticity_;
  double damping_;
  double density_;
  SoftIntegrator integrator_;
  Material material_;
  Vec3 color_;
  std::vector<Vec3> x_, v_;
  std::vector<double> m_;          // lumped node masses: a quarter of each tetrahedron's [kg]
  std::vector<char> pinned_;
  std::vector<Mat3> restInverse_;  // D_m^-1
  std::vector<double> restVolume_; // V_0 [m^3]
  std::vector<Mat3> b_;            // -V_0 D_m^-T: columns b_1, b_2, b_3
  std::vector<StressLinearization> linearized_;  // the implicit step's, per tetrahedron
  int lastIterations_ = 0;
  // Scratch of the implicit step, kept to avoid allocating each step.
  std::vector<Vec3> f_, r_, p_, q_, z_, dv_, zero_, preconditioned_;
};

}  // namespace rbsim

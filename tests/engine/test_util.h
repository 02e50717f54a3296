#pragma once
// Small helpers shared by the engine suites: data paths, the integrator list, a box body, and an
// element-wise comparison of Eigen objects that prints both sides when it fails.
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/body_def.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/integrate/integrator.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/types.h"
#include "rbsim/world/world.h"

namespace rbsim {
// Test names and messages show "expmap", not the enum's bytes.
inline void PrintTo(Integrator integrator, std::ostream* os) { *os << integratorName(integrator); }
}  // namespace rbsim

namespace rbsim::test {

inline std::string dataPath(const std::string& name) {
  return std::string(RBSIM_TEST_DATA_DIR) + "/" + name;
}

// The forward-Euler family of seed 004 (explicit in x, P, L; they differ in the rotation step).
inline const std::vector<Integrator>& forwardEulerIntegrators() {
  static const std::vector<Integrator> family = {Integrator::EulerMatrix, Integrator::EulerQuat,
                                                 Integrator::ExpMap};
  return family;
}

// Every integrator rbsim offers.
inline const std::vector<Integrator>& allIntegrators() {
  static const std::vector<Integrator> all = {Integrator::EulerMatrix, Integrator::EulerQuat,
                                              Integrator::ExpMap, Integrator::SymplecticEuler,
                                              Integrator::Rk4, Integrator::ImplicitGyro,
                                              Integrator::Dlm, Integrator::Exact, Integrator::Exact4,
                                              Integrator::Newmark};
  return all;
}

// A name no other test process uses, for files under the system temporary directory.
inline std::string uniqueTempName(const std::string& stem) {
  return "rbsim_engine_tests_" + stem + "_" + std::to_string(std::random_device{}());
}

// Parameter names for INSTANTIATE_TEST_SUITE_P: "euler-matrix" -> "euler_matrix".
inline std::string integratorParamName(const testing::TestParamInfo<Integrator>& info) {
  std::string name = integratorName(info.param);
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

// A solid box of uniform density: the seed's vertex list and the closed-form inertia.
inline BodyDef boxDef(const Vec3& extents, double mass, const std::string& name = "box") {
  BodyDef def;
  def.name = name;
  def.mesh = std::make_shared<const Mesh>(makeBox(extents));
  def.mass = mass;
  def.inertiaBody = cuboidInertia(mass, extents);
  return def;
}

// max_ij |a_ij - b_ij| <= tol, printing both operands otherwise.
template <typename DA, typename DB>
testing::AssertionResult allNear(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b,
                                 double tol) {
  const double err = (a - b).cwiseAbs().maxCoeff();
  if (err <= tol) return testing::AssertionSuccess();
  const Eigen::IOFormat fmt(Eigen::FullPrecision, 0, ", ", "; ", "", "", "[", "]");
  return testing::AssertionFailure() << "max |a - b| = " << err << " > " << tol
                                     << "\n  a = " << a.format(fmt) << "\n  b = " << b.format(fmt);
}

// An empty World stepping with the given integrator, time step [s] and gravity [m/s^2].
inline World worldWith(Integrator integrator, double dt, const Vec3& gravity) {
  Settings s;
  s.integrator = integrator;
  s.timeStep = dt;
  s.gravity = gravity;
  return World(s);
}

}  // namespace rbsim::test

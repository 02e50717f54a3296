#include "rbsim/soft/soft_body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rbsim {

const char* softIntegratorName(SoftIntegrator integrator) {
  return integrator == SoftIntegrator::SymplecticEuler ? "symplectic-euler" : "backward-euler";
}

bool parseSoftIntegrator(const std::string& name, SoftIntegrator& integrator) {
  if (name == "symplectic-euler") {
    integrator = SoftIntegrator::SymplecticEuler;
  } else if (name == "backward-euler") {
    integrator = SoftIntegrator::BackwardEuler;
  } else {
    return false;
  }
  return true;
}

SoftBody::SoftBody(const SoftBodyDef& def)
    : name_(def.name),
      mesh_(def.mesh),
      damping_(def.damping),
      density_(def.density),
      integrator_(def.integrator),
      material_(def.material),
      color_(def.color) {
  const std::string problem = checkTetMesh(mesh_);
  if (!problem.empty()) throw std::invalid_argument("soft body '" + name_ + "': " + problem);
  if (mesh_.tets.empty()) throw std::invalid_argument("soft body '" + name_ + "': no tetrahedra");
  if (!(def.density > 0.0) || !std::isfinite(def.density)) {
    throw std::invalid_argument("soft body '" + name_ + "': expected density > 0");
  }
  if (!(def.damping >= 0.0) || !std::isfinite(def.damping)) {
    throw std::invalid_argument("soft body '" + name_ + "': expected damping >= 0");
  }
  try {
    elasticity_ = Elasticity{def.model, lameParameters(def.youngsModulus, def.poissonRatio)};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("soft body '" + name_ + "': " + e.what());
  }
  const std::string materialProblem = checkMaterial(def.material);
  if (!materialProblem.empty()) throw std::invalid_argument("soft body '" + name_ + "': " + materialProblem);
  if (!def.position.allFinite() || !def.velocity.allFinite()) {
    throw std::invalid_argument("soft body '" + name_ + "': expected a finite position and velocity");
  }

  const std::size_t n = mesh_.nodes.size();
  x_.resize(n);
  for (std::size_t i = 0; i < n; ++i) x_[i] = mesh_.nodes[i] + def.position;
  v_.assign(n, def.velocity);
  m_.assign(n, 0.0);
  pinned_.assign(n, 0);
  for (std::uint32_t p : def.pinned) {
    if (p >= n) throw std::invalid_argument("soft body '" + name_ + "': pinned node " + std::to_string(p) + " does not exist");
    pinned_[p] = 1;
    v_[p] = Vec3::Zero();
  }
  for (std::size_t t = 0; t < mesh_.tets.size(); ++t) {
    const Mat3 dm = shape(mesh_.nodes, t);
    const double volume = dm.determinant() / 6.0;
    restInverse_.push_back(dm.inverse());
    restVolume_.push_back(volume);
    // Seed 002 1.2: f_i = P b_i with b_i = -1/3 (A_1 N_1 + A_2 N_2 + A_3 N_3) over the faces at
    // node i in material coordinates, which equals -V_0 D_m^-T e_i.
    b_.push_back(-volume * restInverse_.back().transpose());
    for (std::uint32_t node : mesh_.tets[t]) m_[node] += 0.25 * density_ * volume;
  }
}

Mat3 SoftBody::shape(const std::vector<Vec3>& x, std::size_t t) const {
  const Tet& tet = mesh_.tets[t];
  Mat3 d;
  d << x[tet[1]] - x[tet[0]], x[tet[2]] - x[tet[0]], x[tet[3]] - x[tet[0]];
  return d;
}

Mat3 SoftBody::deformationGradient(std::size_t t) const { return shape(x_, t) * restInverse_[t]; }

void SoftBody::addForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& forces) const {
  for (std::size_t t = 0; t < mesh_.tets.size(); ++t) {
    const Mat3 F = shape(x, t) * restInverse_[t];
    Mat3 P = firstPiolaStress(elasticity_, F);
    if (damping_ > 0.0) {
      const Mat3 Fdot = shape(v, t) * restInverse_[t];
      const Mat3 greenRate = 0.5 * (F.transpose() * Fdot + Fdot.transpose() * F);
      P += 2.0 * damping_ * F * greenRate;
    }
    const Mat3 h = P * b_[t];  // columns: f_1, f_2, f_3
    const Tet& tet = mesh_.tets[t];
    forces[tet[1]] += h.col(0);
    forces[tet[2]] += h.col(1);
    forces[tet[3]] += h.col(2);
    forces[tet[0]] -= h.col(0) + h.col(1) + h.col(2);  // the four sum to zero (seed 002)
  }
}

void SoftBody::internalForces(std::vector<Vec3>& forces) const {
  forces.assign(x_.size(), Vec3::Zero());
  addForces(x_, v_, forces);
}

void SoftBody::linearize() {
  linearized_.resize(mesh_.tets.size());
  for (std::size_t t = 0; t < mesh_.tets.size(); ++t) linearized_[t] = rbsim::linearize(elasticity_, deformationGradient(t));
}

void SoftBody::forceDifferential(const std::vector<Vec3>& dx, const std::vector<Vec3>& dv, std::vector<Vec3>& df) const {
  df.assign(x_.size(), Vec3::Zero());
  for (std::size_t t = 0; t < mesh_.tets.size(); ++t) {
    const Mat3& F = linearized_[t].F;
    Mat3 dP = stressDifferential(elasticity_, linearized_[t], shape(dx, t) * restInverse_[t]);
    if (damping_ > 0.0) {
      const Mat3 dFdot = shape(dv, t) * restInverse_[t];
      dP += 2.0 * damping_ * F * (0.5 * (F.transpose() * dFdot + dFdot.transpose() * F));
    }
    const Mat3 h = dP * b_[t];
    const Tet& tet = mesh_.tets[t];
    df[tet[1]] += h.col(0);
    df[tet[2]] += h.col(1);
    df[tet[3]] += h.col(2);
    df[tet[0]] -= h.col(0) + h.col(1) + h.col(2);
  }
}

double SoftBody::elasticEnergy() const {
  double energy = 0.0;
  for (std::size_t t = 0; t < mesh_.tets.size(); ++t) {
    energy += restVolume_[t] * strainEnergyDensity(elasticity_, deformationGradient(t));
  }
  return energy;
}

double SoftBody::kineticEnergy() const {
  double energy = 0.0;
  for (std::size_t i = 0; i < x_.size(); ++i) energy += 0.5 * m_[i] * v_[i].squaredNorm();
  return energy;
}

Vec3 SoftBody::linearMomentum() const {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < x_.size(); ++i) p += m_[i] * v_[i];
  return p;
}

double SoftBody::mass() const {
  double total = 0.0;
  for (double m : m_) total += m;
  return total;
}

double SoftBody::stableTimeStep() const {
  // The thinnest element: its smallest altitude, 3 V / (largest face area).
  double thinnest = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh_.tets.size(); ++t) {
    const Tet& tet = mesh_.tets[t];
    const int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    double largest = 0.0;
    for (const auto& f : faces) {
      const Vec3& a = mesh_.nodes[tet[f[0]]];
      largest = std::max(largest, 0.5 * (mesh_.nodes[tet[f[1]]] - a).cross(mesh_.nodes[tet[f[2]]] - a).norm());
    }
    thinnest = std::min(thinnest, 3.0 * restVolume_[t] / largest);
  }
  const double waveSpeed = std::sqrt((elasticity_.lame.lambda + 2.0 * elasticity_.lame.mu) / density_);
  return kCourantNumber * thinnest / waveSpeed;
}

void SoftBody::collidePlanes(const std::vector<Plane>& planes, const std::vector<Material>& planeMaterials) {
  // Seed 000 "Collision Response" and "Friction" for a node against a static plane: the node is
  // put back on the surface; an approaching normal velocity u_N is replaced by -c_R u_N, and the
  // tangential velocity stops if the normal impulse's cone mu_s holds it, else loses mu_k of it.
  for (std::size_t p = 0; p < planes.size(); ++p) {
    const Plane& plane = planes[p];
    const Material m = combine(material_, planeMaterials[p]);
    for (std::size_t i = 0; i < x_.size(); ++i) {
      const double depth = -plane.signedDistance(x_[i]);
      if (depth <= 0.0 || pinned_[i]) continue;
      x_[i] += depth * plane.normal;
      const double normalSpeed = v_[i].dot(plane.normal);
      if (normalSpeed >= 0.0) continue;
      const double normalChange = -(1.0 + m.restitution) * normalSpeed;
      Vec3 tangential = v_[i] - normalSpeed * plane.normal;
      const double slip = tangential.norm();
      if (slip <= m.staticFriction * normalChange) {
        tangential = Vec3::Zero();
      } else {
        tangential *= 1.0 - m.kineticFriction * normalChange / slip;
      }
      v_[i] = -m.restitution * normalSpeed * plane.normal + tangential;
    }
  }
}

void SoftBody::step(double dt, const Vec3& gravity, const std::vector<Plane>& planes,
                    const std::vector<Material>& planeMaterials) {
  if (integrator_ == SoftIntegrator::SymplecticEuler) {
    stepSymplectic(dt, gravity);
  } else {
    stepBackwardEuler(dt, gravity);
  }
  collidePlanes(planes, planeMaterials);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!x_[i].allFinite() || !v_[i].allFinite()) throwNonFinite("node " + std::to_string(i) + "'s position or velocity", dt);
  }
}

void SoftBody::throwNonFinite(const std::string& what, double dt) const {
  std::ostringstream message;
  message << "soft body '" << name_ << "': " << what << " stopped being finite (" << softIntegratorName(integrator_)
          << ", dt = " << dt << " s; the explicit step is stable below " << stableTimeStep() << " s, lambda = "
          << elasticity_.lame.lambda << " Pa, mu = " << elasticity_.lame.mu
          << " Pa). Likely a step past the stability limit, an element crushed flat, or moduli too large for the mesh.";
  throw std::domain_error(message.str());
}

}  // namespace rbsim

// "soft_bodies": [{...}, ...]: FEM soft bodies (engine/soft). A block of tetrahedra is generated
// from "shape": {"type": "box", "extents": [x, y, z], "cells": [nx, ny, nz]}.
#include "scene/soft_parser.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/scene/json_fields.h"
#include "scene/body_parser.h"
#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {

// Nodes within this fraction of the block's extent of the pinned face's coordinate lie on it (the
// grid puts them there exactly, up to the rounding of extents * i / n); relative, so that a block
// of 1e-13 m is not all one face.
constexpr double kOnFaceTolerance = 1e-12;  // [1] of the extent along the face's axis
// More cells than this per axis is a typo or a machine-filling mistake (1e6 tetrahedra).
constexpr int kMaxCellsPerAxis = 60;
constexpr double kTetsPerCell = 6.0;  // Kuhn's subdivision of a cube (soft/tet_mesh.h)
// Element evaluations (stress, or its differential, of one tetrahedron) per World step over all
// soft bodies, at most: about 40 ns each, the limit is ~1 s of computing per step. Backward Euler
// evaluates each element up to kConjugateGradientMaxIterations + 2 times a step, the explicit
// step once.
constexpr double kMaxSoftElementEvaluationsPerStep = 2.5e7;  // [evaluations per step]

double evaluationsPerTet(SoftIntegrator integrator) {
  return integrator == SoftIntegrator::BackwardEuler ? kConjugateGradientMaxIterations + 2.0 : 1.0;
}

// Every quantity the soft body derives from the block's numbers, checked where it is computed
// here, before the World makes it: finite and positive, reported against the field it came from.
void checkDerived(const JsonObject& s, const JsonObject& shape, const SoftBodyDef& def, const Vec3& extents,
                  const int cells[3]) {
  const double cellCount = static_cast<double>(cells[0]) * cells[1] * cells[2];
  const double tetVolume = extents.x() * extents.y() * extents.z() / cellCount / kTetsPerCell;
  if (!(tetVolume > 0.0) || !std::isfinite(tetVolume)) {
    shape.fail("extents", "each tetrahedron's volume is " + formatNumber(tetVolume) + " m^3 (extents / cells); expected a finite "
                          "volume > 0 (the extents " + (tetVolume > 0.0 ? "overflow" : "underflow") + ")");
  }
  const double nodeMass = 0.25 * def.density * tetVolume;
  const double totalMass = def.density * tetVolume * cellCount * kTetsPerCell;
  if (!(nodeMass > 0.0) || !std::isfinite(totalMass) || !std::isfinite(1.0 / nodeMass)) {
    s.fail("density", "the body's mass rho V = " + formatNumber(totalMass) + " kg, a node's " + formatNumber(nodeMass) +
                          " kg; expected finite masses > 0 whose inverses are finite");
  }
  const Vec3 corner = def.position.cwiseAbs() + 0.5 * extents;
  if (!corner.allFinite()) s.fail("position", "the block's corners overflow; expected position +- extents / 2 finite");
  if (!(totalMass * def.velocity.stableNorm() < INFINITY)) {
    s.fail("velocity", "the momentum m v = " + formatNumber(totalMass) + " kg x " + formatNumber(def.velocity.stableNorm()) +
                           " m/s overflows; expected a finite product");
  }
  const double lambda = def.poissonRatio * def.youngsModulus / ((1.0 + def.poissonRatio) * (1.0 - 2.0 * def.poissonRatio));
  const double mu = def.youngsModulus / (2.0 * (1.0 + def.poissonRatio));
  const double pModulus = lambda + 2.0 * mu;  // the stiffness of a compression wave
  if (!std::isfinite(lambda) || !std::isfinite(mu) || !(pModulus > 0.0) || !std::isfinite(pModulus)) {
    s.fail("youngs_modulus", "Lame's constants are lambda = " + formatNumber(lambda) + " Pa, mu = " + formatNumber(mu) +
                                 " Pa (lambda + 2 mu = " + formatNumber(pModulus) + " Pa) from E = " + formatNumber(def.youngsModulus) +
                                 " Pa and nu = " + formatNumber(def.poissonRatio) + "; expected finite moduli with lambda + 2 mu > 0");
  }
  const double waveSpeed = std::sqrt(pModulus / def.density);
  const double edge = extents.minCoeff() / std::max({cells[0], cells[1], cells[2]});
  const double crossing = edge / waveSpeed;  // a wave's time across a cell: the explicit step's scale
  if (!(waveSpeed > 0.0) || !std::isfinite(waveSpeed) || !(crossing > 0.0)) {
    s.fail("youngs_modulus", "the pressure wave speed sqrt((lambda + 2 mu) / rho) = " + formatNumber(waveSpeed) +
                                 " m/s crosses a cell in " + formatNumber(crossing) + " s; expected a finite speed > 0 and a time > 0");
  }
  // A stress of the stiffest modulus over an element's face, per unit strain: the force scale.
  const double forceScale = pModulus * tetVolume / edge;
  if (!std::isfinite(forceScale) || !std::isfinite(forceScale / nodeMass)) {
    s.fail("youngs_modulus", "a node's force per unit strain, (lambda + 2 mu) V / h = " + formatNumber(forceScale) +
                                 " N, over its mass " + formatNumber(nodeMass) + " kg overflows; expected a finite acceleration");
  }
  if (!std::isfinite(def.damping * tetVolume / edge / nodeMass)) {
    s.fail("damping", "a node's damping force per unit strain rate over its mass overflows; expected a finite value");
  }
}

// The block's integrator, read ahead of the rest for the work estimate (checked again below).
SoftIntegrator integratorOf(const JsonObject& s) {
  SoftIntegrator integrator = SoftIntegrator::BackwardEuler;
  parseSoftIntegrator(s.string("integrator", softIntegratorName(integrator)), integrator);
  return integrator;
}

void pinFace(const JsonObject& s, SoftBodyDef& def) {
  if (!s.has("pin")) return;
  const std::string face = s.requiredString("pin");
  const char* faces[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  int which = -1;
  for (int f = 0; f < 6; ++f) {
    if (face == faces[f]) which = f;
  }
  if (which < 0) s.fail("pin", "expected one of \"-x\", \"+x\", \"-y\", \"+y\", \"-z\", \"+z\" (the face whose nodes are held), got \"" + face + "\"");
  const int axis = which / 2;
  double low = INFINITY, high = -INFINITY;
  for (const Vec3& p : def.mesh.nodes) {
    low = std::min(low, p[axis]);
    high = std::max(high, p[axis]);
  }
  const double extreme = which % 2 == 0 ? low : high;
  for (std::size_t i = 0; i < def.mesh.nodes.size(); ++i) {
    if (std::abs(def.mesh.nodes[i][axis] - extreme) < kOnFaceTolerance * (high - low)) {
      def.pinned.push_back(static_cast<std::uint32_t>(i));
    }
  }
}

}  // namespace

void parseSoftBodies(const JsonObject& root, Scene& scene) {
  if (!root.has("soft_bodies")) return;
  const std::vector<JsonObject> blocks = root.objectArray(
      "soft_bodies", {"name", "shape", "position", "velocity", "density", "youngs_modulus", "poisson_ratio", "model", "damping",
                      "integrator", "pin", "restitution", "friction_static", "friction_kinetic", "color"});
  double work = 0.0;  // element evaluations per step of the blocks so far
  for (const JsonObject& s : blocks) {
    SoftBodyDef def;
    def.name = s.string("name", "soft" + std::to_string(scene.softBodies.size()));
    const JsonObject shape = s.object("shape", {"type", "extents", "cells"});
    if (shape.requiredString("type") != "box") shape.fail("type", "expected \"box\" (a block of tetrahedra)");
    const Vec3 extents = shape.positiveVec3("extents");
    int cells[3] = {2, 2, 2};
    if (shape.has("cells")) {
      const Vec3 n = shape.vec3("cells", Vec3::Constant(2.0));
      for (int a = 0; a < 3; ++a) {
        if (!(n[a] >= 1.0 && n[a] <= kMaxCellsPerAxis) || n[a] != std::floor(n[a])) {
          shape.fail("cells", "expected 3 whole numbers in [1, " + std::to_string(kMaxCellsPerAxis) + "]");
        }
        cells[a] = static_cast<int>(n[a]);
      }
    }
    const double tets = kTetsPerCell * cells[0] * cells[1] * cells[2];
    work += tets * evaluationsPerTet(integratorOf(s));
    if (work > kMaxSoftElementEvaluationsPerStep) {
      shape.fail("cells", std::to_string(static_cast<long long>(tets)) + " tetrahedra (with the soft bodies before) need up to " +
                              formatNumber(work) + " element evaluations per step (" + softIntegratorName(integratorOf(s)) +
                              ": " + formatNumber(evaluationsPerTet(integratorOf(s))) + " per tetrahedron); the limit is " +
                              formatNumber(kMaxSoftElementEvaluationsPerStep) + " per step: use fewer cells");
    }
    def.mesh = makeTetBox(extents, cells[0], cells[1], cells[2]);
    if (!(extents.maxCoeff() <= kMaxCoordinate)) shape.fail("extents", "expected each at most 1e6 m, the farthest a scene reaches");
    def.position = s.boundedVec3("position", def.position, kMaxCoordinate, "m", "the farthest a scene reaches");
    def.velocity = s.boundedVec3("velocity", def.velocity, kMaxSpeed, "m/s", "the speed of light");
    def.density = s.positiveNumber("density", def.density);
    def.youngsModulus = s.positiveNumber("youngs_modulus", def.youngsModulus);
    if (def.youngsModulus > kMaxYoungsModulus) {
      s.fail("youngs_modulus", "expected at most 1e13 Pa (ten times diamond's 1.2e12 Pa; steel is 2e11 Pa)");
    }
    def.poissonRatio = s.number("poisson_ratio", def.poissonRatio);
    if (!(def.poissonRatio > -1.0 && def.poissonRatio < 0.5)) s.fail("poisson_ratio", "expected a value in (-1, 0.5)");
    const std::string model = s.string("model", constitutiveModelName(def.model));
    if (!parseConstitutiveModel(model, def.model)) {
      s.fail("model", "unknown model \"" + model + "\"; expected linear, stvk, corotated or neo-hookean");
    }
    def.damping = s.number("damping", def.damping);
    if (!(def.damping >= 0.0)) s.fail("damping", "expected a viscosity >= 0 Pa s");
    const std::string integrator = s.string("integrator", softIntegratorName(def.integrator));
    if (!parseSoftIntegrator(integrator, def.integrator)) {
      s.fail("integrator", "unknown soft integrator \"" + integrator + "\"; expected symplectic-euler or backward-euler");
    }
    def.color = s.vec3("color", def.color);
    if (def.color.minCoeff() < 0.0 || def.color.maxCoeff() > 1.0) s.fail("color", "components must lie in [0, 1]");
    def.material = parseMaterial(s);
    checkDerived(s, shape, def, extents, cells);
    pinFace(s, def);
    scene.softBodies.push_back(def);
  }
}

}  // namespace rbsim::scene_detail

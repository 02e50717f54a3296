// "soft_bodies": [{...}, ...]: FEM soft bodies (engine/soft). A block of tetrahedra is generated
// from "shape": {"type": "box", "extents": [x, y, z], "cells": [nx, ny, nz]}.
#include "scene/soft_parser.h"

#include <cmath>
#include <stdexcept>

#include "scene/body_parser.h"

namespace rbsim::scene_detail {

namespace {

// Nodes within this of the pinned face's coordinate lie on it (the grid puts them there exactly,
// up to the rounding of extents * i / n).
constexpr double kOnFaceTolerance = 1e-12;  // [m]
// More cells than this per axis is a typo or a machine-filling mistake (1e6 tetrahedra).
constexpr int kMaxCellsPerAxis = 60;

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
  double extreme = which % 2 == 0 ? INFINITY : -INFINITY;
  for (const Vec3& p : def.mesh.nodes) extreme = which % 2 == 0 ? std::min(extreme, p[axis]) : std::max(extreme, p[axis]);
  for (std::size_t i = 0; i < def.mesh.nodes.size(); ++i) {
    if (std::abs(def.mesh.nodes[i][axis] - extreme) < kOnFaceTolerance) def.pinned.push_back(static_cast<std::uint32_t>(i));
  }
}

}  // namespace

void parseSoftBodies(const JsonObject& root, Scene& scene) {
  if (!root.has("soft_bodies")) return;
  const std::vector<JsonObject> blocks = root.objectArray(
      "soft_bodies", {"name", "shape", "position", "velocity", "density", "youngs_modulus", "poisson_ratio", "model", "damping",
                      "integrator", "pin", "restitution", "friction_static", "friction_kinetic", "color"});
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
    def.mesh = makeTetBox(extents, cells[0], cells[1], cells[2]);
    def.position = s.vec3("position", def.position);
    def.velocity = s.vec3("velocity", def.velocity);
    def.density = s.positiveNumber("density", def.density);
    def.youngsModulus = s.positiveNumber("youngs_modulus", def.youngsModulus);
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
    pinFace(s, def);
    scene.softBodies.push_back(def);
  }
}

}  // namespace rbsim::scene_detail

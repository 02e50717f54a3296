#include "run/soft_view.h"

#include <cstdio>
#include <string>

#include "rbsim/world/systems.h"
#include "run/format.h"
#include "run/to_glm.h"

namespace rbsim::app {

void addSoftView(const World& world, render::FrameData& frame) {
  for (const SoftBody& soft : softBodies(world)) {
    render::BodyView view;
    view.worldVertices.reserve(soft.positions().size());
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : soft.positions()) {
      view.worldVertices.push_back(toGlm(x));
      centre += x / static_cast<double>(soft.positions().size());
    }
    view.triangles = &soft.mesh().boundary;
    view.position = toGlm(centre);
    view.color = toGlm(soft.color());
    view.axisLength = 0.0f;  // a deforming body has no body axes to draw
    view.smooth = true;
    frame.bodies.push_back(std::move(view));
  }
  if (softBodies(world).empty()) return;
  const SoftBody& soft = softBodies(world).front();
  std::vector<render::OverlayRow>& rows = frame.overlay.rows;
  using render::RowLevel;
  rows.push_back({"soft body", soft.name() + format(" (%.0f tetrahedra, %.3g kg)", static_cast<double>(soft.tetCount()), soft.mass()), RowLevel::Essential});
  rows.push_back({"model", constitutiveModelName(soft.elasticity().model), RowLevel::Useful});
  rows.push_back({"Lame mu, lambda", format("%.3g Pa, %.3g Pa", soft.elasticity().lame.mu, soft.elasticity().lame.lambda), RowLevel::Detail});
  std::string integrator = softIntegratorName(soft.integrator());
  if (soft.integrator() == SoftIntegrator::BackwardEuler) integrator += format(", %.0f CG iterations", soft.lastIterations());
  rows.push_back({"soft integrator", integrator, RowLevel::Useful});
  rows.push_back({"stable explicit dt", format("%.3g s (dt %.3g s)", soft.stableTimeStep(), world.settings().timeStep), RowLevel::Detail});
  rows.push_back({"elastic energy", format("%.4g J", soft.elasticEnergy()), RowLevel::Essential});
  rows.push_back({"kinetic energy (soft)", format("%.4g J", soft.kineticEnergy()), RowLevel::Useful});
}

}  // namespace rbsim::app

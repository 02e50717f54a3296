#include "run/particle_view.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "rbsim/world/systems.h"
#include "run/to_glm.h"

namespace rbsim::app {

namespace {

render::SpriteBatch spritesOf(const ParticleSystem& system, const ParticleLook& look, const glm::vec3& eye) {
  render::SpriteBatch batch;
  batch.additive = look.blend == ParticleLook::Blend::Additive;
  const ParticleStore& p = system.particles();
  batch.sprites.reserve(p.count());
  const glm::vec3 end = toGlm(look.colorEnd);
  for (std::size_t i = 0; i < p.count(); ++i) {
    if (!(p.size[i] > 0.0f)) continue;  // cloth nodes are drawn as the surface
    // Age fraction in [0, 1]: 0 for the immortal.
    const float a = std::isfinite(p.lifetime[i]) ? static_cast<float>(std::min(1.0, p.age[i] / p.lifetime[i])) : 0.0f;
    const glm::vec3 birth(p.color[i].x(), p.color[i].y(), p.color[i].z());
    render::Sprite s;
    s.position = toGlm(p.position[i]);
    s.size = p.size[i] * (1.0f + a * (static_cast<float>(look.sizeEndScale) - 1.0f));
    const glm::vec3 rgb = look.hasColorEnd ? birth + a * (end - birth) : birth;
    const float alpha = static_cast<float>(look.alphaStart + a * (look.alphaEnd - look.alphaStart));
    s.color = glm::vec4(rgb, alpha);
    batch.sprites.push_back(s);
  }
  if (!batch.additive) {  // farthest first, so each covers only what is behind it
    const auto distance2 = [&eye](const render::Sprite& s) {
      const glm::vec3 d = s.position - eye;
      return glm::dot(d, d);
    };
    std::sort(batch.sprites.begin(), batch.sprites.end(),
              [&](const render::Sprite& x, const render::Sprite& y) { return distance2(x) > distance2(y); });
  }
  return batch;
}

render::BodyView clothOf(const ParticleSystem& system) {
  render::BodyView view;
  const ParticleStore& p = system.particles();
  view.worldVertices.reserve(p.count());
  for (std::size_t i = 0; i < p.count(); ++i) view.worldVertices.push_back(toGlm(p.position[i]));
  view.triangles = &system.clothTriangles();
  view.color = toGlm(system.def().cloth.color);
  view.axisLength = 0.0f;
  view.smooth = true;
  return view;
}

}  // namespace

void addParticleView(const World& world, const Scene& scene, render::FrameData& frame) {
  const auto& systems = particleSystems(world);
  for (std::size_t k = 0; k < systems.size(); ++k) {
    const ParticleSystem& system = systems[k];
    const ParticleLook look = k < scene.particleLooks.size() ? scene.particleLooks[k] : ParticleLook{};
    if (system.def().cloth.enabled) frame.bodies.push_back(clothOf(system));
    render::SpriteBatch batch = spritesOf(system, look, frame.camera.eye);
    if (!batch.sprites.empty()) frame.sprites.push_back(std::move(batch));
    std::string value = std::to_string(system.particles().count()) + " live, " + std::to_string(system.emitted()) +
                        " born, " + particleIntegratorName(system.def().integrator);
    if (system.lost() > 0) value += ", " + std::to_string(system.lost()) + " refused (full)";
    frame.overlay.rows.push_back({"particles " + system.def().name, value, render::RowLevel::Essential});
  }
}

}  // namespace rbsim::app

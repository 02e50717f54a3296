#include "run/compare_view.h"

#include <algorithm>
#include <iterator>

#include <glm/glm.hpp>

#include "render/projection.h"
#include "run/frame_builder.h"
#include "run/to_glm.h"

namespace rbsim::app {

namespace {

// buildFrame's overlay starts with "time t" and "integrator"; a comparison's rows follow them.
constexpr std::ptrdiff_t kLeadingRows = 2;

// Everything a world's frame draws in world space, moved by `d` [m].
void shift(render::FrameData& frame, const glm::vec3& d) {
  for (render::BodyView& body : frame.bodies) {
    for (glm::vec3& p : body.worldVertices) p += d;
    body.position += d;
  }
  for (render::ForceArrow& arrow : frame.forces) arrow.point += d;
  for (render::DebugLine& line : frame.lines) {
    line.a += d;
    line.b += d;
  }
  for (render::DebugPoint& point : frame.points) point.position += d;
  for (render::SpriteBatch& batch : frame.sprites) {
    for (render::Sprite& sprite : batch.sprites) sprite.position += d;
  }
}

template <typename T>
void append(std::vector<T>& to, std::vector<T>&& from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// Where a world point lands on the image, in pixels from the top left; false behind the camera.
bool toPixel(const glm::mat4& viewProj, const glm::vec3& p, int width, int height, glm::vec2& pixel) {
  const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
  if (clip.w <= 0.0f) return false;
  pixel = glm::vec2((0.5f + 0.5f * clip.x / clip.w) * static_cast<float>(width),
                    (0.5f - 0.5f * clip.y / clip.w) * static_cast<float>(height));
  return true;
}

// The selected body in every world, quantity by quantity, so the values stand one under the
// other: "x  PGS", "x  soft step", "v  PGS", ... (KE: kinetic energy, a short label keeps the
// panel narrow enough to leave the worlds in view)
std::vector<std::pair<std::string, std::string>> selectedBodyRows(const std::vector<World>& worlds, const Phase& phase,
                                                                  const std::vector<FreeFlightError>* freeFlight) {
  const Scene& scene = phase.scene();
  const std::size_t i = scene.view.selected;
  std::vector<std::pair<std::string, std::string>> rows = {{"compared", phase.compareKey}};
  if (i >= worlds.front().bodies().size()) return rows;  // a scene of particles alone has no bodies
  const RigidBody& body = worlds.front().bodies()[i];
  rows.push_back({"body", body.name() + " (" + scene.inertiaMethods[i] + " inertia, " + formatNumber(body.mass(), "kg") + ")"});
  const auto add = [&](const char* name, auto value) {
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      if (i < worlds[k].bodies().size()) rows.push_back({std::string(name) + "  " + phase.worlds[k].label, value(worlds[k].bodies()[i])});
    }
  };
  add("x", [](const RigidBody& b) { return formatVec(b.position(), "m"); });
  add("v", [](const RigidBody& b) { return formatVec(b.velocity(), "m/s"); });
  add("omega", [](const RigidBody& b) { return formatVec(b.angularVelocity(), "rad/s"); });
  add("KE", [](const RigidBody& b) { return formatNumber(b.kineticEnergy(), b.awake() ? "J" : "J (asleep)"); });
  if (freeFlight != nullptr) {
    for (std::size_t k = 0; k < worlds.size() && k < freeFlight->size(); ++k) {
      rows.push_back({"vs exact spin  " + phase.worlds[k].label, formatFreeFlightError((*freeFlight)[k].read(worlds[k]))});
    }
  }
  return rows;
}

}  // namespace

render::FrameData buildPhaseFrame(const std::vector<World>& worlds, const Phase& phase, const std::string& demoTitle,
                                  const std::vector<FreeFlightError>* freeFlight) {
  const FreeFlightError* first = freeFlight != nullptr && !freeFlight->empty() ? &freeFlight->front() : nullptr;
  if (!phase.compared()) return buildFrame(worlds.front(), phase.scene(), demoTitle, true, first);
  render::FrameData frame = buildFrame(worlds.front(), phase.scene(), demoTitle, /*selectedBodyRows=*/false);
  shift(frame, toGlm(phase.worlds.front().offset));
  for (std::size_t k = 1; k < worlds.size(); ++k) {
    render::FrameData other = buildFrame(worlds[k], phase.worlds[k].scene, demoTitle);
    shift(other, toGlm(phase.worlds[k].offset));
    for (render::BodyView& body : other.bodies) body.selected = false;  // the panel follows world 0
    append(frame.bodies, std::move(other.bodies));
    append(frame.forces, std::move(other.forces));
    append(frame.lines, std::move(other.lines));
    append(frame.points, std::move(other.points));
    append(frame.sprites, std::move(other.sprites));
  }

  const ViewDesc& view = phase.scene().view;
  const glm::mat4 viewProj = render::viewProjection(frame.camera, view.width, view.height);
  for (const PhaseWorld& world : phase.worlds) {
    render::OverlayLabel label{world.label, glm::vec2(0.0f)};
    if (toPixel(viewProj, toGlm(world.labelAnchor), view.width, view.height, label.pixel)) {
      frame.overlay.labels.push_back(label);
    }
  }
  // After "time t" and "integrator" (buildFrame's first rows), before any debug view's rows.
  const std::vector<std::pair<std::string, std::string>> rows = selectedBodyRows(worlds, phase, freeFlight);
  auto& all = frame.overlay.rows;
  all.insert(all.begin() + std::min<std::ptrdiff_t>(kLeadingRows, static_cast<std::ptrdiff_t>(all.size())), rows.begin(), rows.end());
  return frame;
}

}  // namespace rbsim::app

#include "run/planar_view.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "rbsim/world/systems.h"

namespace rbsim::app {

namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// The triangles of a prism over an n-gon: vertices 0..n-1 the front face (z > 0), n..2n-1 the
// back. Shared by every frame, so the pointer in BodyView stays valid.
const Triangles& prismTriangles(std::size_t n) {
  static std::map<std::size_t, Triangles> cache;
  Triangles& t = cache[n];
  if (!t.empty()) return t;
  const auto u = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
  for (std::size_t i = 1; i + 1 < n; ++i) {
    t.push_back({u(0), u(i), u(i + 1)});              // front, counter-clockwise seen from +z
    t.push_back({u(n), u(n + i + 1), u(n + i)});      // back, seen from -z
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    t.push_back({u(i), u(n + i), u(n + j)});
    t.push_back({u(i), u(n + j), u(j)});
  }
  return t;
}

}  // namespace

void addPlanarView(const World& world, const Scene& scene, render::FrameData& frame) {
  const PlanarWorld* planar = planarWorld(world);
  if (planar == nullptr) return;
  const float half = static_cast<float>(0.5 * scene.planarDepth);
  for (std::size_t b = 0; b < planar->bodies().size(); ++b) {
    const PlanarBody& body = planar->bodies()[b];
    const std::size_t n = body.polygon().size();
    render::BodyView view;
    for (float z : {half, -half}) {
      for (std::size_t i = 0; i < n; ++i) {
        const Vec2 c = body.corner(i);
        view.worldVertices.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()), z);
      }
    }
    view.triangles = &prismTriangles(n);
    view.position = glm::vec3(static_cast<float>(body.state().position.x()), static_cast<float>(body.state().position.y()), 0.0f);
    const float c = std::cos(static_cast<float>(body.state().angle)), s = std::sin(static_cast<float>(body.state().angle));
    view.rotation = glm::mat3(glm::vec3(c, s, 0.0f), glm::vec3(-s, c, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    const Vec3& color = scene.planarColors[b];
    view.color = glm::vec3(static_cast<float>(color.x()), static_cast<float>(color.y()), static_cast<float>(color.z()));
    view.axisLength = 0.0f;
    frame.bodies.push_back(std::move(view));
  }
  // The ground lines, drawn over a stretch either side of their point nearest the origin.
  constexpr double kLineHalfLength = 8.0;  // [m]
  constexpr glm::vec3 kLineColor{0.95f, 0.95f, 0.95f};
  for (const PlanarLine& line : planar->lines()) {
    const Vec2 base = line.offset * line.normal, along(-line.normal.y(), line.normal.x());
    const Vec2 a = base - kLineHalfLength * along, b = base + kLineHalfLength * along;
    for (float z : {half, -half}) {
      frame.lines.push_back({glm::vec3(static_cast<float>(a.x()), static_cast<float>(a.y()), z),
                             glm::vec3(static_cast<float>(b.x()), static_cast<float>(b.y()), z), kLineColor, false});
    }
  }
  if (planar->bodies().empty()) return;
  const PlanarBody& first = planar->bodies().front();
  char text[128];
  std::snprintf(text, sizeof text, "%s (%.3g kg, I %.3g kg m^2)", first.name().c_str(), first.mass(), first.inertia());
  frame.overlay.rows.push_back({"2D body", text, render::RowLevel::Essential});
  std::snprintf(text, sizeof text, "%+.4f %+.4f m", first.state().position.x(), first.state().position.y());
  frame.overlay.rows.push_back({"x", text, render::RowLevel::Essential});
  std::snprintf(text, sizeof text, "%+.4f rad", first.state().angle);
  frame.overlay.rows.push_back({"theta", text, render::RowLevel::Essential});
  std::snprintf(text, sizeof text, "%+.4f rad/s", first.angularVelocity());
  frame.overlay.rows.push_back({"omega", text, render::RowLevel::Useful});
  std::snprintf(text, sizeof text, "%+.4f kg m^2/s", first.state().angularMomentum);
  frame.overlay.rows.push_back({"L = I omega", text, render::RowLevel::Useful});
  double energy = 0.0;
  for (const PlanarBody& body : planar->bodies()) energy += body.kineticEnergy();
  std::snprintf(text, sizeof text, "%zu bodies, %zu contact points", planar->bodies().size(), planar->contacts().size());
  frame.overlay.rows.push_back({"2D world", text, render::RowLevel::Useful});
  std::snprintf(text, sizeof text, "%.4g J", energy);
  frame.overlay.rows.push_back({"kinetic energy (2D)", text, render::RowLevel::Useful});
}

}  // namespace rbsim::app

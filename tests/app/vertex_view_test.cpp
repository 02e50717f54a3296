// view.vertices (seed 004 section 2, "do this transform yourself"): the dots are the engine's own
// vertex list p' = R p + x, and the body the renderer draws, from those vertices (demo 2,
// view.instancing false) or from R and x (an instance, in the vertex shader), covers exactly the
// polygon those vertices span on the image.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "run/paths.h"
#include "render/offscreen_renderer.h"
#include "render/projection.h"
#include "render/scene_geometry.h"
#include "run/frame_builder.h"
#include "run/phase.h"
#include "run/runner.h"

namespace rbsim::app {
namespace {

// Where a world point lands, in pixels from the top left.
glm::vec2 pixelOf(const render::Camera& camera, int width, int height, const glm::vec3& p) {
  const glm::vec4 clip = render::viewProjection(camera, width, height) * glm::vec4(p, 1.0f);
  return {(0.5f + 0.5f * clip.x / clip.w) * static_cast<float>(width), (0.5f - 0.5f * clip.y / clip.w) * static_cast<float>(height)};
}

// The convex hull of points (Andrew's monotone chain), counter-clockwise in image coordinates.
std::vector<glm::vec2> hull(std::vector<glm::vec2> p) {
  std::sort(p.begin(), p.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto cross = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

bool inside(const std::vector<glm::vec2>& h, const glm::vec2& q) {
  for (std::size_t i = 0; i < h.size(); ++i) {
    const glm::vec2 a = h[i], b = h[(i + 1) % h.size()];
    if ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) < 0.0f) return false;
  }
  return true;
}

// Distance from q to the polygon's boundary [px].
float edgeDistance(const std::vector<glm::vec2>& h, const glm::vec2& q) {
  float best = INFINITY;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const glm::vec2 a = h[i], b = h[(i + 1) % h.size()];
    const float t = std::clamp(glm::dot(q - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
    best = std::min(best, glm::length(q - (a + t * (b - a))));
  }
  return best;
}

// The outline the renderer draws along a silhouette, and its antialiasing, reach this far [px].
constexpr float kOutlineReach = 2.5f;

TEST(VertexView, TheDrawnBodyCoversThePolygonOfTheEnginesVertexList) {
  constexpr int kWidth = 960, kHeight = 540;
  // Demo 2 draws from the vertex list itself (view.instancing false); instanced, the renderer
  // must draw the same polygon from R and x.
  Phase phase = loadPhase(assetDir() + "/scenes/assignment2_a_manual_pose.json",
                          {"view.size=[960,540]", "view.overlay=false", "view.axes=false", "view.grid=false"});
  ASSERT_FALSE(phase.scene().view.instancing);
  ASSERT_FALSE(render::drawnAsInstance(buildFrame(buildWorld(phase.scene()), phase.scene(), "").bodies[0]));
  phase = loadPhase(assetDir() + "/scenes/assignment2_a_manual_pose.json",
                    {"view.size=[960,540]", "view.overlay=false", "view.axes=false", "view.grid=false", "view.instancing=true"});
  const Scene& scene = phase.scene();
  ASSERT_TRUE(scene.view.vertices);
  render::OffscreenRenderer renderer(kWidth, kHeight, render::defaultShaderDir());
  // The scene without the box (the camera stands still): what the box covers differs from it.
  render::FrameData empty = buildFrame(buildWorld(scene), scene, "");
  empty.points.clear();
  empty.bodies.clear();
  const std::vector<std::uint8_t> without = renderer.render(empty);
  // Not selected, the box is an instance: its mesh is uploaded at its first frame and every later
  // frame places it by that frame's R and x alone. Selected, it is drawn from its vertex list.
  for (const bool selected : {false, true}) {
    World world = buildWorld(scene);
    // The start, and each pose set by hand at t = 1, 2, 3 s.
    for (const double t : {0.5, 1.5, 2.5, 3.5}) {
      while (world.time() < t) world.step();
      const RigidBody& box = world.bodies()[0];
      render::FrameData frame = buildFrame(world, scene, "");
      ASSERT_EQ(frame.points.size(), box.vertexCount());
      for (std::size_t i = 0; i < box.vertexCount(); ++i) {
        const Vec3 p = box.rotation() * box.bodyVertex(i) + box.position();  // p' = R p + x
        EXPECT_NEAR(frame.points[i].position.x, p.x(), 1e-6);
        EXPECT_NEAR(frame.points[i].position.y, p.y(), 1e-6);
        EXPECT_NEAR(frame.points[i].position.z, p.z(), 1e-6);
      }
      std::vector<glm::vec2> projected;
      for (const render::DebugPoint& p : frame.points) projected.push_back(pixelOf(frame.camera, kWidth, kHeight, p.position));
      const std::vector<glm::vec2> polygon = hull(projected);
      frame.points.clear();  // the body alone
      frame.bodies[0].selected = selected;
      ASSERT_EQ(render::drawnAsInstance(frame.bodies[0]), !selected);
      const std::vector<std::uint8_t> withBody = renderer.render(frame);
      // Every pixel inside the vertices' polygon is the body's, and the body reaches no farther
      // out than its outline: a transform other than the engine's would leave part of either.
      long inPolygon = 0, missing = 0, beyond = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const std::size_t at = 4 * (static_cast<std::size_t>(y) * kWidth + x);
          int diff = 0;
          for (int c = 0; c < 3; ++c) diff += std::abs(withBody[at + c] - without[at + c]);
          const bool body = diff > 30;
          const glm::vec2 q(x + 0.5f, y + 0.5f);
          const bool in = inside(polygon, q);
          const bool nearEdge = edgeDistance(polygon, q) <= kOutlineReach;
          inPolygon += in ? 1 : 0;
          missing += in && !body && !nearEdge ? 1 : 0;
          beyond += !in && body && !nearEdge ? 1 : 0;
        }
      }
      ASSERT_GT(inPolygon, 2000) << "t = " << t;
      EXPECT_EQ(missing, 0) << inPolygon << " pixels in the polygon at t = " << t << ", selected " << selected;
      EXPECT_EQ(beyond, 0) << inPolygon << " pixels in the polygon at t = " << t << ", selected " << selected;
    }
  }
}

}  // namespace
}  // namespace rbsim::app

// Bodies that name a shared mesh are drawn as instances (R, x applied on the GPU) instead of from
// their world vertices: the picture must be the same one, up to float rounding on edge pixels.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "render/offscreen_renderer.h"
#include "render/scene_geometry.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kInstancingWidth = 320;
constexpr int kInstancingHeight = 180;
// A pixel counts as different beyond this (8-bit channels): an edge pixel whose coverage moved
// by a rounding step changes by a few levels; a missing or misplaced face changes by ~100.
constexpr int kChannelTolerance = 16;
// Edge pixels may flip between the two paths (float R p + x on the GPU against the same sum done
// on the CPU); at most this fraction of the image.
constexpr double kMaxDifferentFraction = 0.002;

glm::mat3 rotationAbout(const glm::vec3& axis, float radians) {
  return glm::mat3(glm::rotate(glm::mat4(1.0f), radians, glm::normalize(axis)));
}

// A pile of rotated boxes of two meshes and two colours, with shadows and outlines on; the
// first body is selected (drawn by the world-vertex path even when it has a mesh). Empty meshes:
// every body is drawn from its world vertices.
FrameData boxes(const std::shared_ptr<const void>& meshA, const std::shared_ptr<const void>& meshB) {
  FrameData frame;
  frame.options.overlay = false;
  frame.options.axes = true;
  for (int i = 0; i < 12; ++i) {
    const bool big = i % 3 == 0;
    const glm::vec3 half = big ? glm::vec3(0.4f, 0.25f, 0.3f) : glm::vec3(0.2f);
    const glm::vec3 centre(-2.0f + 0.4f * static_cast<float>(i), 0.3f + 0.15f * static_cast<float>(i % 4),
                           -1.0f + 0.2f * static_cast<float>(i % 5));
    BodyView body = makeBox(centre, half, rotationAbout({1.0f, 2.0f, 0.5f + i}, 0.4f * i),
                            i % 2 == 0 ? glm::vec3(0.85f, 0.3f, 0.2f) : glm::vec3(0.25f, 0.45f, 0.85f));
    body.selected = i == 0;
    body.mesh = big ? meshA : meshB;
    frame.bodies.push_back(std::move(body));
  }
  return frame;
}

int differentPixels(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  int count = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::abs(static_cast<int>(a[i + c]) - static_cast<int>(b[i + c])) > kChannelTolerance) {
        ++count;
        break;
      }
    }
  }
  return count;
}

TEST(Instancing, OnlyOpaqueUnselectedRigidBodiesWithAMeshAreInstances) {
  BodyView body = makeBox(glm::vec3(0.0f), glm::vec3(0.5f), glm::mat3(1.0f), glm::vec3(0.5f));
  EXPECT_FALSE(drawnAsInstance(body));  // no mesh: a one-off shape
  body.mesh = std::make_shared<int>(0);
  EXPECT_TRUE(drawnAsInstance(body));
  BodyView ghost = body, cloth = body, selected = body, hidden = body;
  ghost.opacity = 0.5f;
  cloth.smooth = true;
  selected.selected = true;
  hidden.opacity = 0.0f;
  EXPECT_FALSE(drawnAsInstance(ghost));
  EXPECT_FALSE(drawnAsInstance(cloth));
  EXPECT_FALSE(drawnAsInstance(selected));
  EXPECT_FALSE(drawnAsInstance(hidden));
}

TEST(Instancing, BodyShapeIsTheMeshInBodySpace) {
  const glm::vec3 half(0.4f, 0.25f, 0.3f);
  const BodyView body = makeBox({1.0f, 2.0f, -3.0f}, half, rotationAbout({1.0f, 2.0f, 3.0f}, 0.9f), glm::vec3(0.5f));
  std::vector<MeshVertex> triangles;
  std::vector<LineVertex> edges;
  buildBodyShape(body, triangles, edges);
  ASSERT_EQ(triangles.size(), 36u);  // 12 triangles
  EXPECT_EQ(edges.size(), 24u);      // the 12 box edges; face diagonals are no creases
  for (const MeshVertex& v : triangles) {
    // Every corner is back at (+-hx, +-hy, +-hz) to float rounding of R^T (p' - x).
    EXPECT_NEAR(std::abs(v.position.x), half.x, 1e-5f);
    EXPECT_NEAR(std::abs(v.position.y), half.y, 1e-5f);
    EXPECT_NEAR(std::abs(v.position.z), half.z, 1e-5f);
  }
}

TEST(Instancing, DrawsTheSamePictureAsWorldVertices) {
  OffscreenRenderer renderer(kInstancingWidth, kInstancingHeight, shaderDir());
  FrameData empty;
  empty.options.overlay = false;
  const std::vector<std::uint8_t> background = renderer.render(empty);
  // Stand-ins for the engine's meshes: only their identity counts.
  const std::shared_ptr<const void> meshA = std::make_shared<int>(1), meshB = std::make_shared<int>(2);
  const std::vector<std::uint8_t> worldPath = renderer.render(boxes(nullptr, nullptr));
  const std::vector<std::uint8_t> instanced = renderer.render(boxes(meshA, meshB));
  const int pixels = kInstancingWidth * kInstancingHeight;
  // The boxes are in the picture at all (so equality below says something).
  ASSERT_GT(differentPixels(background, worldPath), pixels / 50);
  EXPECT_LE(differentPixels(worldPath, instanced), static_cast<int>(kMaxDifferentFraction * pixels));
  // A second instanced frame reuses the uploaded meshes and must not drift.
  const std::vector<std::uint8_t> again = renderer.render(boxes(meshA, meshB));
  EXPECT_EQ(differentPixels(instanced, again), 0);
}

}  // namespace
}  // namespace rbsim::render::test

// The image must agree with projective geometry: a box rendered by the GL pipeline lands where
// glm::perspective * glm::lookAt says its centre and corners go.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kProjectionWidth = 320;
constexpr int kProjectionHeight = 240;

// The test box is green: nothing else in the scene (blue-grey sky and ground, red/blue world
// axis lines, black shadow) is, so "green" means "box".
bool isBoxColoured(const Rgb& p) {
  return p.g > 40 && p.g > 1.4 * p.r && p.g > 1.4 * p.b;
}

FrameData boxFrame(bool withBox) {
  FrameData frame;
  frame.camera.eye = {3.0f, 2.5f, 4.0f};
  frame.camera.target = {-0.5f, 0.3f, 0.4f};  // box off-centre: a wrong zoom would shift it
  frame.camera.fovYDegrees = 45.0f;
  frame.options.overlay = false;
  frame.options.axes = false;
  frame.options.grid = true;
  if (withBox) {
    const glm::mat3 rotation =
        glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0)));
    frame.bodies.push_back(makeBox({0.6f, 0.5f, -0.5f}, glm::vec3(0.5f), rotation,
                                   {0.10f, 0.80f, 0.15f}));
  }
  return frame;
}

TEST(Projection, BoxLandsWhereTheCameraMathsSays) {
  OffscreenRenderer renderer(kProjectionWidth, kProjectionHeight, shaderDir());
  const FrameData frame = boxFrame(true);
  const std::vector<std::uint8_t> image = renderer.render(frame);
  const std::vector<std::uint8_t> empty = renderer.render(boxFrame(false));
  ASSERT_EQ(image.size(), static_cast<std::size_t>(kProjectionWidth * kProjectionHeight * 4));

  // Projected centre: inside the silhouette of a convex body, so box-coloured.
  const BodyView& box = frame.bodies[0];
  const glm::vec2 centre = projectToPixel(frame.camera, kProjectionWidth, kProjectionHeight, box.position);
  const Rgb atCentre = pixelAt(image, kProjectionWidth, static_cast<int>(centre.x),
                               static_cast<int>(centre.y));
  EXPECT_TRUE(isBoxColoured(atCentre))
      << "centre pixel (" << centre.x << ", " << centre.y << ") is " << atCentre.r << ","
      << atCentre.g << "," << atCentre.b;

  // Bounding rectangle of the 8 projected corners (continuous pixel coordinates).
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& corner : box.worldVertices) {
    const glm::vec2 p = projectToPixel(frame.camera, kProjectionWidth, kProjectionHeight, corner);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  ASSERT_GT(lo.x, 4.0f);
  ASSERT_GT(lo.y, 4.0f);
  ASSERT_LT(hi.x, kProjectionWidth - 4.0f);
  ASSERT_LT(hi.y, kProjectionHeight - 4.0f);

  // Bounding box of the box-coloured pixels; pixel i covers [i, i + 1).
  int minX = kProjectionWidth, minY = kProjectionHeight, maxX = -1, maxY = -1;
  for (int y = 0; y < kProjectionHeight; ++y) {
    for (int x = 0; x < kProjectionWidth; ++x) {
      if (!isBoxColoured(pixelAt(image, kProjectionWidth, x, y))) continue;
      minX = std::min(minX, x);
      maxX = std::max(maxX, x);
      minY = std::min(minY, y);
      maxY = std::max(maxY, y);
    }
  }
  SCOPED_TRACE(::testing::Message() << "projected corners x [" << lo.x << ", " << hi.x << "] y ["
                                    << lo.y << ", " << hi.y << "]; box pixels x [" << minX
                                    << ", " << maxX + 1 << "] y [" << minY << ", " << maxY + 1
                                    << "]");
  EXPECT_NEAR(minX, lo.x, 2.0);
  EXPECT_NEAR(maxX + 1, hi.x, 2.0);
  EXPECT_NEAR(minY, lo.y, 2.0);
  EXPECT_NEAR(maxY + 1, hi.y, 2.0);

  // Well outside the rectangle: the same background and grid as the empty scene, at most
  // darkened (the box's shadow on the ground), never box-coloured.
  int outside = 0;
  for (int y = 0; y < kProjectionHeight; ++y) {
    for (int x = 0; x < kProjectionWidth; ++x) {
      if (x > lo.x - 5 && x < hi.x + 5 && y > lo.y - 5 && y < hi.y + 5) continue;
      const Rgb p = pixelAt(image, kProjectionWidth, x, y);
      const Rgb e = pixelAt(empty, kProjectionWidth, x, y);
      ++outside;
      ASSERT_FALSE(isBoxColoured(p)) << "at " << x << "," << y;
      ASSERT_TRUE(p.r <= e.r + 2 && p.g <= e.g + 2 && p.b <= e.b + 2)
          << "at " << x << "," << y << ": " << p.r << "," << p.g << "," << p.b << " vs empty "
          << e.r << "," << e.g << "," << e.b;
    }
  }
  EXPECT_GT(outside, kProjectionWidth * kProjectionHeight / 2);
}

TEST(Projection, MovingTheBoxMovesItsPixelsByTheProjectedAmount) {
  // A physics-facing check: translate the body 0.8 m along x, as a step of the engine would,
  // and the box-coloured centroid must follow the projected centre.
  OffscreenRenderer renderer(kProjectionWidth, kProjectionHeight, shaderDir());
  FrameData frame = boxFrame(true);
  for (const float dx : {0.0f, 0.8f}) {
    FrameData moved = frame;
    BodyView& box = moved.bodies[0];
    for (glm::vec3& v : box.worldVertices) v.x += dx;
    box.position.x += dx;
    const std::vector<std::uint8_t>& image = renderer.render(moved);
    glm::dvec2 sum(0.0);
    long count = 0;
    for (int y = 0; y < kProjectionHeight; ++y) {
      for (int x = 0; x < kProjectionWidth; ++x) {
        if (isBoxColoured(pixelAt(image, kProjectionWidth, x, y))) {
          sum += glm::dvec2(x + 0.5, y + 0.5);
          ++count;
        }
      }
    }
    ASSERT_GT(count, 100);
    const glm::vec2 expected = projectToPixel(moved.camera, kProjectionWidth, kProjectionHeight, box.position);
    // The area centroid of a projected cube sits near, not exactly at, its projected centre.
    EXPECT_NEAR(sum.x / count, expected.x, 4.0) << "dx = " << dx;
    EXPECT_NEAR(sum.y / count, expected.y, 4.0) << "dx = " << dx;
  }
}

}  // namespace
}  // namespace rbsim::render::test

// The depth and segmentation images (issue 57) against projective geometry: a plane seen head-on
// reads its distance at every pixel, a box seen face-on covers exactly the pixel centres inside
// its projected front face, see-through bodies are in neither image, and asking for the images
// leaves the colour image as it was.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "render/offscreen_renderer.h"
#include "render/projection.h"
#include "render/segmentation_pass.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr double kDepthStep = 1.0 / 16777215.0;  // one step of the 24-bit depth buffer (window depth)
// A surface's depth is within 2 steps: one for rounding to 24 bits, one for the float32 depth the
// vertex shader computes, whose ulp near 1 is a step as well (0.25 to 1.5 steps measured, eye 0.5
// to 50 m above the ground: tests/python/test_render.py).
constexpr double kSurfaceSteps = 2.0;
// The colour pass draws bodies with glPolygonOffset(1, 1), so their outlines win the depth test:
// a face seen head-on is pushed back by the implementation's "smallest resolvable offset" r, which
// the GL spec leaves to the driver; llvmpipe's is 3 steps of a 24-bit buffer (measured here: 3.02).
constexpr double kBodyOffsetSteps = 3.0;

// `steps` steps of the depth buffer at distance z [m] (dz/dd = z^2 (f - n) / (f n)), and the float32
// the image stores (half an ulp of z).
double depthResolution(double z, const Camera& c, double steps = kSurfaceSteps) {
  const double n = c.nearPlane, f = c.farPlane;
  return steps * z * z * (f - n) / (f * n) * kDepthStep + 0.5 * z * std::ldexp(1.0, -23);
}

Camera lookingAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
  Camera camera;
  camera.eye = eye;
  camera.target = target;
  camera.up = up;
  return camera;
}

TEST(LinearDepth, InvertsTheProjectionsDepthAndGivesInfinityForNoSurface) {
  const Camera c;
  const glm::mat4 p = glm::perspective(glm::radians(c.fovYDegrees), 1.5f, c.nearPlane, c.farPlane);
  for (const double z : {0.05, 0.3, 5.0, 60.0, 199.0}) {
    // The window depth the matrix gives a point at distance z: z_ndc = -P22 + P32 / z.
    const double d = 0.5 * (-static_cast<double>(p[2][2]) + static_cast<double>(p[3][2]) / z) + 0.5;
    EXPECT_NEAR(linearDepth(d, c.nearPlane, c.farPlane), z, 1e-6 * z) << z;
  }
  EXPECT_NEAR(linearDepth(0.0, c.nearPlane, c.farPlane), c.nearPlane, 1e-7);
  EXPECT_TRUE(std::isinf(linearDepth(1.0, c.nearPlane, c.farPlane)));
}

// Whether a pixel of a segmentation image has a neighbour (of 8) showing another surface.
bool onEdge(const std::vector<std::int32_t>& segments, int x, int y) {
  const std::int32_t here = segments[static_cast<std::size_t>(y * kWidth + x)];
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int u = std::clamp(x + dx, 0, kWidth - 1), v = std::clamp(y + dy, 0, kHeight - 1);
      if (segments[static_cast<std::size_t>(v * kWidth + u)] != here) return true;
    }
  }
  return false;
}

class ExtraImagesAt : public ::testing::TestWithParam<int> {};  // samples per pixel

TEST_P(ExtraImagesAt, GroundSeenHeadOnReadsItsDistanceAtEveryPixel) {
  OffscreenRenderer renderer(kWidth, kHeight, shaderDir(), GetParam());
  FrameData frame;
  frame.options.overlay = false;
  constexpr float kHeightAbove = 4.0f;  // [m]
  frame.camera = lookingAt({0.3f, kHeightAbove, 0.2f}, {0.3f, 0.0f, 0.2f}, {0.0f, 0.0f, -1.0f});
  renderer.render(frame, nullptr, {true, true});
  const std::vector<float>& depth = renderer.depth();
  ASSERT_EQ(depth.size(), static_cast<std::size_t>(kWidth * kHeight));
  const double tolerance = depthResolution(kHeightAbove, frame.camera);
  double worst = 0.0;
  for (const float z : depth) worst = std::max(worst, std::abs(static_cast<double>(z) - kHeightAbove));
  EXPECT_LE(worst, tolerance) << "resolution " << tolerance << " m";
  for (const std::int32_t s : renderer.segmentation()) ASSERT_EQ(s, kSegmentGround);
}

TEST_P(ExtraImagesAt, BoxSeenFaceOnCoversThePixelCentresOfItsProjectedFace) {
  OffscreenRenderer renderer(kWidth, kHeight, shaderDir(), GetParam());
  FrameData frame;
  frame.options.overlay = false;
  frame.options.grid = false;  // sky all around: no surface but the box
  frame.camera = lookingAt({0.0f, 1.0f, 6.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
  const glm::vec3 centre(0.2f, 1.1f, 0.0f), half(0.5f, 0.3f, 0.4f);
  frame.bodies.push_back(makeBox(centre, half, glm::mat3(1.0f), {0.8f, 0.3f, 0.2f}));
  // A see-through body in front of it: drawn in the colour image, in neither of the others.
  BodyView ghost = makeBox({0.2f, 1.1f, 2.0f}, glm::vec3(0.2f), glm::mat3(1.0f), {0.2f, 0.8f, 0.3f});
  ghost.opacity = 0.4f;
  frame.bodies.push_back(ghost);
  renderer.render(frame, nullptr, {true, true});

  // The front face z = centre.z + half.z projects to a rectangle; a pixel is covered when its
  // centre is inside (GL's rasterisation rule).
  const glm::vec2 low = projectToPixel(frame.camera, kWidth, kHeight, centre + glm::vec3(-half.x, half.y, half.z));
  const glm::vec2 high = projectToPixel(frame.camera, kWidth, kHeight, centre + glm::vec3(half.x, -half.y, half.z));
  const auto centresInside = [](float from, float to) {  // pixel centres i + 0.5 in (from, to)
    return static_cast<int>(std::ceil(to - 0.5f)) - static_cast<int>(std::floor(from - 0.5f)) - 1;
  };
  const int columns = centresInside(low.x, high.x), rows = centresInside(low.y, high.y);
  const double faceDistance = frame.camera.eye.z - (centre.z + half.z);
  const double tolerance = depthResolution(faceDistance, frame.camera, kSurfaceSteps + kBodyOffsetSteps);
  int count = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      const std::int32_t s = renderer.segmentation()[i];
      const float z = renderer.depth()[i];
      ASSERT_TRUE(s == 0 || s == kSegmentBackground) << x << ", " << y << ": " << s;
      // The two images see the same surfaces; multisampled, an edge pixel's depth is one of its
      // samples', not its centre's.
      if (GetParam() == 1 || !onEdge(renderer.segmentation(), x, y)) {
        ASSERT_EQ(s == 0, std::isfinite(z)) << x << ", " << y;
      }
      if (s == 0 && std::isfinite(z)) {
        ++count;
        EXPECT_NEAR(z, faceDistance, tolerance) << x << ", " << y;
      }
    }
  }
  EXPECT_EQ(count, columns * rows);
  // And the count is the face's area in pixels, up to the pixels its edges cross.
  const double area = (high.x - low.x) * (high.y - low.y);
  EXPECT_LE(std::abs(count - area), (high.x - low.x) + (high.y - low.y) + 1.0);
}

TEST_P(ExtraImagesAt, LeaveTheColourImageAsItWas) {
  OffscreenRenderer renderer(kWidth, kHeight, shaderDir(), GetParam());
  FrameData frame;
  frame.overlay.title = "extra images";
  frame.overlay.rows = {{"time t", "0 s", RowLevel::Essential}};
  for (int i = 0; i < 3; ++i) {
    frame.bodies.push_back(makeBox({-1.0f + i, 0.4f, 0.0f}, glm::vec3(0.3f), glm::mat3(1.0f), {0.3f, 0.5f, 0.8f}));
  }
  frame.forces.push_back({{0.0f, 0.4f, 0.0f}, {0.0f, 20.0f, 0.0f}});
  const std::vector<std::uint8_t> plain = renderer.render(frame);
  EXPECT_TRUE(renderer.depth().empty() && renderer.segmentation().empty());
  const std::vector<std::uint8_t> withImages = renderer.render(frame, nullptr, {true, true});
  EXPECT_EQ(plain, withImages);
  EXPECT_EQ(renderer.render(frame), plain);  // and the state they leave changes no later frame
}

INSTANTIATE_TEST_SUITE_P(Samples, ExtraImagesAt, ::testing::Values(1, 4));

}  // namespace
}  // namespace rbsim::render::test

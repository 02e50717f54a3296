// Ghost bodies (opacity < 1) are see-through: their pixels are the blend of their own shaded
// colour and what lies behind, nearer ghosts over farther ones, and the CPU side sorts and splits
// them out of the opaque bodies.
#include <cmath>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render/scene_geometry.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kGhostWidth = 640;
constexpr int kGhostHeight = 360;

FrameData gridFrame() {
  FrameData frame;
  frame.options.grid = true;
  frame.options.axes = false;
  frame.options.overlay = false;
  return frame;
}

Rgb pixelOf(const std::vector<std::uint8_t>& image, const FrameData& frame, const glm::vec3& p) {
  const glm::vec2 at = projectToPixel(frame.camera, kGhostWidth, kGhostHeight, p);
  return pixelAt(image, kGhostWidth, static_cast<int>(at.x), static_cast<int>(at.y));
}

// Blending happens on the display values in the framebuffer: c = alpha * src + (1 - alpha) * dst.
Rgb blend(const Rgb& src, const Rgb& dst, double alpha) {
  const auto mix = [alpha](int s, int d) {
    return static_cast<int>(std::lround(alpha * s + (1.0 - alpha) * d));
  };
  return {mix(src.r, dst.r), mix(src.g, dst.g), mix(src.b, dst.b)};
}

::testing::AssertionResult near(const Rgb& actual, const Rgb& expected, int tolerance) {
  if (std::abs(actual.r - expected.r) <= tolerance && std::abs(actual.g - expected.g) <= tolerance &&
      std::abs(actual.b - expected.b) <= tolerance) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << actual.r << "," << actual.g << "," << actual.b << " is not within " << tolerance
         << " of " << expected.r << "," << expected.g << "," << expected.b;
}

int largestDifference(const Rgb& p, const Rgb& q) {
  return std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
}

TEST(Ghost, IsTheBlendOfItsColourAndTheGroundBehindIt) {
  OffscreenRenderer renderer(kGhostWidth, kGhostHeight, shaderDir());
  const FrameData empty = gridFrame();
  FrameData frame = gridFrame();
  frame.bodies.push_back(makeBox({0.0f, 0.5f, 0.0f}, glm::vec3(0.5f), glm::mat3(1.0f),
                                 {0.85f, 0.15f, 0.10f}));
  const std::vector<std::uint8_t> background = renderer.render(empty);
  const std::vector<std::uint8_t> opaque = renderer.render(frame);
  frame.bodies[0].opacity = 0.3f;
  const std::vector<std::uint8_t> ghost = renderer.render(frame);
  // Face centres the camera sees (+x, +y, +z), away from the outlines.
  for (const glm::vec3 p : {glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                            glm::vec3(0.0f, 0.5f, 0.5f)}) {
    SCOPED_TRACE(::testing::Message() << "face centre " << p.x << "," << p.y << "," << p.z);
    const Rgb body = pixelOf(opaque, frame, p);
    const Rgb behind = pixelOf(background, frame, p);
    const Rgb seen = pixelOf(ghost, frame, p);
    EXPECT_TRUE(near(seen, blend(body, behind, 0.3), 3));
    EXPECT_GT(largestDifference(seen, body), 20);    // not the opaque body
    EXPECT_GT(largestDifference(seen, behind), 20);  // not the background
  }
}

TEST(Ghost, NearerGhostIsBlendedOverTheFartherOneWhateverTheListOrder) {
  OffscreenRenderer renderer(kGhostWidth, kGhostHeight, shaderDir());
  const FrameData empty = gridFrame();
  // Both on the line from the default eye through the origin; `near` is half as far away.
  const glm::vec3 eye = empty.camera.eye;
  const glm::vec3 farCentre(0.0f, 0.5f, 0.0f);
  const glm::vec3 nearCentre = glm::mix(eye, farCentre, 0.5f);
  const BodyView nearBox = makeBox(nearCentre, glm::vec3(0.25f), glm::mat3(1.0f),
                                   {0.9f, 0.1f, 0.1f});
  const BodyView farBox = makeBox(farCentre, glm::vec3(0.5f), glm::mat3(1.0f),
                                  {0.1f, 0.2f, 0.9f});
  // The pixel just off the common centre, inside both silhouettes and clear of their edges.
  const glm::vec3 probe = nearCentre + glm::vec3(0.0f, 0.1f, 0.0f);
  const auto render = [&](std::vector<BodyView> bodies) {
    FrameData frame = gridFrame();
    frame.bodies = std::move(bodies);
    return pixelOf(renderer.render(frame), frame, probe);
  };
  const Rgb behind = pixelOf(renderer.render(empty), empty, probe);
  const Rgb nearColour = render({nearBox});
  const Rgb farColour = render({farBox});
  const Rgb expected = blend(nearColour, blend(farColour, behind, 0.4), 0.4);

  BodyView nearGhost = nearBox, farGhost = farBox;
  nearGhost.opacity = farGhost.opacity = 0.4f;
  EXPECT_TRUE(near(render({nearGhost, farGhost}), expected, 4)) << "near listed first";
  EXPECT_TRUE(near(render({farGhost, nearGhost}), expected, 4)) << "far listed first";
}

TEST(Ghost, GeometryKeepsGhostsApartSortedBackToFront) {
  FrameData frame;
  frame.camera.eye = {0.0f, 0.0f, 10.0f};
  const auto box = [](float z, float opacity) {
    BodyView body = makeBox({0.0f, 0.0f, z}, glm::vec3(0.5f), glm::mat3(1.0f), {1, 1, 1});
    body.opacity = opacity;
    return body;
  };
  frame.bodies = {box(5.0f, 0.5f), box(0.0f, 1.0f), box(-5.0f, 0.25f), box(2.0f, 0.0f)};
  SceneGeometry g;
  buildSceneGeometry(frame, g);
  EXPECT_EQ(g.bodies.size(), 36u);  // the one opaque box; opacity 0 draws nothing
  ASSERT_EQ(g.ghostRanges.size(), 2u);
  EXPECT_EQ(g.ghostRanges[0].opacity, 0.25f);  // z = -5: farthest from the eye, first
  EXPECT_EQ(g.ghostRanges[1].opacity, 0.5f);
  EXPECT_EQ(g.ghostRanges[1].first, 36);
  EXPECT_EQ(g.ghostRanges[1].count, 36);
  EXPECT_EQ(g.ghosts.size(), 72u);
  EXPECT_EQ(g.edges.size(), 24u);
  ASSERT_EQ(g.ghostEdges.size(), 48u);
  EXPECT_EQ(g.ghostEdges[0].color.a, 0.25f);  // outlines as faint as their ghost
}

}  // namespace
}  // namespace rbsim::render::test

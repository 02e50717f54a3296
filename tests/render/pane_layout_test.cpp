// A comparison's panes (pane_layout.h): they tile the image right of the info column without
// overlapping, their shape follows the image's, and a body drawn in pane k lands where the
// projection through pane k's own camera and rectangle puts it, and nowhere else.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render/pane_layout.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

bool overlap(const PaneRect& a, const PaneRect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

TEST(PaneLayout, PanesTileTheImageRightOfTheInfoColumnWithoutOverlapping) {
  for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{640, 480}, std::pair{1920, 1080}}) {
    for (std::size_t n = 1; n <= 8; ++n) {
      for (const bool info : {false, true}) {
        const std::vector<PaneRect> panes = paneLayout(n, width, height, info);
        ASSERT_EQ(panes.size(), n);
        const int left = info ? infoColumnWidth(width, height, PanelMode::Compact) : 0;
        long area = 0;
        for (std::size_t k = 0; k < n; ++k) {
          const PaneRect& p = panes[k];
          EXPECT_GE(p.x, std::min(left, width / 2));
          EXPECT_GE(p.y, 0);
          EXPECT_LE(p.x + p.width, width);
          EXPECT_LE(p.y + p.height, height);
          area += static_cast<long>(p.width) * p.height;
          for (std::size_t j = 0; j < k; ++j) EXPECT_FALSE(overlap(p, panes[j])) << n << " panes: " << j << ", " << k;
        }
        // The gaps take a few per cent; a grid with a cell to spare leaves it empty.
        const long free = static_cast<long>(width - std::min(left, width / 2)) * height;
        EXPECT_GT(static_cast<double>(area), (n == 1 || n == 2 || n == 4 ? 0.95 : 0.5) * static_cast<double>(free));
      }
    }
  }
  // Two worlds beside a 1280x720 full panel's column: one above the other, each nearly 16:9.
  const std::vector<PaneRect> two = paneLayout(2, 1280, 720, true, PanelMode::Full);
  EXPECT_EQ(two[0].x, two[1].x);
  EXPECT_LT(two[0].y + two[0].height, two[1].y);
  const double aspect = static_cast<double>(two[0].width) / two[0].height;
  EXPECT_NEAR(aspect, 16.0 / 9.0, 0.2);
  // Four without the column: a 2 x 2 grid of 16:9 panes.
  const std::vector<PaneRect> four = paneLayout(4, 1280, 720, false);
  EXPECT_EQ(four[0].y, four[1].y);
  EXPECT_EQ(four[0].x, four[2].x);
  EXPECT_NEAR(static_cast<double>(four[3].width) / four[3].height, 16.0 / 9.0, 0.05);
}

// A pane narrower than the image keeps the image's horizontal field of view.
TEST(PaneLayout, ANarrowPaneSeesAsWideAsTheImage) {
  Camera camera;
  camera.fovYDegrees = 45.0f;
  const PaneRect pane{0, 0, 320, 720};
  const Camera wide = paneCamera(camera, 1280, 720, pane);
  const double halfWidthImage = std::tan(glm::radians(22.5)) * 1280.0 / 720.0;
  const double halfWidthPane = std::tan(glm::radians(0.5 * wide.fovYDegrees)) * 320.0 / 720.0;
  EXPECT_NEAR(halfWidthPane, halfWidthImage, 1e-5);
  EXPECT_EQ(paneCamera(camera, 1280, 720, PaneRect{0, 0, 640, 360}).fovYDegrees, 45.0f);  // same shape
}

bool isGreen(const Rgb& p) { return p.g > 40 && p.g > 1.4 * p.r && p.g > 1.4 * p.b; }
bool paneIsRed(const Rgb& p) { return p.r > 40 && p.r > 1.4 * p.g && p.r > 1.4 * p.b; }

TEST(PaneLayout, EachPaneDrawsItsOwnWorldThroughItsOwnRectangle) {
  constexpr int kWidth = 480, kHeight = 270;
  FrameData frame;
  frame.options.overlay = false;
  frame.infoColumn = false;
  // World 0 has a green box on the left, world 1 a red one on the right.
  const glm::vec3 colours[2] = {{0.1f, 0.8f, 0.15f}, {0.85f, 0.1f, 0.1f}};
  const glm::vec3 centres[2] = {{-0.9f, 0.5f, 0.0f}, {0.9f, 0.5f, 0.0f}};
  for (std::size_t k = 0; k < 2; ++k) {
    FrameData pane;
    pane.options.overlay = false;
    pane.options.axes = false;
    pane.camera.eye = {0.0f, 1.5f, 6.0f};
    pane.camera.target = {0.0f, 0.5f, 0.0f};
    pane.bodies.push_back(makeBox(centres[k], glm::vec3(0.4f), glm::mat3(1.0f), colours[k]));
    frame.panes.push_back(pane);
  }
  const std::vector<PaneRect> rects = paneLayout(2, kWidth, kHeight, false);
  for (std::size_t k = 0; k < 2; ++k) frame.panes[k].camera = paneCamera(frame.panes[k].camera, kWidth, kHeight, rects[k]);
  OffscreenRenderer renderer(kWidth, kHeight, shaderDir());
  const std::vector<std::uint8_t> image = renderer.render(frame);
  // In pane k, world k's box is where pane k's projection puts it; the other world's is not.
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t w = 0; w < 2; ++w) {
      const glm::vec2 local = projectToPixel(frame.panes[k].camera, rects[k].width, rects[k].height, centres[w]);
      ASSERT_GT(local.x, 0.0f);
      ASSERT_LT(local.x, static_cast<float>(rects[k].width));
      const Rgb p = pixelAt(image, kWidth, rects[k].x + static_cast<int>(local.x), rects[k].y + static_cast<int>(local.y));
      const bool green = isGreen(p), red = paneIsRed(p);
      if (w == k) {
        EXPECT_TRUE(k == 0 ? green : red) << "pane " << k << " lacks its own box";
      } else {
        EXPECT_FALSE(green || red) << "pane " << k << " shows world " << w << "'s box";
      }
    }
  }
}

}  // namespace
}  // namespace rbsim::render::test

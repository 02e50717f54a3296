// The overlay panel must be in the very first frame (ImGui hides auto-sized windows on their
// first frame; the panel has a fixed size to avoid that) and must contain legible text.
#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kOverlayWidth = 320;
constexpr int kOverlayHeight = 240;

// Text is near-white (values), light grey-blue (labels) or gold (title); the sky behind the
// panel's top-left corner is dark blue, the panel itself near-black.
bool isTextColoured(const Rgb& p) {
  const bool light = p.r > 160 && p.g > 160 && p.b > 160;
  const bool gold = p.r > 190 && p.g > 150 && p.b < 140;
  return light || gold;
}

FrameData overlayFrame(bool overlay) {
  FrameData frame;
  frame.bodies.push_back(makeBox({0.0f, 0.5f, 0.0f}, glm::vec3(0.5f), glm::mat3(1.0f),
                                 {0.8f, 0.5f, 0.2f}));
  frame.options.overlay = overlay;
  frame.overlay.title = "Demo 2";
  frame.overlay.caption = "overlay test";
  frame.overlay.rows = {{"t [s]", "1.250"}, {"KE [J]", "12.345"}};
  return frame;
}

TEST(Overlay, PanelWithTextOnTheFirstFrame) {
  std::vector<std::uint8_t> with, without;
  {
    OffscreenRenderer renderer(kOverlayWidth, kOverlayHeight, shaderDir());
    with = renderer.render(overlayFrame(true));  // frame 1 of this renderer
    // The overlay must leave no GL state behind that changes the next frame.
    EXPECT_TRUE(renderer.render(overlayFrame(true)) == with) << "frame 2 differs from frame 1";
  }
  {
    OffscreenRenderer renderer(kOverlayWidth, kOverlayHeight, shaderDir());
    without = renderer.render(overlayFrame(false));
  }
  // The panel starts a few pixels from the top-left corner; look at the part where the title
  // and the first rows are, whatever the exact font metrics.
  int changed = 0, text = 0, textWithout = 0, total = 0;
  for (int y = 10; y < 50; ++y) {
    for (int x = 10; x < 100; ++x) {
      const Rgb a = pixelAt(with, kOverlayWidth, x, y);
      const Rgb b = pixelAt(without, kOverlayWidth, x, y);
      ++total;
      if (std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) > 12) ++changed;
      if (isTextColoured(a)) ++text;
      if (isTextColoured(b)) ++textWithout;
    }
  }
  EXPECT_GT(changed, total / 2) << "the panel background should cover the region";
  EXPECT_GT(text, 40) << "title and row text should be drawn";
  EXPECT_EQ(textWithout, 0) << "the same region without overlay has no text-like pixels";
  // Far from the panel nothing changes: the overlay does not disturb the 3D image.
  for (int y = kOverlayHeight - 40; y < kOverlayHeight; ++y) {
    for (int x = kOverlayWidth - 40; x < kOverlayWidth; ++x) {
      const Rgb a = pixelAt(with, kOverlayWidth, x, y);
      const Rgb b = pixelAt(without, kOverlayWidth, x, y);
      ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b) << "at " << x << "," << y;
    }
  }
}

// A caption pinned to a point (OverlayLabel, the worlds of a compared phase): drawn on the very
// first frame, its top centre at the point, in the title's gold, and drawn with no panel at all.
TEST(Overlay, LabelHangsBelowItsPointOnTheFirstFrame) {
  const glm::vec2 point(0.75f * kOverlayWidth, 0.6f * kOverlayHeight);  // right of and below the panel
  FrameData frame = overlayFrame(true);
  frame.overlay.labels.push_back({"PGS", point});
  std::vector<std::uint8_t> with, without, alone;
  {
    OffscreenRenderer renderer(kOverlayWidth, kOverlayHeight, shaderDir());
    with = renderer.render(frame);
  }
  {
    OffscreenRenderer renderer(kOverlayWidth, kOverlayHeight, shaderDir());
    without = renderer.render(overlayFrame(true));
  }
  {
    FrameData bare = overlayFrame(true);
    bare.overlay = OverlayData{};
    bare.overlay.labels.push_back({"PGS", point});
    OffscreenRenderer renderer(kOverlayWidth, kOverlayHeight, shaderDir());
    alone = renderer.render(bare);
  }
  // Changed pixels and gold text in the box below the point; nothing changed above it.
  const auto count = [&](const std::vector<std::uint8_t>& image, int y0, int y1, bool goldOnly) {
    int n = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = static_cast<int>(point.x) - 20; x < static_cast<int>(point.x) + 20; ++x) {
        const Rgb a = pixelAt(image, kOverlayWidth, x, y), b = pixelAt(without, kOverlayWidth, x, y);
        const bool gold = a.r > 190 && a.g > 150 && a.b < 140;
        const bool changed = std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) > 12;
        n += goldOnly ? gold : changed;
      }
    }
    return n;
  };
  const int y = static_cast<int>(point.y);
  EXPECT_GT(count(with, y, y + 20, false), 200) << "the caption's box should cover the region below the point";
  EXPECT_GT(count(with, y, y + 20, true), 10) << "its text should be drawn in gold";
  EXPECT_EQ(count(with, y - 20, y - 2, false), 0) << "nothing above the point changes";
  EXPECT_GT(count(alone, y, y + 20, true), 10) << "a caption is drawn without a panel too";
}

}  // namespace
}  // namespace rbsim::render::test

// The overlay's time plots (plot_panel.cpp): a series is drawn in its colour inside the panel at
// the bottom right, rising where its values rise, and the plots show without the overlay panel.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kPlotPanelWidth = 640;
constexpr int kPlotPanelHeight = 360;

// A series rising from 0 to 1 over [0, 10] s: the first of the panel's colours (255, 158, 74).
FrameData withPlot(bool overlay) {
  FrameData frame;
  frame.options.overlay = overlay;
  frame.options.grid = false;
  OverlayPlot plot;
  plot.title = "rising";
  plot.unit = "J";
  plot.legend = {""};
  plot.tMin = 0.0f;
  plot.tMax = 10.0f;
  plot.times.emplace_back();
  plot.values.emplace_back();
  for (int i = 0; i <= 100; ++i) {
    plot.times[0].push_back(0.1f * static_cast<float>(i));
    plot.values[0].push_back(0.01f * static_cast<float>(i));
  }
  frame.overlay.plots.push_back(plot);
  return frame;
}

bool isSeriesColour(const std::vector<std::uint8_t>& image, int x, int y) {
  const std::uint8_t* p = &image[4 * (static_cast<std::size_t>(y) * kPlotPanelWidth + static_cast<std::size_t>(x))];
  return p[0] > 200 && p[1] > 110 && p[1] < 200 && p[2] < 120;
}

// Rows (from the top) holding the series colour in image column x, or -1.
int seriesRowAt(const std::vector<std::uint8_t>& image, int x) {
  for (int y = 0; y < kPlotPanelHeight; ++y) {
    if (isSeriesColour(image, x, y)) return y;
  }
  return -1;
}

TEST(PlotPanel, DrawsTheSeriesRisingAtTheBottomRight) {
  OffscreenRenderer renderer(kPlotPanelWidth, kPlotPanelHeight, shaderDir());
  for (const bool overlay : {true, false}) {
    const std::vector<std::uint8_t> image = renderer.render(withPlot(overlay));
    int coloured = 0, left = 0;
    for (int y = 0; y < kPlotPanelHeight; ++y) {
      for (int x = 0; x < kPlotPanelWidth; ++x) {
        if (!isSeriesColour(image, x, y)) continue;
        ++coloured;
        if (x < kPlotPanelWidth / 2) ++left;
      }
    }
    EXPECT_GT(coloured, 100) << "overlay " << overlay;
    EXPECT_EQ(left, 0) << "the panel is on the right";
    // Rising: its rightmost column is higher up (a smaller row) than its leftmost.
    int first = -1, last = -1;
    for (int x = 0; x < kPlotPanelWidth; ++x) {
      if (seriesRowAt(image, x) < 0) continue;
      if (first < 0) first = x;
      last = x;
    }
    ASSERT_GE(first, 0);
    EXPECT_GT(last - first, kPlotPanelWidth / 8) << "the series spans the plot";
    const int early = seriesRowAt(image, first), late = seriesRowAt(image, last);
    EXPECT_LT(late, early - kPlotPanelHeight / 20);
    EXPECT_GT(early, kPlotPanelHeight / 2) << "at the bottom";
  }
  FrameData none = withPlot(true);
  none.overlay.plots.clear();
  const std::vector<std::uint8_t> image = renderer.render(none);
  for (int x = kPlotPanelWidth / 2; x < kPlotPanelWidth; x += 7) EXPECT_EQ(seriesRowAt(image, x), -1);
}

}  // namespace
}  // namespace rbsim::render::test

#include "pane_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbsim::render {

namespace {

constexpr int kPaneGap = 4;                   // between panes [px]
constexpr float kMarginFraction = 0.015f;     // the overlay's margin, of the image height [1]
constexpr float kMarginPixels = 4.0f;         // plus this [px]
// The panel's width, of the image width [1]: a full panel's rows hold three vectors; a compact one
// leaves the scene two thirds of a 16:9 image.
constexpr float kFullPanelWidthFraction = 0.45f;
constexpr float kCompactPanelWidthFraction = 0.33f;
constexpr double kMaxPaneFovDegrees = 150.0;  // a very narrow pane's field of view, at most [deg]

}  // namespace

float overlayMargin(int imageHeight) {
  return std::round(kMarginFraction * static_cast<float>(imageHeight)) + kMarginPixels;
}

int infoColumnWidth(int imageWidth, int imageHeight, PanelMode panel) {
  const float fraction = panel == PanelMode::Full ? kFullPanelWidthFraction : kCompactPanelWidthFraction;
  return static_cast<int>(std::lround(fraction * static_cast<float>(imageWidth) + 2.0f * overlayMargin(imageHeight)));
}

std::vector<PaneRect> paneLayout(std::size_t count, int imageWidth, int imageHeight, bool infoColumn, PanelMode panel) {
  std::vector<PaneRect> panes;
  if (count == 0 || imageWidth <= 0 || imageHeight <= 0) return panes;
  const int left = infoColumn ? std::min(infoColumnWidth(imageWidth, imageHeight, panel), imageWidth / 2) : 0;
  const int areaWidth = imageWidth - left;
  const double imageAspect = static_cast<double>(imageWidth) / imageHeight;
  std::size_t bestColumns = 1;
  double bestMismatch = std::numeric_limits<double>::infinity();
  for (std::size_t columns = 1; columns <= count; ++columns) {
    const std::size_t rows = (count + columns - 1) / columns;
    const double paneAspect = (static_cast<double>(areaWidth) / columns) / (static_cast<double>(imageHeight) / rows);
    const double mismatch = std::abs(std::log(paneAspect / imageAspect));
    if (mismatch < bestMismatch) {
      bestMismatch = mismatch;
      bestColumns = columns;
    }
  }
  const int columns = static_cast<int>(bestColumns);
  const int rows = static_cast<int>((count + bestColumns - 1) / bestColumns);
  // Edges at rounded fractions, so the panes tile the area exactly; a gap taken from each side.
  const auto edge = [](int start, int length, int i, int n) { return start + (length * i + n / 2) / n; };
  for (std::size_t k = 0; k < count; ++k) {
    const int c = static_cast<int>(k) % columns, r = static_cast<int>(k) / columns;
    const int x0 = edge(left, areaWidth, c, columns) + (c > 0 || infoColumn ? kPaneGap / 2 : 0);
    const int x1 = edge(left, areaWidth, c + 1, columns) - (c + 1 < columns ? kPaneGap / 2 : 0);
    const int y0 = edge(0, imageHeight, r, rows) + (r > 0 ? kPaneGap / 2 : 0);
    const int y1 = edge(0, imageHeight, r + 1, rows) - (r + 1 < rows ? kPaneGap / 2 : 0);
    panes.push_back({x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)});
  }
  return panes;
}

Camera paneCamera(const Camera& camera, int imageWidth, int imageHeight, const PaneRect& pane) {
  const double imageAspect = static_cast<double>(imageWidth) / imageHeight;
  const double paneAspect = static_cast<double>(pane.width) / pane.height;
  Camera out = camera;
  if (paneAspect < imageAspect) {
    // Same horizontal extent: tan(fovY'/2) * paneAspect = tan(fovY/2) * imageAspect.
    const double halfTan = std::tan(0.5 * glm::radians(static_cast<double>(camera.fovYDegrees))) * imageAspect / paneAspect;
    out.fovYDegrees = static_cast<float>(std::min(kMaxPaneFovDegrees, glm::degrees(2.0 * std::atan(halfTan))));
  }
  return out;
}

}  // namespace rbsim::render

// No text of the overlay panel is ever cut off (issue 38): at 640x360, 1280x720 and 3840x2160,
// compact and full, with plots under it and without, every line of the panel as it is laid out
// (panel_layout.h) stays inside the panel's text area, the panel inside the image (above the
// plots' room), and a label never runs into its value.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render/panel_rows.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr float kTolerance = 0.5f;  // [px] of rounding in the text measure

// The rows of demo 5's bouncer and of a 3-world comparison, a value with no space to break at,
// and enough Detail rows to overflow a small image in the full panel.
OverlayData demoPanel(PanelMode mode, bool plots) {
  OverlayData d;
  d.title = "Demo 5: contact, a title long enough to need two lines in a small image";
  d.caption = "impulses with restitution and friction (seed 000): yellow points, arrows = impulse; the bouncer "
              "(e = 0.6) comes to rest, the slider stops at v0^2 / (2 mu_k g)";
  d.panel = mode;
  d.rows = {{"time t", "1.23333 s", RowLevel::Essential},
            {"integrator", "dlm, dt 0.00416667 s", RowLevel::Useful},
            {"body", "bouncer (exact inertia, 1 kg)", RowLevel::Essential},
            {"x", "  +0.7782   +1.0357   +0.4777 m", RowLevel::Essential},
            {"R row 1", "  +0.0841   -0.9965   +0.0010 ", RowLevel::Detail},
            {"R row 2", "  +0.9965   +0.0841   +0.0008 ", RowLevel::Detail},
            {"R row 3", "  -0.0009   +0.0010   +1.0000 ", RowLevel::Detail},
            {"v", "  +1.5645   +0.0999   -0.0604 m/s", RowLevel::Useful},
            {"omega", "  -0.0021   -0.0174  -14.4549 rad/s", RowLevel::Useful},
            {"L", "  -0.0001   -0.0007   -0.6023 kg m^2/s", RowLevel::Detail},
            {"vs exact spin  euler-quat", "1.8e-06 rad, dE/E -4.4e-16, since 0.879 s", RowLevel::Essential},
            {"mesh", "/a/very/long/path/without/any/space/to/break/at/assets/meshes/bunny_with_a_long_name.obj",
             RowLevel::Useful},
            {"contacts", "4 manifolds, 16 points", RowLevel::Essential}};
  for (int i = 0; i < 12; ++i) d.rows.push_back({"  plane-slider " + std::to_string(i), "n (+0.00 +1.00 +0.00) 0.0000 m deep", RowLevel::Detail});
  if (plots) {
    d.plotsUnderPanel = true;
    OverlayPlot p;
    p.title = "E, kinetic + potential";
    p.unit = "J";
    p.times = {{0.0f, 1.0f}};
    p.values = {{1.0f, 2.0f}};
    d.plots = {p, p};
  }
  return d;
}

struct Size {
  int width, height;
};

class PanelFit : public ::testing::TestWithParam<Size> {};

TEST_P(PanelFit, EveryLineStaysInsideItsBox) {
  const Size size = GetParam();
  OffscreenRenderer renderer(size.width, size.height, shaderDir());
  for (const PanelMode mode : {PanelMode::Compact, PanelMode::Full}) {
    for (const bool plots : {false, true}) {
      SCOPED_TRACE(std::string(mode == PanelMode::Full ? "full" : "compact") + (plots ? ", plots under it" : ""));
      const OverlayData data = demoPanel(mode, plots);
      const PanelLayout layout = renderer.layoutPanel(data);
      ASSERT_GT(layout.width, 0.0f);
      EXPECT_GE(layout.x, 0.0f);
      EXPECT_GE(layout.y, 0.0f);
      EXPECT_LE(layout.x + layout.width, static_cast<float>(size.width));
      EXPECT_LE(layout.y + layout.height, static_cast<float>(size.height));
      if (plots) {  // the plots keep at least five lines each below the panel
        const float line = layout.lines.back().height;
        EXPECT_LE(layout.y + layout.height + 2.0f * 5.0f * line, static_cast<float>(size.height));
      }
      bool title = false, caption = false;
      for (const PanelLine& l : layout.lines) {
        title = title || l.kind == PanelLine::Kind::Title;
        caption = caption || l.kind == PanelLine::Kind::Caption;
        EXPECT_GE(l.x, layout.innerLeft - kTolerance) << l.text;
        EXPECT_LE(l.x + l.width, layout.innerRight + kTolerance) << "cut off at the right: " << l.text;
        EXPECT_GE(l.y, layout.y) << l.text;
        EXPECT_LE(l.y + l.height, layout.y + layout.height + kTolerance) << "cut off at the bottom: " << l.text;
      }
      EXPECT_TRUE(title);
      // Lines on the same band (a label and its value) do not touch.
      for (std::size_t i = 0; i < layout.lines.size(); ++i) {
        for (std::size_t j = i + 1; j < layout.lines.size(); ++j) {
          const PanelLine &a = layout.lines[i], &b = layout.lines[j];
          const bool sameBand = a.y < b.y + b.height - kTolerance && b.y < a.y + a.height - kTolerance;
          if (!sameBand) continue;
          EXPECT_TRUE(a.x + a.width <= b.x + kTolerance || b.x + b.width <= a.x + kTolerance)
              << "\"" << a.text << "\" runs into \"" << b.text << "\"";
        }
      }
      // Every row of the panel is shown, or counted in the last line.
      const std::size_t rows = panelRows(data.rows, mode).size();
      EXPECT_EQ(layout.shownRows + layout.hiddenRows, rows);
      if (mode == PanelMode::Compact) {
        EXPECT_LE(rows, kCompactRows + 5u) << "only the Essential rows may pass the budget";
      }
      if (size.height >= 720 && mode == PanelMode::Compact) {
        EXPECT_EQ(layout.hiddenRows, 0u) << "a compact panel fits a 720-row image whole";
        EXPECT_TRUE(caption);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, PanelFit, ::testing::Values(Size{640, 360}, Size{1280, 720}, Size{3840, 2160}),
                         [](const auto& info) {
                           return std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

TEST(PanelRows, ACompactPanelKeepsTheEssentialRowsThenTheUsefulOnesInOrder) {
  std::vector<OverlayRow> rows;
  for (int i = 0; i < 12; ++i) rows.push_back({"useful " + std::to_string(i), "", RowLevel::Useful});
  rows.insert(rows.begin() + 5, {"essential", "", RowLevel::Essential});
  rows.push_back({"detail", "", RowLevel::Detail});
  rows.push_back({"last essential", "", RowLevel::Essential});
  rows.push_back({"drag force", "", RowLevel::Action});
  const std::vector<OverlayRow> compact = panelRows(rows, PanelMode::Compact);
  ASSERT_EQ(compact.size(), kCompactRows + 1) << "the budget and the Action row beside it";
  EXPECT_EQ(compact[0].label, "useful 0");
  EXPECT_EQ(compact[5].label, "essential");
  EXPECT_EQ(compact[kCompactRows - 1].label, "last essential");
  EXPECT_EQ(compact.back().label, "drag force");
  EXPECT_EQ(compact[6].label, "useful 5");
  EXPECT_EQ(panelRows(rows, PanelMode::Full).size(), rows.size());
  EXPECT_TRUE(panelRows(rows, PanelMode::Off).empty());
}

}  // namespace
}  // namespace rbsim::render::test

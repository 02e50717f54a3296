// Debug lines and points land where glm's camera maths puts them, in their own colour, at their
// size and shape; depth-tested lines hide inside bodies while on-top lines and points do not; and
// thousands of lines render in one frame.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

// 720 rows: line widths are exactly as given (they scale with the image height), so the pixel
// nearest a 1.5-pixel line is fully covered.
constexpr int kDebugDrawWidth = 1280;
constexpr int kDebugDrawHeight = 720;

FrameData emptyFrame() {
  FrameData frame;
  frame.options.grid = false;
  frame.options.axes = false;
  frame.options.overlay = false;
  return frame;
}

glm::vec2 project(const FrameData& frame, const glm::vec3& p) {
  return projectToPixel(frame.camera, kDebugDrawWidth, kDebugDrawHeight, p);
}

glm::vec2 pixelCentre(int x, int y) { return {x + 0.5f, y + 0.5f}; }

float distanceToSegment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab));
}

int channelDifference(const Rgb& p, const Rgb& q) {
  return std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b);
}

// True if some pixel within one of (x, y) passes `test`: the pixel whose centre is nearest a
// thin line may be a neighbour of the one that contains the projected point.
template <typename Test>
bool nearPixelIs(const std::vector<std::uint8_t>& image, const glm::vec2& at, Test test) {
  const int cx = static_cast<int>(at.x), cy = static_cast<int>(at.y);
  for (int y = cy - 1; y <= cy + 1; ++y) {
    for (int x = cx - 1; x <= cx + 1; ++x) {
      if (x >= 0 && y >= 0 && x < kDebugDrawWidth && y < kDebugDrawHeight && test(pixelAt(image, kDebugDrawWidth, x, y))) {
        return true;
      }
    }
  }
  return false;
}

bool isRed(const Rgb& p) { return p.r > 200 && p.g < 70 && p.b < 90; }
bool isReddish(const Rgb& p) { return p.r > p.g + 50 && p.r > p.b + 50; }
bool isYellow(const Rgb& p) { return p.r > 220 && p.g > 200 && p.b < 60; }

TEST(DebugDraw, RedLineCoversItsProjectionAndNothingElse) {
  OffscreenRenderer renderer(kDebugDrawWidth, kDebugDrawHeight, shaderDir());
  FrameData frame = emptyFrame();
  frame.lines.push_back({{-2.0f, 0.4f, 0.5f}, {1.5f, 1.3f, -1.0f}, {1.0f, 0.0f, 0.0f}});
  const std::vector<std::uint8_t> image = renderer.render(frame);
  const glm::vec2 a = project(frame, frame.lines[0].a);
  const glm::vec2 b = project(frame, frame.lines[0].b);
  ASSERT_GT(glm::length(b - a), 300.0f) << "the test line should cross a good part of the view";

  for (int i = 1; i < 20; ++i) {
    const glm::vec2 at = glm::mix(a, b, i / 20.0f);
    EXPECT_TRUE(nearPixelIs(image, at, isRed)) << "no red pixel near " << at.x << "," << at.y;
  }
  int reddish = 0;
  for (int y = 0; y < kDebugDrawHeight; ++y) {
    for (int x = 0; x < kDebugDrawWidth; ++x) {
      if (!isReddish(pixelAt(image, kDebugDrawWidth, x, y))) continue;
      ++reddish;
      // 0.75 px half width, 0.5 px antialiased border, and the rest for pixel-centre rounding.
      ASSERT_LT(distanceToSegment(pixelCentre(x, y), a, b), 2.0f) << "at " << x << "," << y;
    }
  }
  // About width x length pixels: a broken or much too thin line would have far fewer.
  EXPECT_GT(reddish, 1.2f * glm::length(b - a));
  EXPECT_LT(reddish, 3.5f * glm::length(b - a));
}

TEST(DebugDraw, PointIsARoundDotOfTheRequestedSizeAtItsProjection) {
  OffscreenRenderer renderer(kDebugDrawWidth, kDebugDrawHeight, shaderDir());
  const FrameData empty = emptyFrame();
  FrameData frame = emptyFrame();
  constexpr float kDiameter = 16.0f;
  frame.points.push_back({{0.7f, 0.9f, -0.4f}, {1.0f, 0.9f, 0.0f}, kDiameter});
  const std::vector<std::uint8_t> background = renderer.render(empty);
  const std::vector<std::uint8_t> image = renderer.render(frame);
  const glm::vec2 centre = project(frame, frame.points[0].position);
  const float radius = 0.5f * kDiameter;

  int changed = 0;
  glm::dvec2 sum(0.0);
  for (int y = static_cast<int>(centre.y) - 20; y <= static_cast<int>(centre.y) + 20; ++y) {
    for (int x = static_cast<int>(centre.x) - 20; x <= static_cast<int>(centre.x) + 20; ++x) {
      const Rgb p = pixelAt(image, kDebugDrawWidth, x, y);
      const float r = glm::length(pixelCentre(x, y) - centre);
      const int difference = channelDifference(p, pixelAt(background, kDebugDrawWidth, x, y));
      // Inside, well clear of the dark rim: the requested colour.
      if (r < radius - 2.0f) {
        EXPECT_TRUE(isYellow(p)) << "at r = " << r << ": " << p.r << "," << p.g << "," << p.b;
      }
      // Outside the disc, including the corners of its bounding square (r up to 11.3 here),
      // which a square sprite would cover: untouched.
      if (r > radius + 1.0f) {
        EXPECT_LE(difference, 3) << "at r = " << r;
      }
      if (difference > 30) {
        ++changed;
        sum += glm::dvec2(pixelCentre(x, y));
      }
    }
  }
  const double area = 3.14159265 * radius * radius;
  EXPECT_NEAR(changed, area, 0.15 * area);
  ASSERT_GT(changed, 0);
  EXPECT_NEAR(sum.x / changed, centre.x, 0.5);
  EXPECT_NEAR(sum.y / changed, centre.y, 0.5);
}

TEST(DebugDraw, PointsAndOnTopLinesShowInsideABodyDepthTestedLinesDoNot) {
  OffscreenRenderer renderer(kDebugDrawWidth, kDebugDrawHeight, shaderDir());
  FrameData frame = emptyFrame();
  const glm::vec3 centre{0.0f, 0.5f, 0.0f};
  frame.bodies.push_back(makeBox(centre, glm::vec3(0.5f), glm::mat3(1.0f), {0.1f, 0.8f, 0.15f}));
  // A short segment through the box's centre, wholly inside it, and a point at the centre.
  const glm::vec3 a = centre - glm::vec3(0.2f, 0.0f, 0.0f);
  const glm::vec3 b = centre + glm::vec3(0.2f, 0.0f, 0.0f);
  const glm::vec2 middle = project(frame, centre);
  const auto isGreen = [](const Rgb& p) { return p.g > 1.4 * p.r && p.g > 1.4 * p.b; };

  frame.lines.push_back({a, b, {1.0f, 0.0f, 0.0f}, false});
  const std::vector<std::uint8_t> hidden = renderer.render(frame);
  EXPECT_FALSE(nearPixelIs(hidden, middle, isReddish)) << "a depth-tested line showed through";
  EXPECT_TRUE(isGreen(pixelAt(hidden, kDebugDrawWidth, static_cast<int>(middle.x),
                              static_cast<int>(middle.y))));

  frame.lines[0].onTop = true;
  EXPECT_TRUE(nearPixelIs(renderer.render(frame), middle, isRed)) << "on-top line hidden";

  frame.lines.clear();
  frame.points.push_back({centre, {1.0f, 0.9f, 0.0f}, 12.0f});
  const std::vector<std::uint8_t>& dot = renderer.render(frame);
  const Rgb p = pixelAt(dot, kDebugDrawWidth, static_cast<int>(middle.x), static_cast<int>(middle.y));
  EXPECT_TRUE(isYellow(p)) << p.r << "," << p.g << "," << p.b;
}

TEST(DebugDraw, FiveThousandLinesRenderInOneFrame) {
  OffscreenRenderer renderer(kDebugDrawWidth, kDebugDrawHeight, shaderDir());
  FrameData frame = emptyFrame();
  frame.options.grid = true;
  frame.bodies.push_back(makeBox({0.0f, 0.5f, 0.0f}, glm::vec3(0.5f), glm::mat3(1.0f),
                                 {0.8f, 0.5f, 0.2f}));
  // Short cyan segments confined to the left 40% of the image, so none can cross the known
  // magenta line on the right.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f), step(-0.3f, 0.3f);
  const glm::vec3 cyan{0.0f, 1.0f, 1.0f};
  while (frame.lines.size() < 4999) {
    const glm::vec3 p(coord(rng), 0.5f * (coord(rng) + 3.0f), coord(rng));
    const glm::vec3 q = p + glm::vec3(step(rng), step(rng), step(rng));
    if (std::max(project(frame, p).x, project(frame, q).x) > 0.4f * kDebugDrawWidth) continue;
    frame.lines.push_back({p, q, cyan, frame.lines.size() % 2 == 0});
  }
  const DebugLine known{{2.0f, 0.3f, 0.0f}, {2.0f, 1.5f, 0.0f}, {1.0f, 0.0f, 1.0f}};
  ASSERT_GT(project(frame, known.a).x, 0.6f * kDebugDrawWidth);
  frame.lines.push_back(known);
  ASSERT_EQ(frame.lines.size(), 5000u);

  const std::vector<std::uint8_t> image = renderer.render(frame);  // throws on a GL error
  const auto isMagenta = [](const Rgb& p) { return p.r > 200 && p.g < 80 && p.b > 200; };
  const auto isCyan = [](const Rgb& p) { return p.r < 80 && p.g > 200 && p.b > 200; };
  EXPECT_TRUE(nearPixelIs(image, project(frame, 0.5f * (known.a + known.b)), isMagenta));
  // Spot checks on the crowd: an on-top segment is always visible at its middle.
  int checked = 0;
  for (std::size_t i = 0; i < 4999 && checked < 20; i += 2, ++checked) {
    const DebugLine& line = frame.lines[i];
    EXPECT_TRUE(nearPixelIs(image, project(frame, 0.5f * (line.a + line.b)), isCyan))
        << "line " << i;
  }
}

}  // namespace
}  // namespace rbsim::render::test

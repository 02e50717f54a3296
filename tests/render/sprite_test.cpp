// Particle sprites: an additive sprite brightens what is behind it, an alpha sprite of a dark
// colour darkens it, a sprite behind an opaque body is hidden, the image stays opaque, and a
// sprite lands where the projection puts its centre, at the size asked for in metres.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kSpriteWidth = 640;
constexpr int kSpriteHeight = 360;

FrameData plainFrame() {
  FrameData frame;
  frame.options.grid = true;
  frame.options.axes = false;
  frame.options.overlay = false;
  return frame;
}

FrameData withSprite(const glm::vec3& at, float size, const glm::vec4& color, bool additive) {
  FrameData frame = plainFrame();
  frame.sprites.push_back({additive, {Sprite{at, size, color}}});
  return frame;
}

int brightness(const Rgb& p) { return p.r + p.g + p.b; }

Rgb spritePixelOf(const std::vector<std::uint8_t>& image, const FrameData& frame, const glm::vec3& p) {
  const glm::vec2 at = projectToPixel(frame.camera, kSpriteWidth, kSpriteHeight, p);
  return pixelAt(image, kSpriteWidth, static_cast<int>(at.x), static_cast<int>(at.y));
}

TEST(Sprite, AdditiveBrightensAlphaCoversAndTheImageStaysOpaque) {
  OffscreenRenderer renderer(kSpriteWidth, kSpriteHeight, shaderDir());
  const glm::vec3 centre(0.0f, 1.0f, 0.0f);
  const std::vector<std::uint8_t> background = renderer.render(plainFrame());
  const FrameData fire = withSprite(centre, 0.5f, {1.0f, 0.5f, 0.1f, 0.8f}, true);
  const std::vector<std::uint8_t> bright = renderer.render(fire);
  const Rgb before = spritePixelOf(background, fire, centre);
  const Rgb lit = spritePixelOf(bright, fire, centre);
  EXPECT_GT(lit.r, before.r + 40);
  EXPECT_GE(lit.g, before.g);
  const FrameData smoke = withSprite(centre, 0.5f, {0.02f, 0.02f, 0.02f, 0.9f}, false);
  const std::vector<std::uint8_t> dark = renderer.render(smoke);
  EXPECT_LT(brightness(spritePixelOf(dark, smoke, centre)), brightness(before) - 150);
  for (std::size_t i = 3; i < dark.size(); i += 4) ASSERT_EQ(dark[i], 255) << "pixel " << i / 4;
  for (std::size_t i = 3; i < bright.size(); i += 4) ASSERT_EQ(bright[i], 255) << "pixel " << i / 4;
}

TEST(Sprite, CoversItsSizeAroundItsProjectedCentre) {
  OffscreenRenderer renderer(kSpriteWidth, kSpriteHeight, shaderDir());
  const glm::vec3 centre(0.3f, 0.8f, -0.2f);
  const float size = 0.6f;  // [m]
  const FrameData frame = withSprite(centre, size, {0.0f, 0.0f, 0.0f, 1.0f}, false);
  const std::vector<std::uint8_t> background = renderer.render(plainFrame());
  const std::vector<std::uint8_t> image = renderer.render(frame);
  const glm::vec2 middle = projectToPixel(frame.camera, kSpriteWidth, kSpriteHeight, centre);
  // The sprite faces the camera, so its half size spans the camera's right axis.
  const glm::vec3 right = glm::normalize(glm::cross(frame.camera.target - frame.camera.eye, frame.camera.up));
  const float radiusPx = glm::length(projectToPixel(frame.camera, kSpriteWidth, kSpriteHeight, centre + 0.5f * size * right) - middle);
  const auto changed = [&](float dx) {
    const int x = static_cast<int>(middle.x + dx), y = static_cast<int>(middle.y);
    return brightness(pixelAt(image, kSpriteWidth, x, y)) < brightness(pixelAt(background, kSpriteWidth, x, y)) - 6;
  };
  EXPECT_TRUE(changed(0.0f));
  EXPECT_TRUE(changed(0.7f * radiusPx));
  EXPECT_TRUE(changed(-0.7f * radiusPx));
  EXPECT_FALSE(changed(1.1f * radiusPx));
  EXPECT_FALSE(changed(-1.1f * radiusPx));
}

TEST(Sprite, IsHiddenBehindAnOpaqueBody) {
  OffscreenRenderer renderer(kSpriteWidth, kSpriteHeight, shaderDir());
  FrameData frame = plainFrame();
  frame.bodies.push_back(makeBox({0.0f, 0.5f, 0.0f}, glm::vec3(0.5f), glm::mat3(1.0f), {0.2f, 0.4f, 0.8f}));
  const std::vector<std::uint8_t> boxOnly = renderer.render(frame);
  // 1.5 m beyond the box's centre on the line of sight through it.
  const glm::vec3 centre(0.0f, 0.5f, 0.0f);
  const glm::vec3 behind = centre + 1.5f * glm::normalize(centre - frame.camera.eye);
  frame.sprites.push_back({true, {Sprite{behind, 0.3f, {1.0f, 1.0f, 1.0f, 1.0f}}}});
  const std::vector<std::uint8_t> image = renderer.render(frame);
  const Rgb a = spritePixelOf(boxOnly, frame, behind), b = spritePixelOf(image, frame, behind);
  EXPECT_EQ(brightness(a), brightness(b));
}

}  // namespace
}  // namespace rbsim::render::test

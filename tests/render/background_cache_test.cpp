// The sky and ground are drawn once per camera and copied into later frames (gl_renderer.h). A
// renderer that has drawn other views must give the same picture as a fresh one: moving the
// camera, changing the field of view or switching the grid redraws the background, and a
// copied background under moving bodies equals a freshly drawn one.
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kBackgroundCacheWidth = 256;
constexpr int kBackgroundCacheHeight = 144;

FrameData boxAt(float x) {
  FrameData frame;
  frame.options.overlay = false;
  frame.bodies.push_back(makeBox({x, 0.4f, 0.0f}, glm::vec3(0.4f), glm::mat3(1.0f), {0.85f, 0.3f, 0.2f}));
  return frame;
}

std::vector<std::uint8_t> fresh(const FrameData& frame) {
  OffscreenRenderer renderer(kBackgroundCacheWidth, kBackgroundCacheHeight, shaderDir());
  return renderer.render(frame);
}

TEST(BackgroundCache, EveryViewMatchesAFreshRenderer) {
  OffscreenRenderer reused(kBackgroundCacheWidth, kBackgroundCacheHeight, shaderDir());
  std::vector<FrameData> frames;
  frames.push_back(boxAt(0.0f));
  frames.push_back(boxAt(0.7f));  // same camera: background copied, body moved
  FrameData moved = boxAt(0.7f);
  moved.camera.eye = {-3.0f, 2.0f, 5.0f};
  frames.push_back(moved);
  FrameData wider = moved;
  wider.camera.fovYDegrees = 60.0f;
  frames.push_back(wider);
  FrameData noGrid = wider;
  noGrid.options.grid = false;
  frames.push_back(noGrid);
  frames.push_back(boxAt(0.0f));  // back to the first view
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const std::vector<std::uint8_t> image = reused.render(frames[k]);
    EXPECT_EQ(image, fresh(frames[k])) << "frame " << k;
  }
  // The views do differ, so the comparison above could fail.
  EXPECT_NE(fresh(frames[2]), fresh(frames[3]));
  EXPECT_NE(fresh(frames[3]), fresh(frames[4]));
}

// With multisampling the frame is drawn into a multisampled framebuffer and the cached
// background must be multisampled like it (a blit between different sample counts is a GL
// error, which render() turns into a RenderError). Away from edges the picture is the
// single-sampled one: every sample of a pixel inside a surface has the same colour.
TEST(BackgroundCache, MultisampledFramesCopyAMultisampledBackground) {
  OffscreenRenderer single(kBackgroundCacheWidth, kBackgroundCacheHeight, shaderDir(), 1);
  OffscreenRenderer multi(kBackgroundCacheWidth, kBackgroundCacheHeight, shaderDir(), 4);
  ASSERT_GT(multi.samples(), 1) << "the driver offers no multisampling";
  const std::vector<std::uint8_t> expected = single.render(boxAt(0.0f));
  multi.render(boxAt(0.5f));
  const std::vector<std::uint8_t> image = multi.render(boxAt(0.0f));  // background copied, not drawn
  // Sky, ground and the box's front face: interior pixels, no edge nearby (off the face's centre,
  // where the body's z axis comes through).
  const glm::vec2 face = projectToPixel(Camera{}, kBackgroundCacheWidth, kBackgroundCacheHeight, {0.2f, 0.55f, 0.4f});
  for (const glm::ivec2 p : {glm::ivec2(kBackgroundCacheWidth / 2, 3), glm::ivec2(5, kBackgroundCacheHeight - 4),
                             glm::ivec2(static_cast<int>(face.x), static_cast<int>(face.y))}) {
    const Rgb a = pixelAt(expected, kBackgroundCacheWidth, p.x, p.y);
    const Rgb b = pixelAt(image, kBackgroundCacheWidth, p.x, p.y);
    EXPECT_LE(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 3) << "pixel " << p.x << "," << p.y;
  }
}

}  // namespace
}  // namespace rbsim::render::test

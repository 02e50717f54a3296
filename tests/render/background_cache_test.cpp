// The sky and ground are drawn once per camera and copied into later frames (gl_renderer.h). A
// renderer that has drawn other views must give the same picture as a fresh one: moving the
// camera, changing the field of view or switching the grid redraws the background, and a
// copied background under moving bodies equals a freshly drawn one.
#include <vector>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kWidth = 256;
constexpr int kHeight = 144;

FrameData boxAt(float x) {
  FrameData frame;
  frame.options.overlay = false;
  frame.bodies.push_back(makeBox({x, 0.4f, 0.0f}, glm::vec3(0.4f), glm::mat3(1.0f), {0.85f, 0.3f, 0.2f}));
  return frame;
}

std::vector<std::uint8_t> fresh(const FrameData& frame) {
  OffscreenRenderer renderer(kWidth, kHeight, shaderDir());
  return renderer.render(frame);
}

TEST(BackgroundCache, EveryViewMatchesAFreshRenderer) {
  OffscreenRenderer reused(kWidth, kHeight, shaderDir());
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

}  // namespace
}  // namespace rbsim::render::test

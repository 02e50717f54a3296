// render() in two halves (begin, then finish after other work): the same picture as render(),
// unaffected by what the caller does to its FrameData in between, and misuse is an error.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render/render_error.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kBeginFinishWidth = 192;
constexpr int kBeginFinishHeight = 108;

FrameData beginFinishBoxAt(float x) {
  FrameData frame;
  frame.overlay.title = "begin / finish";
  frame.bodies.push_back(makeBox({x, 0.4f, 0.0f}, glm::vec3(0.4f), glm::mat3(1.0f), {0.25f, 0.45f, 0.85f}));
  return frame;
}

TEST(BeginFinish, GivesWhatRenderGivesWhateverHappensBetween) {
  OffscreenRenderer whole(kBeginFinishWidth, kBeginFinishHeight, shaderDir());
  OffscreenRenderer halves(kBeginFinishWidth, kBeginFinishHeight, shaderDir());
  for (int k = 0; k < 10; ++k) {  // past kPassSampleEvery, so a frame timed pass by pass is among them
    FrameData frame = beginFinishBoxAt(0.1f * static_cast<float>(k));
    const std::vector<std::uint8_t> expected = whole.render(frame);
    halves.begin(frame);
    frame = beginFinishBoxAt(-2.0f);  // the caller moves on: the begun frame must not change
    EXPECT_EQ(halves.finish(), expected) << "frame " << k;
  }
}

// finishShared() hands out the image without copying it; one that a writer still holds must not
// be reused for a later frame, and once let go its buffer is.
TEST(BeginFinish, ASharedImageStaysAsItWasWhileHeld) {
  OffscreenRenderer renderer(kBeginFinishWidth, kBeginFinishHeight, shaderDir());
  renderer.begin(beginFinishBoxAt(0.0f));
  const std::shared_ptr<const std::vector<std::uint8_t>> held = renderer.finishShared();
  const std::vector<std::uint8_t> copy = *held;
  const std::vector<std::uint8_t>* heldAddress = held.get();
  for (int k = 1; k <= 4; ++k) {
    renderer.begin(beginFinishBoxAt(0.3f * static_cast<float>(k)));
    const auto later = renderer.finishShared();
    EXPECT_NE(later.get(), heldAddress);
    EXPECT_NE(*later, copy) << "frame " << k << " shows the box elsewhere";
  }
  EXPECT_EQ(*held, copy);
}

TEST(BeginFinish, RefusesTwoBeginsAndAFinishWithoutBegin) {
  OffscreenRenderer renderer(kBeginFinishWidth, kBeginFinishHeight, shaderDir());
  EXPECT_THROW(renderer.finish(), RenderError);
  renderer.begin(beginFinishBoxAt(0.0f));
  EXPECT_THROW(renderer.begin(beginFinishBoxAt(0.0f)), RenderError);
  EXPECT_NO_THROW(renderer.finish());
}

}  // namespace
}  // namespace rbsim::render::test

// The EGL surfaceless context (OSMesa's successor) and OSMesa must give the same picture: both
// are Mesa's llvmpipe behind the same GL calls, so any difference is a bug in how one of them is
// set up (framebuffer, readback, row order, a state left bound to framebuffer 0).
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "render/gl_context.h"
#include "render/offscreen_renderer.h"
#include "render/title_card.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kGlBackendWidth = 320;
constexpr int kGlBackendHeight = 180;

// Everything the renderer draws: bodies with outlines and shadows on the ground grid, the sky,
// axes, a force arrow, debug lines and points, and the overlay panel's text.
FrameData fullFrame() {
  FrameData frame;
  frame.options.overlay = true;
  frame.options.axes = true;
  BodyView box = makeBox({0.0f, 0.6f, 0.0f}, {0.5f, 0.3f, 0.4f},
                         glm::mat3(glm::vec3(0.8f, 0.0f, -0.6f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.6f, 0.0f, 0.8f)),
                         {0.85f, 0.3f, 0.2f});
  box.selected = true;
  frame.bodies.push_back(box);
  frame.bodies.push_back(makeBox({1.2f, 0.25f, 0.5f}, glm::vec3(0.25f), glm::mat3(1.0f), {0.25f, 0.45f, 0.85f}));
  frame.forces.push_back({{0.0f, 0.9f, 0.0f}, {0.0f, 5.0f, 0.0f}});
  frame.lines.push_back({{-1.0f, 0.1f, -1.0f}, {1.0f, 0.1f, 1.0f}, {0.2f, 0.9f, 0.3f}, true});
  frame.points.push_back({{-0.8f, 0.5f, 0.2f}, {0.9f, 0.2f, 0.9f}, 8.0f});
  frame.overlay.title = "Backend check";
  frame.overlay.rows = {{"x", "(0.00, 0.60, 0.00) m"}, {"v", "(0.00, 0.00, 0.00) m/s"}};
  return frame;
}

// Both backends draw into a framebuffer object on the same rasteriser, so the pictures must be
// the same to the bit. (Before both used an object, OSMesa drew into its window-system buffer,
// stored upside down, and 0.5 % of the bytes differed on edge pixels, by up to 18 levels.)
int differentBytes(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  EXPECT_EQ(a.size(), b.size());
  int count = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) count += a[i] != b[i] ? 1 : 0;
  return count;
}

bool haveOsmesa() { return parseGlBackend("osmesa").has_value(); }

TEST(GlBackend, ParsesTheNamesThisBuildOffers) {
  EXPECT_EQ(parseGlBackend("egl"), GlBackend::Egl);
  EXPECT_FALSE(parseGlBackend("vulkan").has_value());
  EXPECT_FALSE(parseGlBackend("EGL").has_value());
  EXPECT_EQ(defaultGlBackend(), haveOsmesa() ? GlBackend::Osmesa : GlBackend::Egl);
}

TEST(GlBackend, EglDrawsTheSamePixelsAsOsmesa) {
  if (!haveOsmesa()) GTEST_SKIP() << "this build has no OSMesa to compare with";
  const FrameData frame = fullFrame();
  std::vector<std::uint8_t> osmesa, egl;
  {
    OffscreenRenderer renderer(kGlBackendWidth, kGlBackendHeight, shaderDir(), 1, GlBackend::Osmesa);
    osmesa = renderer.render(frame);
  }
  {
    OffscreenRenderer renderer(kGlBackendWidth, kGlBackendHeight, shaderDir(), 1, GlBackend::Egl);
    egl = renderer.render(frame);
  }
  // The picture is not blank: the sky at the top and the ground at the bottom differ.
  EXPECT_NE(pixelAt(egl, kGlBackendWidth, kGlBackendWidth / 2, 5).b, pixelAt(egl, kGlBackendWidth, kGlBackendWidth / 2, kGlBackendHeight - 5).b);
  EXPECT_EQ(differentBytes(osmesa, egl), 0) << "of " << osmesa.size();
}

// Two renderers, one on each backend, alive at once and used in turns (the reel has a title-card
// context beside the scene's): each must draw into its own framebuffer, every time.
TEST(GlBackend, ContextsOfBothBackendsTakeTurnsOnOneThread) {
  if (!haveOsmesa()) GTEST_SKIP() << "this build has no OSMesa to compare with";
  const FrameData frame = fullFrame();
  FrameData empty = frame;
  empty.bodies.clear();
  empty.options.overlay = false;
  OffscreenRenderer a(kGlBackendWidth, kGlBackendHeight, shaderDir(), 1, GlBackend::Osmesa);
  OffscreenRenderer b(kGlBackendWidth, kGlBackendHeight, shaderDir(), 1, GlBackend::Egl);
  const std::vector<std::uint8_t> first = a.render(frame);
  const std::vector<std::uint8_t> other = b.render(empty);
  const std::vector<std::uint8_t> again = a.render(frame);
  const std::vector<std::uint8_t> eglFull = b.render(frame);
  EXPECT_GT(differentBytes(first, other), 1000) << "the empty frame is another picture";
  EXPECT_EQ(differentBytes(first, again), 0) << "the same context draws the same frame again";
  EXPECT_EQ(differentBytes(first, eglFull), 0);
}

TEST(GlBackend, TitleCardsAreTheSameThroughBoth) {
  if (!haveOsmesa()) GTEST_SKIP() << "this build has no OSMesa to compare with";
  TitleCard card;
  card.kicker = "DEMO 1 OF 2";
  card.title = "Backends";
  card.description = "OSMesa and EGL";
  std::vector<std::uint8_t> osmesa, egl;
  {
    TitleCardRenderer cards(kGlBackendWidth, kGlBackendHeight, GlBackend::Osmesa);
    osmesa = cards.render(card);
  }
  {
    TitleCardRenderer cards(kGlBackendWidth, kGlBackendHeight, GlBackend::Egl);
    egl = cards.render(card);
  }
  EXPECT_EQ(differentBytes(osmesa, egl), 0);
  int lit = 0;
  for (std::size_t i = 0; i < egl.size(); i += 4) lit += egl[i] > 128 ? 1 : 0;
  EXPECT_GT(lit, 50) << "the title's text is drawn";
}

}  // namespace
}  // namespace rbsim::render::test

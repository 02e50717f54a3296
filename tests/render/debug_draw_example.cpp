// render_debug_example OUT_DIR: renders a 1280x720 picture of the collision debug drawing (AABB
// wireframes, an overlapping pair in red, contact points and normals, a swept AABB and a ghost at
// its time of impact) to OUT_DIR/frame_000000.png for a person to look at, then times frames with
// 5000 debug lines and 100 points against the same scene without them.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "render/debug_shapes.h"
#include "render/offscreen_renderer.h"
#include "render/png_file.h"
#include "render/png_sequence_writer.h"
#include "render_test_util.h"

namespace {

using namespace rbsim::render;
using rbsim::render::test::makeBox;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;

glm::mat3 rotation(float degrees, const glm::vec3& axis) {
  return glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(axis)));
}

void addAabb(FrameData& frame, const BodyView& body, const glm::vec3& color) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& v : body.worldVertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  appendBoxLines(frame.lines, lo, hi, color);
}

FrameData exampleFrame() {
  FrameData frame;
  frame.camera.eye = {3.6f, 3.0f, 5.6f};
  frame.camera.target = {-0.2f, 0.6f, 0.0f};
  frame.options.axes = false;
  frame.overlay.title = "Debug drawing";
  frame.overlay.caption = "AABBs, contacts, time of impact";
  frame.overlay.rows = {{"bodies", "6"}, {"overlapping pairs", "1"}, {"contacts", "4"}};
  // An overlapping pair resting on the ground: red AABBs, contact points and normals.
  frame.bodies.push_back(makeBox({0.3f, 0.4f, 0.0f}, glm::vec3(0.4f), rotation(20, {0, 1, 0}),
                                 {0.80f, 0.50f, 0.20f}));
  frame.bodies.push_back(makeBox({0.95f, 0.9f, 0.1f}, {0.35f, 0.2f, 0.35f},
                                 rotation(25, {0.3f, 0.2f, 1}), {0.25f, 0.55f, 0.30f}));
  // Bodies on their own: cyan AABBs.
  frame.bodies.push_back(makeBox({-1.7f, 0.3f, -1.2f}, glm::vec3(0.3f), rotation(50, {0, 1, 0}),
                                 {0.55f, 0.35f, 0.65f}));
  frame.bodies.push_back(makeBox({1.8f, 0.25f, -1.6f}, {0.5f, 0.25f, 0.3f},
                                 rotation(-15, {0, 1, 0}), {0.30f, 0.45f, 0.75f}));
  // A falling body, its swept AABB over the step and a ghost where it hits the ground.
  const BodyView falling = makeBox({-1.1f, 2.0f, 0.9f}, glm::vec3(0.3f), rotation(35, {1, 1, 0}),
                                   {0.75f, 0.25f, 0.25f});
  BodyView ghost = makeBox({-1.1f, 0.42f, 0.9f}, glm::vec3(0.3f), rotation(35, {1, 1, 0}),
                           {0.75f, 0.25f, 0.25f});
  ghost.opacity = 0.3f;
  frame.bodies.push_back(falling);
  frame.bodies.push_back(ghost);

  for (int i = 0; i < 2; ++i) addAabb(frame, frame.bodies[i], kDebugOverlapAabbColor);
  for (int i = 2; i < 5; ++i) addAabb(frame, frame.bodies[i], kDebugAabbColor);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (int i = 4; i < 6; ++i) {
    for (const glm::vec3& v : frame.bodies[i].worldVertices) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  appendBoxLines(frame.lines, lo, hi, kDebugSweptAabbColor);
  // Contacts where the green box's bottom corners dip into the orange one, normal along +y of
  // the orange box's top face.
  const glm::vec3 contacts[] = {
      {0.62f, 0.80f, -0.15f}, {0.70f, 0.80f, 0.30f}, {0.40f, 0.80f, 0.25f}, {0.36f, 0.80f, -0.2f}};
  for (const glm::vec3& c : contacts) {
    frame.points.push_back({c, kDebugContactPointColor, 9.0f});
    appendArrowLines(frame.lines, c, c + glm::vec3(0.0f, 0.35f, 0.0f), kDebugContactNormalColor);
  }
  // The ghost's contact with the ground.
  const glm::vec3 impact = frame.bodies[5].worldVertices[0];
  glm::vec3 lowest = impact;
  for (const glm::vec3& v : frame.bodies[5].worldVertices) {
    if (v.y < lowest.y) lowest = v;
  }
  frame.points.push_back({lowest, kDebugContactPointColor, 9.0f});
  appendArrowLines(frame.lines, lowest, lowest + glm::vec3(0.0f, 0.35f, 0.0f),
                   kDebugContactNormalColor);
  return frame;
}

// 417 random AABBs (5004 lines) and 100 points spread over the view.
void addLoad(FrameData& frame) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> xz(-4.0f, 4.0f), y(0.0f, 3.0f), size(0.05f, 0.3f);
  frame.lines.clear();
  frame.points.clear();
  for (int i = 0; i < 417; ++i) {
    const glm::vec3 lo(xz(rng), y(rng), xz(rng));
    appendBoxLines(frame.lines, lo, lo + glm::vec3(size(rng), size(rng), size(rng)),
                   i % 3 == 0 ? kDebugOverlapAabbColor : kDebugAabbColor, i % 10 == 0);
  }
  for (int i = 0; i < 100; ++i) {
    frame.points.push_back({{xz(rng), y(rng), xz(rng)}, kDebugContactPointColor, 8.0f});
  }
}

struct Cost {
  double wallMs = 0.0;
  double cpuMs = 0.0;  // all threads of the process: llvmpipe rasterises on worker threads
};

double cpuNowMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// Mean cost of a frame of `a` and of `b`, rendered alternately so that changing load from other
// processes on the machine hits both alike.
std::pair<Cost, Cost> meanFrameCosts(OffscreenRenderer& renderer, const FrameData& a,
                                     const FrameData& b, int frames) {
  renderer.render(a);  // warm-up: first-frame allocations
  renderer.render(b);
  Cost costs[2];
  for (int i = 0; i < 2 * frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuNowMs();
    renderer.render(i % 2 == 0 ? a : b);
    Cost& cost = costs[i % 2];
    cost.cpuMs += (cpuNowMs() - cpuStart) / frames;
    cost.wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                            start).count() / frames;
  }
  return {costs[0], costs[1]};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  OffscreenRenderer renderer(kWidth, kHeight, rbsim::render::test::shaderDir());
  const FrameData frame = exampleFrame();
  renderer.render(frame);  // the overlay panel shows from the second frame on
  auto image = std::make_shared<std::vector<std::uint8_t>>(renderer.render(frame));
  PngSequenceWriter writer(argv[1], kWidth, kHeight, rbsim::render::kDefaultPngLevel, 1, 1);
  writer.submit({0, image});
  writer.finish();
  std::printf("wrote %s/frame_000000.png (%zu lines, %zu points)\n", argv[1], frame.lines.size(),
              frame.points.size());

  FrameData loaded = frame;
  addLoad(loaded);
  FrameData bare = frame;
  bare.lines.clear();
  bare.points.clear();
  constexpr int kFrames = 40;
  const auto [bareCost, loadedCost] = meanFrameCosts(renderer, bare, loaded, kFrames);
  std::printf("%dx%d, mean of %d frames each, interleaved:\n"
              "  without debug drawing: %6.2f ms wall, %6.2f ms CPU\n"
              "  %zu lines, %zu points: %6.2f ms wall, %6.2f ms CPU (+%.2f wall, +%.2f CPU)\n",
              kWidth, kHeight, kFrames, bareCost.wallMs, bareCost.cpuMs, loaded.lines.size(),
              loaded.points.size(), loadedCost.wallMs, loadedCost.cpuMs,
              loadedCost.wallMs - bareCost.wallMs, loadedCost.cpuMs - bareCost.cpuMs);
  return 0;
}

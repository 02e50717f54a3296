#include "run/runner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "io/input_error.h"
#include "render/frame_sink.h"
#include "render/offscreen_renderer.h"
#include "run/frame_builder.h"
#include "run/trace_writer.h"

namespace rbsim::app {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

std::uint64_t stepOfFrame(std::uint64_t frame, double fps, double dt) {
  return static_cast<std::uint64_t>(std::llround(static_cast<double>(frame) / (fps * dt)));
}

std::uint64_t frameCount(std::uint64_t steps, double fps, double dt) {
  std::uint64_t frames = 0;
  while (stepOfFrame(frames, fps, dt) <= steps) ++frames;
  return frames;
}

std::uint64_t frameCount(const Scene& scene) {
  return frameCount(scene.stepCount(), scene.view.fps, scene.settings.timeStep);
}

RunSummary runScenes(const std::vector<Scene>& scenes, const RunOptions& options, const std::string& title,
                     const FrameObserver& observer) {
  RunSummary summary;
  const auto wallStart = Clock::now();
  const ViewDesc& first = scenes.front().view;
  for (const Scene& scene : scenes) {
    if (scene.view.width != first.width || scene.view.height != first.height || scene.view.fps != first.fps) {
      throw InputError(scene.file, "view", "every phase of one video needs the same size and fps as the first");
    }
  }

  const bool wantImages = options.render && (!options.framesDir.empty() || !options.videoPath.empty());
  std::unique_ptr<render::OffscreenRenderer> renderer;
  std::unique_ptr<render::FrameSink> sink;
  if (wantImages) {
    render::SinkOptions sinkOptions;
    if (!options.framesDir.empty()) sinkOptions.pngDir = options.framesDir;
    if (!options.videoPath.empty()) sinkOptions.videoPath = options.videoPath;
    sinkOptions.fps = first.fps;
    sinkOptions.width = first.width;
    sinkOptions.height = first.height;
    sinkOptions.pngLevel = options.pngLevel;
    sink = std::make_unique<render::FrameSink>(sinkOptions);  // checks ffmpeg and folders first
    renderer = std::make_unique<render::OffscreenRenderer>(first.width, first.height);
  }
  std::optional<TraceWriter> trace;
  if (!options.tracePath.empty()) trace.emplace(options.tracePath);

  for (const Scene& scene : scenes) {
    World world = buildWorld(scene);
    const std::uint64_t steps = scene.stepCount();
    std::uint64_t nextFrame = 0;
    for (std::uint64_t s = 0;; ++s) {
      if (trace && (summary.steps % options.traceEvery == 0)) trace->write(world, summary.steps, world.time());
      while (renderer && stepOfFrame(nextFrame, scene.view.fps, scene.settings.timeStep) == s) {
        auto start = Clock::now();
        const render::FrameData frame = buildFrame(world, scene, title);
        summary.buildSeconds += secondsSince(start);
        start = Clock::now();
        const std::vector<std::uint8_t>& pixels = renderer->render(frame);
        start = Clock::now();
        sink->submit(pixels);
        summary.submitSeconds += secondsSince(start);
        if (observer) observer(pixels);
        ++nextFrame;
        ++summary.frames;
      }
      if (s == steps) break;
      const auto start = Clock::now();
      world.step();
      summary.simulateSeconds += secondsSince(start);
      ++summary.steps;
    }
  }
  if (sink) {
    const auto start = Clock::now();
    sink->finish();
    summary.finishSeconds = secondsSince(start);
    const render::SinkTiming timing = sink->timing();
    summary.pngMsPerFrame = timing.pngMs;
    summary.videoMsPerFrame = timing.videoMs;
    const render::RenderTiming drawn = renderer->timing();
    summary.renderSeconds = 1e-3 * drawn.renderMs * static_cast<double>(drawn.frames);
    summary.readbackSeconds = 1e-3 * drawn.readbackMs * static_cast<double>(drawn.frames);
  }
  summary.wallSeconds = secondsSince(wallStart);
  return summary;
}

void printSummary(const RunSummary& s, const RunOptions& options) {
  if (options.quiet) return;
  std::printf("steps %llu, frames %llu, wall %.2f s\n", static_cast<unsigned long long>(s.steps),
              static_cast<unsigned long long>(s.frames), s.wallSeconds);
  std::printf("simulate: %.4f ms per step\n", s.steps ? 1e3 * s.simulateSeconds / s.steps : 0.0);
  if (s.frames > 0) {
    const double perFrame = 1e3 / static_cast<double>(s.frames);
    std::printf("ms per frame: simulate %.2f, build %.2f, render %.2f, readback %.2f, hand-off %.2f; "
                "on writer threads, in parallel: png %.2f, video %.2f; final flush %.0f ms\n",
                perFrame * s.simulateSeconds, perFrame * s.buildSeconds, perFrame * s.renderSeconds,
                perFrame * s.readbackSeconds, perFrame * s.submitSeconds, s.pngMsPerFrame,
                s.videoMsPerFrame, 1e3 * s.finishSeconds);
  }
  if (!options.videoPath.empty() && s.frames > 0) std::printf("video: %s\n", options.videoPath.c_str());
  if (!options.framesDir.empty() && s.frames > 0) std::printf("frames: %s\n", options.framesDir.c_str());
  if (!options.tracePath.empty()) std::printf("trace: %s\n", options.tracePath.c_str());
}

}  // namespace rbsim::app

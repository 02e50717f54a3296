#include "run/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "io/input_error.h"
#include "render/frame_sink.h"
#include "render/offscreen_renderer.h"
#include "run/compare_view.h"
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

RunSummary runPhases(const std::vector<Phase>& phases, const RunOptions& options, const std::string& title,
                     const FrameObserver& observer) {
  RunSummary summary;
  const auto wallStart = Clock::now();
  const ViewDesc& first = phases.front().scene().view;
  for (const Phase& phase : phases) {
    const ViewDesc& view = phase.scene().view;
    if (view.width != first.width || view.height != first.height || view.fps != first.fps) {
      throw InputError(phase.file, "view", "every phase of one video needs the same size and fps as the first");
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

  std::uint64_t stepBase = 0;  // the trace's step column: the steps of the phases before this one
  for (const Phase& phase : phases) {
    std::vector<World> worlds;
    worlds.reserve(phase.worlds.size());
    for (const PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
    const auto traceRow = [&](std::size_t k) {
      const std::uint64_t step = stepBase + worlds[k].stepCount();
      if (trace && step % options.traceEvery == 0) {
        trace->write(worlds[k], step, worlds[k].time(), phase.compared() ? std::to_string(k) + "/" : "");
      }
    };
    const auto advance = [&](std::size_t k, std::uint64_t target) {
      while (worlds[k].stepCount() < target) {
        const auto start = Clock::now();
        worlds[k].step();
        summary.simulateSeconds += secondsSince(start);
        ++summary.steps;
        traceRow(k);
      }
    };
    for (std::size_t k = 0; k < worlds.size(); ++k) traceRow(k);
    const double fps = phase.scene().view.fps;
    const std::uint64_t frames = frameCount(phase);
    for (std::uint64_t f = 0; f < frames; ++f) {
      for (std::size_t k = 0; k < worlds.size(); ++k) {
        const Scene& scene = phase.worlds[k].scene;
        advance(k, std::min(stepOfFrame(f, fps, scene.settings.timeStep), scene.stepCount()));
      }
      if (!renderer) continue;
      auto start = Clock::now();
      const render::FrameData frame = buildPhaseFrame(worlds, phase, title);
      summary.buildSeconds += secondsSince(start);
      const std::vector<std::uint8_t>& pixels = renderer->render(frame);
      start = Clock::now();
      sink->submit(pixels);
      summary.submitSeconds += secondsSince(start);
      if (observer) observer(pixels);
      ++summary.frames;
    }
    std::uint64_t longest = 0;
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      advance(k, phase.worlds[k].scene.stepCount());  // past the last frame, as the trace expects
      longest = std::max(longest, phase.worlds[k].scene.stepCount());
    }
    stepBase += longest;
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

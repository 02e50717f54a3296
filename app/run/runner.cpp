#include "run/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "export/gltf_file.h"
#include "export/gltf_track.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/io/input_error.h"
#include "render/frame_sink.h"
#include "render/offscreen_renderer.h"
#include "run/compare_view.h"
#include "run/output_budget.h"
#include "run/output_paths.h"
#include "run/plot_history.h"
#include "record/recording.h"
#include "run/progress.h"
#include "run/trace_writer.h"

namespace rbsim::app {

static_assert(kMaxComparedWorlds <= kMaxRecordedWorlds, "a recording must hold every compared world");

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

void checkStepCounts(const Phase& phase) {
  for (const PhaseWorld& world : phase.worlds) {
    const Scene& scene = world.scene;
    if (scene.stepCount() > 0) continue;
    std::ostringstream problem;
    problem << "a duration of " << scene.duration << " s at dt = " << scene.settings.timeStep
            << " s is 0 steps; expected at least one step (a duration of at least dt / 2)";
    throw InputError(phase.file, "world.duration", problem.str());
  }
}

namespace {

// Before anything starts (ffmpeg creates its file at once): output_budget.h's limits on the
// video's frames, the PNG folder and the trace. `frames` is 0 for a run without images.
void checkRunBudgets(const std::vector<Phase>& phases, const Phase& longest, const RunOptions& options,
                     std::uint64_t frames, std::uint64_t steps) {
  const ViewDesc& view = phases.front().scene().view;
  if (frames > 0) {
    std::ostringstream what;
    what << longest.scene().duration << " s";
    if (phases.size() > 1) what << " (the longest of " << phases.size() << " phases)";
    what << " at view.fps " << view.fps;
    checkOutputBudget(longest.file, what.str(), frames, view.width, view.height, view.fps, options.framesDir,
                      options.pngLevel);
  }
  if (options.tracePath.empty()) return;
  double rows = 0.0, bodies = 0.0;  // doubles: an estimate, and no product can wrap
  for (const Phase& phase : phases) {
    for (const PhaseWorld& world : phase.worlds) {
      const double traced = std::floor(static_cast<double>(world.scene.stepCount()) / options.traceEvery) + 1.0;
      // Every body the scene makes, at the most it holds at once (issue 56, item 1).
      rows += traced * world.scene.mostBodiesAtOnce();
      bodies += world.scene.mostBodiesAtOnce();
    }
  }
  std::ostringstream how;
  how << steps << " steps in all, up to " << bodies << " bodies at once, --trace-every " << options.traceEvery;
  checkTraceBudget(options.tracePath, rows, how.str());
}

// What a recording keeps of the run to rebuild its phases (record/recording.h): each phase's
// scene file as read now, and the overrides. A scene whose bodies change as it runs (spawned,
// removed, broken) is recorded with a World snapshot at each change, which cannot hold the state
// of step systems (particles, soft bodies, a 2D world) or of the lcp solver: such a scene is
// refused here, before the run, rather than at its first change.
RecordingHeader recordingHeader(const std::vector<Phase>& phases, const RunOptions& options, const std::string& title) {
  RecordingHeader header;
  header.rbsimVersion = RBSIM_VERSION;
  header.title = title;
  header.overrides = options.overrides;
  for (const Phase& phase : phases) {
    for (const PhaseWorld& w : phase.worlds) {
      const Scene& scene = w.scene;
      const bool breakable = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const BodyDef& b) { return b.fracture != nullptr; });
      if (scene.spawners.empty() && scene.killVolume.empty() && !breakable) continue;
      const char* what = scene.planar                          ? "a 2D world (planar)"
                         : !scene.particleSystems.empty()       ? "particles"
                         : !scene.softBodies.empty()            ? "soft bodies"
                         : scene.settings.solver == Settings::ContactSolverMethod::Lcp ? "the lcp solver (world.solver)"
                                                                                      : nullptr;
      if (what != nullptr) {
        throw InputError(phase.file, "--record", std::string("a scene whose bodies change as it runs (\"spawn\" with a period, "
                                                 "\"kill_volume\", \"fracture\") and which has ") + what +
                                                 " cannot be recorded: its changes are kept as World snapshots, which hold "
                                                 "neither; record it without one or the other");
      }
    }
    RecordedPhase recorded{phase.file, std::filesystem::absolute(phase.file).parent_path().lexically_normal().string(),
                           phase.text.empty() ? readSceneFile(phase.file) : phase.text, {}};
    for (const PhaseWorld& w : phase.worlds) {
      for (const std::string& file : w.scene.files) {
        const RecordedFile f = recordedFileOf(file);
        const bool seen = std::any_of(recorded.files.begin(), recorded.files.end(),
                                      [&](const RecordedFile& r) { return r.path == f.path; });
        if (!seen) recorded.files.push_back(f);
      }
    }
    header.phases.push_back(std::move(recorded));
  }
  return header;
}

}  // namespace

namespace {

// Every output against every input the phases read (scene files, meshes, the recording) and
// against each other, before any is opened (run/output_paths.h).
void checkOutputs(const std::vector<Phase>& phases, const RunOptions& options, bool wantImages, const RecordReader* replay) {
  std::vector<NamedFile> inputs, outputs;
  for (const Phase& phase : phases) {
    inputs.push_back({"scene", phase.file});
    for (const PhaseWorld& world : phase.worlds) {
      for (const std::string& mesh : world.scene.files) inputs.push_back({"mesh", mesh});
    }
  }
  if (replay) inputs.push_back({"recording", replay->path()});
  if (!options.tracePath.empty()) outputs.push_back({"--trace", options.tracePath});
  if (!options.recordPath.empty()) outputs.push_back({"--record", options.recordPath});
  if (!options.gltfPath.empty()) outputs.push_back({"--gltf", options.gltfPath});
  if (wantImages && !options.videoPath.empty()) outputs.push_back({"--video", options.videoPath});
  checkOutputPaths(outputs, inputs, wantImages ? options.framesDir : std::string());
}

// --gltf: a name it knows, one scene of rigid bodies (export/gltf_track.h), within its budget.
void checkGltfRun(const std::vector<Phase>& phases, const std::string& path) {
  gltfFormatOf(path);
  if (phases.size() > 1) {
    throw InputError("", "--gltf with " + std::to_string(phases.size()) + " phases",
                     "a glTF export holds one scene: choose one with --phase K");
  }
  const Phase& phase = phases.front();
  if (phase.compared()) {
    throw InputError(phase.file, "--gltf", "the scene compares " + phase.compareKey + " in " + std::to_string(phase.worlds.size()) +
                                               " worlds, and a glTF export holds one: run one value with --set " + phase.compareKey + "=VALUE");
  }
  checkGltfScene(phase.scene());
  checkGltfBudget(phase.file, frameCount(phase), phase.scene().mostBodiesAtOnce());
}

}  // namespace

RunSummary runPhases(const std::vector<Phase>& phases, const RunOptions& options, const std::string& title,
                     const FrameObserver& observer, RecordReader* replay, World* world) {
  if (world != nullptr && (phases.size() != 1 || phases.front().worlds.size() != 1 || replay != nullptr)) {
    throw std::invalid_argument("runPhases: a given World is the single world of a single phase, stepped");
  }
  RunSummary summary;
  const auto wallStart = Clock::now();
  const ViewDesc& first = phases.front().scene().view;
  std::uint64_t totalFrames = 0, totalSteps = 0;
  const Phase* longest = &phases.front();
  for (const Phase& phase : phases) {
    const ViewDesc& view = phase.scene().view;
    if (view.width != first.width || view.height != first.height || view.fps != first.fps) {
      throw InputError(phase.file, "view", "every phase of one video needs the same size and fps as the first");
    }
    checkStepCounts(phase);
    totalFrames += frameCount(phase);  // each at most kHugeCount: the sum of a few cannot wrap
    for (const PhaseWorld& world : phase.worlds) totalSteps += world.scene.stepCount();
    if (frameCount(phase) > frameCount(*longest)) longest = &phase;
  }

  const bool wantImages = options.render && (!options.framesDir.empty() || !options.videoPath.empty());
  checkRunBudgets(phases, *longest, options, wantImages ? totalFrames : 0, totalSteps);
  if (!options.gltfPath.empty()) checkGltfRun(phases, options.gltfPath);
  checkOutputs(phases, options, wantImages, replay);
  if (wantImages && !options.framesDir.empty()) {
    const std::size_t stale = removeOldFrames(options.framesDir);
    if (stale > 0 && !options.quiet) {
      std::fprintf(stderr, "rbsim: --frames %s: removed %zu frames (frame_NNNNNN.png) of an earlier run, so that the "
                   "folder holds this run's alone\n", options.framesDir.c_str(), stale);
    }
  }
  // The trace first: opening it is cheap, and a bad path then fails before ffmpeg has started.
  std::optional<TraceWriter> trace;
  if (!options.tracePath.empty()) trace.emplace(options.tracePath);
  std::optional<RecordWriter> recorder;
  if (!options.recordPath.empty()) recorder.emplace(options.recordPath, recordingHeader(phases, options, title));
  std::optional<GltfFile> gltfFile;
  if (!options.gltfPath.empty()) gltfFile.emplace(options.gltfPath);
  GltfTrack gltfTrack(phases.front().scene().colors);  // the poses at every frame, for --gltf
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
    renderer = std::make_unique<render::OffscreenRenderer>(first.width, first.height, render::defaultShaderDir(),
                                                           render::OffscreenRenderer::kDefaultSamples,
                                                           options.glBackend);
  }

  // Progress counts what the run is waiting for: frames when it renders, steps otherwise.
  ProgressMeter meter(stderr, isTerminal(stderr), options.quiet);
  ProgressState progress;
  progress.items = phases.size();
  progress.kind = "phase";
  progress.unit = renderer ? "frames" : "steps";
  progress.total = renderer ? totalFrames : totalSteps;
  const auto report = [&] {
    progress.done = renderer ? summary.frames : summary.steps;
    progress.elapsedSeconds = secondsSince(wallStart);
    meter.update(progress);
  };

  std::uint64_t stepBase = 0;  // the trace's step column: the steps of the phases before this one
  for (const Phase& phase : phases) {
    ++progress.item;
    progress.name = std::filesystem::path(phase.file).stem().string();
    std::vector<World> worlds;
    worlds.reserve(phase.worlds.size());
    if (world != nullptr) worlds.push_back(std::move(*world));
    // The given World goes back to its owner however the phase ends, a failed step included.
    struct GiveBack {
      World* to;
      std::vector<World>& worlds;
      ~GiveBack() {
        if (to != nullptr && !worlds.empty()) *to = std::move(worlds.front());
      }
    } giveBack{world, worlds};
    if (world == nullptr) {
      for (const PhaseWorld& w : phase.worlds) worlds.push_back(renderer ? buildFramedWorld(w.scene) : buildWorld(w.scene));
    }
    // The overlay's error against the exact spin, of each world's selected body.
    std::vector<FreeFlightError> freeFlight;
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      freeFlight.emplace_back(selectedBodyId(worlds[k], phase.worlds[k].scene.view.selected));
      if (renderer) freeFlight.back().observe(worlds[k]);
    }
    TimePlots plots(phase);
    const auto traceRow = [&](std::size_t k) {
      const std::uint64_t step = stepBase + worlds[k].stepCount();
      if (trace && step % options.traceEvery == 0) {
        trace->write(worlds[k], step, worlds[k].time(), phase.compared() ? std::to_string(k) + "/" : "");
      }
    };
    const auto advance = [&](std::size_t k, std::uint64_t target) {
      while (worlds[k].stepCount() < target) {
        const auto start = Clock::now();
        if (replay != nullptr) {
          replay->restoreNext(k, worlds.size(), worlds[k]);
        } else {
          try {
            worlds[k].step();
          } catch (const StepLimitError& e) {
            // What the scene asks of a step is the file's fault: the message names it, and which
            // of the compared worlds (the brief: the file, the field, what was expected).
            const std::string which = phase.compared() ? " (" + phase.worlds[k].label + ")" : "";
            if (phase.file.empty()) throw;
            throw StepLimitError(phase.file + which + ": " + e.what());
          }
        }
        summary.simulateSeconds += secondsSince(start);
        if (recorder) recorder->write(k, worlds[k]);
        if (renderer) freeFlight[k].observe(worlds[k]);
        ++summary.steps;
        traceRow(k);
        if (!renderer) report();
      }
    };
    for (std::size_t k = 0; k < worlds.size(); ++k) traceRow(k);
    // A frame is begun, then the worlds step on to the next one while llvmpipe's threads
    // rasterise it, and only then is it finished and handed to the writers: on 2 cores the
    // simulation and the rasteriser overlap instead of taking turns.
    bool pending = false;
    const auto deliver = [&] {
      const std::shared_ptr<const std::vector<std::uint8_t>> pixels = renderer->finishShared();
      pending = false;
      const auto start = Clock::now();
      sink->submit(pixels);
      summary.submitSeconds += secondsSince(start);
      if (observer) observer(*pixels);
      ++summary.frames;
      report();
    };
    const double fps = phase.scene().view.fps;
    const std::uint64_t frames = frameCount(phase);
    for (std::uint64_t f = 0; f < frames;) {
      for (std::size_t k = 0; k < worlds.size(); ++k) {
        const Scene& scene = phase.worlds[k].scene;
        advance(k, std::min(stepOfFrame(f, fps, scene.settings.timeStep), scene.stepCount()));
      }
      if (!renderer) {
        // Without images only the steps matter: jump to the next frame at which some world moves
        // on (the same steps in the same order as when rendering, without visiting every frame).
        std::uint64_t next = frames;
        for (std::size_t k = 0; k < worlds.size(); ++k) {
          const Scene& scene = phase.worlds[k].scene;
          if (worlds[k].stepCount() >= scene.stepCount()) continue;
          next = std::min(next, firstFrameShowing(worlds[k].stepCount() + 1, fps, scene.settings.timeStep));
        }
        const std::uint64_t after = std::max(f + 1, next);
        if (gltfFile) gltfTrack.sample(worlds.front(), after - f);
        f = after;
        continue;
      }
      if (gltfFile) gltfTrack.sample(worlds.front());
      const auto start = Clock::now();
      render::FrameData frame = buildPhaseFrame(worlds, phase, title, &freeFlight);
      if (!plots.empty()) {
        plots.sample(worlds, &freeFlight);
        frame.overlay.plots = plots.plots();
      }
      summary.buildSeconds += secondsSince(start);
      if (pending) deliver();
      renderer->begin(frame);
      pending = true;
      ++f;
    }
    if (pending) deliver();
    std::uint64_t longestSteps = 0;
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      advance(k, phase.worlds[k].scene.stepCount());  // past the last frame, as the trace expects
      longestSteps = std::max(longestSteps, phase.worlds[k].scene.stepCount());
    }
    stepBase += longestSteps;
  }
  if (trace) trace->close();
  if (replay != nullptr) replay->expectEnd();
  if (gltfFile) {  // after a replay's end is checked: a damaged recording leaves the file empty
    gltfFile->write(gltfTrack, first.fps, title.empty() ? phases.front().scene().title : title);
    summary.gltfBodies = gltfTrack.bodies().size();
    summary.gltfFrames = gltfTrack.frames();
  }
  if (recorder) {
    recorder->close();
    summary.recordBytes = recorder->fileBytes();
    summary.recordBodySteps = recorder->bodySteps();
    summary.recordSnapshots = recorder->snapshots();
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
    summary.passFrames = drawn.passFrames;
    summary.passMs = drawn.passMs;
  }
  meter.finish();
  summary.wallSeconds = secondsSince(wallStart);
  return summary;
}

void printSummary(const RunSummary& s, const RunOptions& options) {
  if (options.quiet) return;
  std::printf("steps %llu, frames %llu, wall %.2f s\n", static_cast<unsigned long long>(s.steps),
              static_cast<unsigned long long>(s.frames), s.wallSeconds);
  std::printf("simulate: %.4f ms per step\n", s.steps ? 1e3 * s.simulateSeconds / s.steps : 0.0);
  if (s.recordBodySteps > 0) {
    std::printf("recording: %s, %llu bytes, %.1f bytes per body-step, %llu steps changed the bodies\n",
                options.recordPath.c_str(), static_cast<unsigned long long>(s.recordBytes),
                static_cast<double>(s.recordBytes) / static_cast<double>(s.recordBodySteps),
                static_cast<unsigned long long>(s.recordSnapshots));
  }
  if (s.frames > 0) {
    const double perFrame = 1e3 / static_cast<double>(s.frames);
    std::printf("ms per frame: simulate %.2f, build %.2f, render %.2f, readback %.2f, hand-off %.2f; "
                "on writer threads, in parallel: png %.2f, video %.2f; final flush %.0f ms\n",
                perFrame * s.simulateSeconds, perFrame * s.buildSeconds, perFrame * s.renderSeconds,
                perFrame * s.readbackSeconds, perFrame * s.submitSeconds, s.pngMsPerFrame,
                s.videoMsPerFrame, 1e3 * s.finishSeconds);
  }
  if (s.passFrames > 0) {
    // Each pass finished before the next began, so these add up to a little more than render.
    std::printf("render passes (ms, %ld frames finished after each pass):", s.passFrames);
    for (int k = 0; k < render::kRenderPassCount; ++k) {
      std::printf("%s %s %.2f", k == 0 ? "" : ",", render::kRenderPassNames[k], s.passMs[k]);
    }
    std::printf("\n");
  }
  if (!options.videoPath.empty() && s.frames > 0) std::printf("video: %s\n", options.videoPath.c_str());
  if (!options.framesDir.empty() && s.frames > 0) std::printf("frames: %s\n", options.framesDir.c_str());
  if (!options.tracePath.empty()) std::printf("trace: %s\n", options.tracePath.c_str());
  if (!options.gltfPath.empty()) {
    std::printf("gltf: %s, %zu bodies, %llu frames\n", options.gltfPath.c_str(), s.gltfBodies,
                static_cast<unsigned long long>(s.gltfFrames));
  }
}

}  // namespace rbsim::app

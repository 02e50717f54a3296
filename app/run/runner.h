#pragma once
// Runs scenes: steps the World, renders frames at the scene's fps, streams them to PNG files
// and an MP4, writes the trace, and reports where the time went.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/timing.h"
#include "run/frame_steps.h"
#include "run/phase.h"
#include "run/run_options.h"
#include "rbsim/scene/scene.h"

namespace rbsim::app {

class RecordReader;  // record/recording.h

struct RunSummary {
  std::uint64_t steps = 0;
  std::uint64_t frames = 0;
  double simulateSeconds = 0.0;  // World::step
  double buildSeconds = 0.0;     // World -> FrameData
  double renderSeconds = 0.0;    // issuing each frame and waiting for its rasteriser (begin + finish)
  double readbackSeconds = 0.0;  // the finished image flipped into a top-down RGBA buffer
  double submitSeconds = 0.0;    // hand-off to the writer threads (blocks only on a full queue)
  double pngMsPerFrame = 0.0;    // deflate + write of one PNG on a worker thread (in parallel)
  double videoMsPerFrame = 0.0;  // pipe write of one frame to ffmpeg (waits while it encodes)
  double finishSeconds = 0.0;    // waiting for the writers after the last frame
  long passFrames = 0;           // frames timed pass by pass (render/pass_clock.h)
  std::array<double, render::kRenderPassCount> passMs{};  // mean ms per pass on those frames
  double wallSeconds = 0.0;
  std::uint64_t recordBytes = 0;      // the recording's size (--record) [bytes]
  std::uint64_t recordBodySteps = 0;  // bodies x steps it holds
  std::uint64_t recordSnapshots = 0;  // steps whose entry carries a World snapshot (bodies changed)
  std::size_t gltfBodies = 0;         // the --gltf file's nodes: bodies, and pieces broken off
  std::uint64_t gltfFrames = 0;       // its keys per node
};

// Throws InputError naming world.duration if a world of the phase would run 0 steps (a duration
// under dt / 2): it would show one still frame and say nothing.
void checkStepCounts(const Phase& phase);

// Called with every rendered image (top-down RGBA8) after it went to the run's own outputs:
// `rbsim demo all` copies it into the reel and counts it for the progress line.
using FrameObserver = std::function<void(const std::vector<std::uint8_t>& rgbaTopDown)>;

// Plays the phases one after another into the same frames folder and video (a demo's phases).
// Every phase must have the same image size and fps. `title` heads the overlay (the scene's own
// title when empty). The worlds of a compared phase (phase.h) advance in lockstep: before frame
// k each one is stepped to its own step nearest k / fps (so worlds of different dt stay at the
// same time) and all are drawn into the frame; the phase lasts as long as its longest world.
// The trace has every world's rows; a compared world's bodies are named "K/NAME" for world K.
// RunSummary::steps counts the steps of every world. Before anything runs, a phase of 0 steps and
// a video past output_budget.h's limits are refused (InputError); a run prints progress on stderr
// unless options.quiet. Every output is checked: a failed write throws naming the file.
// With `replay` (rbsim replay), the worlds are not stepped: each step's state is read from the
// recording instead, which must be of these phases (InputError otherwise, or when it is cut short).
// With options.recordPath every step's state is recorded (record/recording.h); with
// options.gltfPath the bodies and their pose at every frame go to a glTF file (export/), which
// a run of several phases or a compared phase cannot have (InputError).
// With `world` (Python's World.run), the single world of a single phase is that World, stepped in
// place from its step count on, instead of one built from the scene; it must be the World the
// scene describes. It is moved back into `world` however the run ends.
RunSummary runPhases(const std::vector<Phase>& phases, const RunOptions& options, const std::string& title,
                     const FrameObserver& observer = {}, RecordReader* replay = nullptr, World* world = nullptr);

void printSummary(const RunSummary& summary, const RunOptions& options);

}  // namespace rbsim::app

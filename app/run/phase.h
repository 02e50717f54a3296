#pragma once
// One phase of a video: a scene file run as one World or, when the scene has a "compare" block,
// as one World per value of one scene key, stepped in lockstep and drawn side by side in one
// frame, each in a pane of its own under a caption naming its value (docs/scene-format.md,
// "Comparing settings side by side"):
//
//   "compare": {"key": "world.solver", "values": ["pgs", "soft-step"], "labels": ["PGS", "soft step"]}
//
// Each value is applied to the scene document exactly as `--set KEY=VALUE` would be
// (engine/src/scene/override.cpp), after the command line's own --set assignments, so a compared
// value is checked by the same code as the key written in the file.
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/math/types.h"
#include "rbsim/scene/scene.h"

namespace rbsim::app {

// More worlds than this in one frame leaves each too small to see; most likely a typo.
inline constexpr std::size_t kMaxComparedWorlds = 8;

struct PhaseWorld {
  Scene scene;                 // the scene with this world's value applied
  std::string value;           // the value as JSON text ("\"pgs\""); empty for a plain scene
  std::string label;           // its caption: compare.labels[k], or "KEY = VALUE"
};

struct Phase {
  std::string file;
  // The scene file's text when the phase was made from text that is no file (Python's World.run):
  // what a recording keeps of it. Empty: a recording reads `file`.
  std::string text;
  std::string compareKey;          // empty: a plain scene (one world, no caption)
  std::vector<PhaseWorld> worlds;  // at least one
  // The first world's scene: its view (camera, size, fps), title and caption are the frame's,
  // and the overlay's selected-body panel follows its world.
  const Scene& scene() const { return worlds.front().scene; }
  bool compared() const { return !compareKey.empty(); }
};

// Reads a scene file, applies the `overrides` ("path=value", the --set flag) to the whole
// document (so --set may change the compare block itself), then builds one Scene per compared
// value. Throws InputError naming the file and the field (e.g. "compare.values[1]").
Phase loadPhase(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for the text of a scene file; `file` names it in messages.
Phase parsePhaseText(const std::string& text, const std::string& file, const std::string& baseDir,
                     const std::vector<std::string>& overrides = {});

// A phase of one plain, already parsed scene.
Phase singleWorldPhase(Scene scene);

// The id of a world's selected body (view.selected, an index into its scene's bodies), or no
// body's when the scene has none: what FreeFlightError watches.
inline BodyId selectedBodyId(const World& world, std::size_t selected) {
  return selected < world.bodies().size() ? world.idAt(selected) : BodyId{};
}

// Frames a phase renders: those of its longest world (frame_steps.h's frameCount).
std::uint64_t frameCount(const Phase& phase);

// The world of a scene whose frames are drawn (video, PNGs, window): on one thread unless the
// scene gives world.threads. While frames are made, llvmpipe's rasterising threads and x264's
// encoder keep every core busy, and more physics threads only wait for a core (`rbsim demo 3`,
// 721 frames at 60 fps: 26.2 s on two threads, 15.9 s on one; docs/speed.md). A step's result
// is the same, bit for bit, on any number of threads (Settings::threads).
World buildFramedWorld(const Scene& scene);

}  // namespace rbsim::app

#pragma once
// One phase of a video: a scene file run as one World or, when the scene has a "compare" block,
// as one World per value of one scene key, stepped in lockstep and drawn side by side in one
// frame, each under a caption naming its value (README "Comparing settings side by side"):
//
//   "compare": {"key": "world.solver", "values": ["pgs", "soft-step"],
//               "labels": ["PGS", "soft step"], "offset": [30, 0, 0]}
//
// Each value is applied to the scene document exactly as `--set KEY=VALUE` would be
// (engine/scene/override.cpp), after the command line's own --set assignments, so a compared
// value is checked by the same code as the key written in the file.
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/math/types.h"
#include "rbsim/scene/scene.h"

namespace rbsim::app {

// More worlds than this in one frame leaves each too small to see; most likely a typo.
inline constexpr std::size_t kMaxComparedWorlds = 8;
// Without "offset", world k is moved k times the x-extent of the first world's bodies at t = 0
// times this, so a quarter of their width separates neighbours [1]...
inline constexpr double kCompareSpacingFactor = 1.25;
// ...and at least this far apart, for scenes of small bodies or none [m].
inline constexpr double kMinCompareSpacing = 2.0;
// A world's caption hangs below the front edge of its bodies' box at t = 0, this far in front
// of it, on the ground in front of the world and clear of the overlay panel at the top left [m].
inline constexpr double kCompareLabelAhead = 0.5;

struct PhaseWorld {
  Scene scene;                 // the scene with this world's value applied
  std::string value;           // the value as JSON text ("\"pgs\""); empty for a plain scene
  std::string label;           // its caption: compare.labels[k], or "KEY = VALUE"
  Vec3 offset = Vec3::Zero();  // its drawing is moved by this [m] (k times compare.offset)
  Vec3 labelAnchor = Vec3::Zero();  // its caption's top centre, offset included [m]
};

struct Phase {
  std::string file;
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

// Frames a phase renders: those of its longest world (runner.h's frameCount).
std::uint64_t frameCount(const Phase& phase);

}  // namespace rbsim::app

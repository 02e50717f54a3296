#pragma once
// `rbsim demo N --window` and `rbsim run SCENE --window`: the scene in an X11 window, drawn by the
// off-screen renderer, with the control panel, an orbit camera, picking and dragging bodies.
#include <cstdint>
#include <string>
#include <vector>

#include "render/gl_context.h"

namespace rbsim::app {

struct SceneSource {
  std::vector<std::string> files;      // a demo's phases, or the one scene file
  std::vector<std::string> overrides;  // from the command line (--set and the flags behind it)
  std::string title;                   // overlay title ("" : the scene's own)
};

struct WindowOptions {
  std::uint64_t frames = 0;  // close after this many frames (0: when the user closes it)
  double speed = 1.0;        // playback: simulated seconds per second, in [kMinPlaybackSpeed, kMaxPlaybackSpeed]
  std::string screenshot;    // write the window's last frame here as PNG (read back from X)
  render::GlBackend glBackend = render::defaultGlBackend();  // --gl
  bool quiet = false;
};

// Runs until the window is closed (q, Escape, the close button) or `frames` have been shown.
// Throws WindowError without a display, InputError for a bad scene at start.
void runWindow(const SceneSource& source, const WindowOptions& options);

}  // namespace rbsim::app

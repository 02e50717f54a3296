#pragma once
// The window's control panel (Dear ImGui, drawn by the renderer's overlay pass at the right of
// the image). It shows the scene's options and asks for changes as scene-key assignments, the
// same "path=value" strings as --set, so whatever is explored in the window can be replayed
// headless. It changes nothing itself: the session applies the requests.
#include <cstddef>
#include <string>
#include <vector>

#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "run/scene_catalogue.h"

namespace rbsim::app {

inline constexpr std::size_t kPlotSamples = 240;  // frames of history in the plots
// The playback speed's range: from slow motion to a fast forward the renderer can keep up with at
// small sizes [simulated seconds per second].
inline constexpr double kMinPlaybackSpeed = 0.1;
inline constexpr double kMaxPlaybackSpeed = 4.0;

// Per-frame history of the selected body, for the plots.
struct PlotHistory {
  std::vector<float> speed;          // |v| [m/s]
  std::vector<float> angularSpeed;   // |omega| [rad/s]
  std::vector<float> kineticEnergy;  // [J]
  void add(const RigidBody& body);
  void clear();
};

struct PanelView {  // what the panel shows
  const Scene* scene = nullptr;
  std::vector<SceneEntry> scenes;   // the shipped scenes, for the scene picker
  const World* world = nullptr;
  const PlotHistory* history = nullptr;
  std::vector<std::string> phases;  // scene files of a demo (one for `rbsim run`)
  std::size_t phase = 0;
  bool paused = false;
  bool recording = false;
  std::string recordingPath;
  std::string message;  // the last error or the copied command line
  double speed = 1.0;   // playback speed asked for: simulated seconds per second [1]
  double shownRate = 1.0;  // what the window achieves: simulated seconds per real second [1]
};

struct PanelRequests {  // what the user asked for this frame
  bool togglePause = false, step = false, reset = false, toggleRecording = false, copyCommand = false;
  int phase = -1;  // switch to this demo phase
  std::string scene;  // open this scene file instead (the scene picker)
  double speed = 0.0;  // a new playback speed; 0: unchanged
  // Scene-key assignments: `restart` ones (physics) rebuild the World from t = 0, the others
  // (view) take effect at once.
  struct Assignment {
    std::string path, value;
    bool restart = false;
  };
  std::vector<Assignment> assignments;
};

// The panel's rectangle: the right-hand side of the image [px].
struct PanelRect {
  float x, y, width, height;
};
PanelRect panelRect(int imageWidth, int imageHeight);

// ImGui calls; run inside the renderer's ImGui frame (render::UiFrame::draw).
PanelRequests drawControlPanel(const PanelView& view, int imageWidth, int imageHeight);

}  // namespace rbsim::app

// The scenes that ship in assets/scenes, by name: `rbsim list` shows them with their titles and
// `rbsim run NAME` finds one without its path. A path that names nothing gets "did you mean"
// suggestions from the folder it points into and from the shipped scenes.
#pragma once

#include <string>
#include <vector>

namespace rbsim::app {

struct SceneEntry {
  std::string name;   // path under assets/scenes without ".json": "contact_stacking", "box3d/large_pyramid"
  std::string path;   // the file
  std::string title;  // the scene's "title", or "" when it has none or cannot be read
};

// Every *.json under the asset folder's scenes/ (one level of subfolders), sorted by name.
std::vector<SceneEntry> shippedScenes();

// The file `argument` means: itself when something exists there; else the shipped scene of that
// name (with or without ".json"). Throws InputError naming the argument, with the nearest names,
// when it is neither.
std::string resolveScene(const std::string& argument);

}  // namespace rbsim::app

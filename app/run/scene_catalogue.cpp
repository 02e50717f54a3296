#include "run/scene_catalogue.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/json_fields.h"
#include "run/paths.h"

namespace rbsim::app {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSceneExtension = ".json";

std::string readTitle(const fs::path& file) {
  std::ifstream in(file);
  const nlohmann::json scene = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!scene.is_object() || !scene.contains("title") || !scene["title"].is_string()) return "";
  return scene["title"].get<std::string>();
}

// The regular *.json files directly in `folder`, by file name; none when it cannot be listed.
std::vector<fs::path> jsonFilesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (it->is_regular_file(error) && it->path().extension() == kSceneExtension) files.push_back(it->path());
  }
  return files;
}

}  // namespace

std::vector<SceneEntry> shippedScenes() {
  const fs::path root = fs::path(assetDir()) / "scenes";
  std::vector<SceneEntry> scenes;
  auto addFolder = [&](const fs::path& folder, const std::string& prefix) {
    for (const fs::path& file : jsonFilesIn(folder)) {
      scenes.push_back({prefix + file.stem().string(), file.string(), readTitle(file)});
    }
  };
  addFolder(root, "");
  std::error_code error;
  for (fs::directory_iterator it(root, error), end; !error && it != end; it.increment(error)) {
    if (it->is_directory(error)) addFolder(it->path(), it->path().filename().string() + "/");
  }
  std::sort(scenes.begin(), scenes.end(), [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
  return scenes;
}

std::string resolveScene(const std::string& argument) {
  std::error_code error;
  if (fs::exists(fs::symlink_status(argument, error))) return argument;
  const std::string extension = kSceneExtension;
  std::string name = argument;
  if (name.size() > extension.size() && name.compare(name.size() - extension.size(), extension.size(), extension) == 0) {
    name.resize(name.size() - extension.size());
  }
  const std::vector<SceneEntry> scenes = shippedScenes();
  std::vector<std::string> names;
  for (const SceneEntry& scene : scenes) {
    if (scene.name == name) return scene.path;
    names.push_back(scene.name);
  }
  // Suggestions: a file beside the one named (a typo in the file name), or a shipped scene.
  const fs::path given(argument);
  std::vector<std::string> beside;
  for (const fs::path& file : jsonFilesIn(given.has_parent_path() ? given.parent_path() : fs::path("."))) {
    beside.push_back(file.filename().string());
  }
  std::string hint;
  if (const std::string near = nearestKey(given.filename().string(), beside); !near.empty()) {
    hint = " (did you mean " + (given.parent_path() / near).string() + "?)";
  } else if (const std::string near = nearestKey(name, names); !near.empty()) {
    hint = " (did you mean the shipped scene " + near + "?)";
  }
  throw InputError(argument, "", "no such file, and no scene of that name in " + assetDir() + "/scenes" + hint +
                                     "; `rbsim list` names the shipped scenes");
}

}  // namespace rbsim::app

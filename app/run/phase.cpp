#include "run/phase.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rbsim/io/input_error.h"
#include "run/frame_steps.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/world_keys.h"

namespace rbsim::app {

namespace {

// "pgs" for a string, the JSON text otherwise: how a value reads in a caption.
std::string shown(const nlohmann::json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

// A --set assignment that changes the compared key (or something inside it) would be replaced
// by every world's own value: refused rather than silently lost.
void refuseOverridesOfTheKey(const std::vector<std::string>& overrides, const std::string& key,
                             const std::string& file) {
  const std::vector<std::string> keyParts = splitScenePath(key);
  for (const std::string& assignment : overrides) {
    const std::vector<std::string> parts = splitScenePath(assignment.substr(0, assignment.find('=')));
    if (parts.size() >= keyParts.size() && std::equal(keyParts.begin(), keyParts.end(), parts.begin())) {
      throw InputError(file, "--set " + assignment,
                       "sets " + key + ", which compare.key gives each world from compare.values; change "
                       "compare.values instead (e.g. --set 'compare.values=[...]')");
    }
  }
}

// Every world's scene is described from the one document with its value applied; the shapes the
// values leave alone are described once, and each distinct grid or hierarchy is cooked once for
// all of them (rbsim/scene/cook.h).
Phase parseCompared(nlohmann::json document, const std::string& file, const std::string& baseDir,
                    const std::vector<std::string>& overrides) {
  const nlohmann::json block = document["compare"];
  document.erase("compare");  // the engine's scene parser knows nothing of it
  const JsonObject c(block, file, "compare", kCompareKeys);
  const std::string key = c.requiredString("key");
  const std::vector<std::string> parts = splitScenePath(key);
  if (parts.empty()) c.fail("key", "expected a scene key in --set form, such as world.solver or bodies.box.mass");
  const std::string expected = "; expected a key of world, bodies, planes, particles, soft_bodies or planar";
  if (parts.front() == "view") c.fail("key", "\"" + key + "\": every world is drawn with the one view" + expected);
  if (parts.front() == "compare") c.fail("key", "\"" + key + "\": a comparison cannot compare itself" + expected);
  if (!c.has("values")) c.fail("values", "missing; expected an array of 2 to " + std::to_string(kMaxComparedWorlds) + " values of " + key);
  const nlohmann::json& values = c.raw("values");
  if (!values.is_array() || values.size() < 2 || values.size() > kMaxComparedWorlds) {
    c.fail("values", "expected an array of 2 to " + std::to_string(kMaxComparedWorlds) + " values of " + key +
                         " (one world each), got " +
                         (values.is_array() ? std::to_string(values.size()) + (values.size() == 1 ? " value" : " values") : values.dump()));
  }
  for (std::size_t k = 1; k < values.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      if (values[k] == values[j]) {
        throw InputError(file, "compare.values[" + std::to_string(k) + "]",
                         "repeats compare.values[" + std::to_string(j) + "] (" + values[j].dump() +
                             "); every world needs a value of its own");
      }
    }
  }
  std::vector<std::string> labels;
  if (c.has("labels")) {
    const nlohmann::json& l = c.raw("labels");
    if (!l.is_array() || l.size() != values.size() ||
        !std::all_of(l.begin(), l.end(), [](const nlohmann::json& s) { return s.is_string(); })) {
      c.fail("labels", "expected an array of " + std::to_string(values.size()) + " strings, one caption per value");
    }
    for (const nlohmann::json& s : l) labels.push_back(s.get<std::string>());
  }
  refuseOverridesOfTheKey(overrides, key, file);

  Phase phase;
  phase.file = file;
  phase.compareKey = key;
  SceneCache cache;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const std::string field = "compare.values[" + std::to_string(k) + "]";
    nlohmann::json variant = document;
    try {
      applyOverride(variant, key + "=" + values[k].dump());  // the --set path
    } catch (const InputError& e) {
      throw InputError(file, "compare.key", "\"" + key + "\": " + e.problem());
    }
    PhaseWorld world;
    try {
      world.scene = describeScene(variant, file, baseDir, &cache);
      cookScene(world.scene, &cache);
    } catch (const InputError& e) {
      Scene plain = describeScene(document, file, baseDir, &cache);  // a fault of the scene itself is reported as such
      cookScene(plain, &cache);
      // A misspelt key is the key's fault, not the value's.
      if (e.field() == key && e.problem().rfind("unknown key", 0) == 0) throw InputError(file, "compare.key", "\"" + key + "\": " + e.problem());
      throw InputError(file, field, key + " = " + values[k].dump() + " gives a bad scene: " + e.field() + ": " + e.problem());
    }
    world.value = values[k].dump();
    world.label = labels.empty() ? key + " = " + shown(values[k]) : labels[k];
    phase.worlds.push_back(std::move(world));
  }
  return phase;
}

}  // namespace

Phase singleWorldPhase(Scene scene) {
  Phase phase;
  phase.file = scene.file;
  PhaseWorld world;
  world.scene = std::move(scene);
  phase.worlds.push_back(std::move(world));
  return phase;
}

Phase parsePhaseText(const std::string& text, const std::string& file, const std::string& baseDir,
                     const std::vector<std::string>& overrides) {
  nlohmann::json document = readSceneDocument(text, file, overrides);
  if (!document.is_object() || !document.contains("compare")) {
    return singleWorldPhase(parseScene(document, file, baseDir));
  }
  return parseCompared(std::move(document), file, baseDir, overrides);
}

Phase loadPhase(const std::string& path, const std::vector<std::string>& overrides) {
  return parsePhaseText(readSceneFile(path), path, std::filesystem::path(path).parent_path().string(), overrides);
}

std::uint64_t frameCount(const Phase& phase) {
  std::uint64_t frames = 0;
  for (const PhaseWorld& world : phase.worlds) frames = std::max(frames, frameCount(world.scene));
  return frames;
}

World buildFramedWorld(const Scene& scene) {
  if (scene.threadsGiven || scene.settings.threads == 1) return buildWorld(scene);
  Scene oneThread = scene;
  oneThread.settings.threads = 1;
  return buildWorld(oneThread);
}

}  // namespace rbsim::app

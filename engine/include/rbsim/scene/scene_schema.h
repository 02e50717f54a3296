#pragma once
// A JSON Schema (draft 2020-12) of scene files, built from the parser's own key tables
// (scene_keys.h): an editor given it completes keys, shows each key's line of description and
// marks a misspelt key, a wrong type or a value out of range as the file is typed. `rbsim schema`
// prints it; docs/scene.schema.json is that output, and docs/scene-format.md says how to use it.
#include <nlohmann/json.hpp>

namespace rbsim {

// The schema of a scene file as `rbsim run` reads it: the engine's blocks and the run command's
// "compare" block. Checks each key's name, type and range; what depends on other keys or on
// files (a mesh's volume, a body named by a joint) is the parser's alone.
nlohmann::json sceneSchema();

}  // namespace rbsim

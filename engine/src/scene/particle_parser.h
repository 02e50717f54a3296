#pragma once
// Scene-file parsing of "particles" blocks into ParticleSystemDef and ParticleLook (keys in
// docs/scene-format.md, "Particle systems"). Internal to scene/; bodies and planes must be parsed
// first.
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim::scene_detail {

void parseParticleSystems(const JsonObject& root, Scene& scene);

}  // namespace rbsim::scene_detail

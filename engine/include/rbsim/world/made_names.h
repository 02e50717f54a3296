#pragma once
// The names the World gives the bodies it makes itself (issue 56, item 4): a ragdoll's bones
// (NAME_bone, world/ragdoll.h) and a periodic spawner's copies (NAME_k, or NAME_k_bone for a
// ragdoll spawner, world/spawner.h). A name given by a scene or by Python is checked against
// these before anything is made, so every body's name stays unique while the World steps.
//
// Two spawners with different names never make the same name: k is digits and a bone's name has
// none, so NAME_k(_bone) parses back to one NAME only.
#include <array>
#include <functional>
#include <string>

#include "rbsim/world/ragdoll.h"
#include "rbsim/world/spawner.h"

namespace rbsim {

// The names addRagdoll gives the bones of ragdoll `ragdoll`, indexed by Bone.
std::array<std::string, kBoneCount> ragdollBodyNames(const std::string& ragdoll);

// Whether a burst of `spawner` may one day name a body `name`.
bool spawnerMakesName(const SpawnerDef& spawner, const std::string& name);

// Why `name` cannot be given beside `spawner`, for a message: "the spawner "S" names the bodies
// it makes S_k (k = 0, 1, ...), and may make "NAME"; expected a name of its own".
std::string madeNameProblem(const SpawnerDef& spawner, const std::string& name);

// An unnamed spawner's name: the first of "spawn", "spawn1", "spawn2", ... that is not `taken`.
std::string freeSpawnerName(const std::function<bool(const std::string&)>& taken);

}  // namespace rbsim

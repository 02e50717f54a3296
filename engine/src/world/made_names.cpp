#include "rbsim/world/made_names.h"

#include <algorithm>
#include <cctype>

namespace rbsim {

namespace {

bool isCount(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

std::array<std::string, kBoneCount> ragdollBodyNames(const std::string& ragdoll) {
  std::array<std::string, kBoneCount> names;
  for (std::size_t i = 0; i < kBoneCount; ++i) names[i] = ragdoll + "_" + boneName(static_cast<Bone>(i));
  return names;
}

std::string freeSpawnerName(const std::function<bool(const std::string&)>& taken) {
  std::string name = "spawn";
  for (std::size_t n = 1; taken(name); ++n) name = "spawn" + std::to_string(n);
  return name;
}

std::string madeNameProblem(const SpawnerDef& spawner, const std::string& name) {
  return "the spawner \"" + spawner.name + "\" names the bodies it makes " + spawner.name + "_k" + (spawner.ragdoll ? "_bone" : "") +
         " (k = 0, 1, ...), and may make \"" + name + "\"; expected a name of its own";
}

bool spawnerMakesName(const SpawnerDef& spawner, const std::string& name) {
  const std::string prefix = spawner.name + "_";
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string rest = name.substr(prefix.size());  // k, or k_bone
  if (!spawner.ragdoll) return isCount(rest);
  const std::size_t cut = rest.find('_');
  if (cut == std::string::npos || !isCount(rest.substr(0, cut))) return false;
  const std::string bone = rest.substr(cut + 1);
  for (std::size_t i = 0; i < kBoneCount; ++i) {
    if (bone == boneName(static_cast<Bone>(i))) return true;
  }
  return false;
}

}  // namespace rbsim

#include "render/body_colors.h"

#include <algorithm>
#include <cctype>

namespace rbsim::app {

namespace {

bool allDigits(const std::string& s, std::size_t from) {
  return from < s.size() && std::all_of(s.begin() + static_cast<std::ptrdiff_t>(from), s.end(),
                                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

}  // namespace

Vec3 bodyColor(const BodyColors& colors, const std::string& name) {
  std::string n = name;
  for (;;) {
    if (const auto listed = colors.byBody.find(n); listed != colors.byBody.end()) return listed->second;
    // NAME_k: a copy of the spawner NAME (engine/src/world/made_names.cpp names them so).
    const std::size_t underscore = n.rfind('_');
    if (underscore != std::string::npos && allDigits(n, underscore + 1)) {
      const auto spawner = colors.bySpawner.find(n.substr(0, underscore));
      if (spawner != colors.bySpawner.end()) return spawner->second;
    }
    // BODY/k: piece k of BODY (engine/src/fracture/fracture.cpp), drawn as the body it broke from.
    const std::size_t slash = n.rfind('/');
    if (slash == std::string::npos || !allDigits(n, slash + 1)) return kDefaultBodyColor;
    n.resize(slash);
  }
}

}  // namespace rbsim::app

// Scene::mostBodiesAtOnce: what the budgets of a run's outputs count (issue 56, item 1).
#include <algorithm>
#include <cmath>

#include "rbsim/scene/scene.h"
#include "rbsim/world/spawner.h"

namespace rbsim {

double Scene::mostBodiesAtOnce() const {
  double bodies = static_cast<double>(this->bodies.size()) + static_cast<double>(ragdolls.size()) * static_cast<double>(kBoneCount);
  for (const SpawnerDef& spawner : spawners) {
    // Bursts at start, start + period, ... before end and within the run.
    const double last = std::min(spawner.end, duration);
    if (!(last >= spawner.start)) continue;
    const double bursts = burstsAliveAtOnce(std::floor((last - spawner.start) / spawner.period) + 1.0, spawner.lifetime,
                                            spawner.period);
    const double perBurst = static_cast<double>(spawner.count) * static_cast<double>(spawner.offsets.size()) *
                            (spawner.ragdoll ? static_cast<double>(kBoneCount) : 1.0);
    bodies += bursts * perBurst;
  }
  return bodies;
}

}  // namespace rbsim

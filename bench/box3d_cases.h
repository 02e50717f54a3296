#pragma once
// What box3d_scenes (rbsim) and bullet_box3d_scenes (Bullet) share: Box3D's benchmark scenes with
// the step counts Box3D's `benchmark` program runs them for (issue 34's table), the process's CPU
// time, and the --scenes list.
#include <sys/resource.h>

#include <sstream>
#include <string>
#include <vector>

namespace rbsim::bench {

struct Box3dScene {
  const char* name;  // assets/scenes/box3d/<name>.json
  int steps;         // Box3D's benchmark program's step count for the scene
  // bullet_box3d_scenes builds it too: its loader knows boxes, spheres, hull files and ball joints,
  // not compound bodies or kinematic motions (the washer's drum, the junkyard's walls and pusher, the
  // trees), ragdolls, spawners (rain, large_world) or mesh grounds (rain, trees).
  bool inBullet;
};

inline constexpr Box3dScene kBox3dScenes[] = {{"large_pyramid", 200, true},
                                              {"many_pyramids", 100, true},
                                              {"joint_grid", 100, true},
                                              {"convex_pile", 500, true},
                                              {"washer", 1000, false},
                                              {"rain", 400, false},
                                              {"junkyard", 500, false},
                                              {"large_world", 500, false},
                                              {"trees100", 500, false},
                                              {"trees50", 500, false},
                                              {"trees25", 500, false}};

// User and system time of every thread of this process so far [s].
inline double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// "a,b,c" -> {"a", "b", "c"}.
inline std::vector<std::string> splitCommas(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

}  // namespace rbsim::bench

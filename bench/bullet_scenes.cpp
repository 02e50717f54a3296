// Issue 18's stacking scenes (bench/stack_layout.h: columns of 10, 20 and 40 unit boxes, a
// pyramid wall of 20 rows and Box3D's large_pyramid of 90 rows) in Bullet 3.24 (Debian's
// libbullet-dev), beside contact_scenes for rbsim: dt = 1/60 s, Bullet's default 10 solver
// iterations, friction 0.6, 10 s, with sleeping off and on. Prints the same figures as
// contact_scenes: the top box's horizontal drift, height lost, the farthest any box ended from
// its start, the fastest box, the median ms per step, and the boxes awake.
//   usage: bullet_scenes [scene ...]   (default: all five)
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bullet_world.h"
#include "stack_layout.h"

using namespace rbsim::bench;

namespace {

void run(const std::string& name, const std::vector<BoxCentre>& layout, bool allowSleep) {
  BulletWorld bw(kStackBoxSize, kStackFriction);
  bw.world.setGravity(btVector3(0, btScalar(-9.81), 0));
  bw.add(&bw.groundShape, 0, btVector3(0, 0, 0));
  std::vector<btRigidBody*> boxes;
  for (const BoxCentre& c : layout) {
    btRigidBody* box = bw.add(&bw.boxShape, btScalar(kStackBoxMass), btVector3(btScalar(c.x), btScalar(c.y), btScalar(c.z)));
    if (!allowSleep) box->setActivationState(DISABLE_DEACTIVATION);
    boxes.push_back(box);
  }
  const int steps = static_cast<int>(kStackSeconds / kStackTimeStep + 0.5);
  std::vector<double> ms;
  for (int step = 0; step < steps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    bw.world.stepSimulation(btScalar(kStackTimeStep), 0);  // exactly one step, no interpolation
    ms.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  double farthest = 0.0, fastest = 0.0;
  std::size_t awake = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const btVector3 p = boxes[i]->getWorldTransform().getOrigin();
    farthest = std::max(farthest, std::sqrt(std::pow(p.x() - layout[i].x, 2) + std::pow(p.y() - layout[i].y, 2) +
                                            std::pow(p.z() - layout[i].z, 2)));
    fastest = std::max(fastest, static_cast<double>(boxes[i]->getLinearVelocity().length()));
    if (boxes[i]->isActive()) ++awake;
  }
  const btVector3 top = boxes.back()->getWorldTransform().getOrigin();
  const BoxCentre& topStart = layout.back();
  const double drift = std::hypot(top.x() - topStart.x, top.z() - topStart.z);
  std::printf("%-14s %5zu boxes  bullet    sleep %-3s  top drift %8.4f m  height lost %8.4f m  farthest %8.4f m  "
              "fastest %7.4f m/s  %8.3f ms/step  %zu awake\n",
              name.c_str(), layout.size(), allowSleep ? "on" : "off", drift, topStart.y - top.y(), farthest, fastest,
              ms[ms.size() / 2], awake);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::pair<std::string, std::vector<BoxCentre>>> scenes{
      {"stack10", columnLayout(10)},     {"stack20", columnLayout(20)},     {"stack40", columnLayout(40)},
      {"pyramid20", pyramidLayout(20)}, {"large_pyramid", pyramidLayout(90)}};
  std::vector<std::string> wanted(argv + 1, argv + argc);
  std::printf("Bullet %d, %s precision\n", btGetVersion(), sizeof(btScalar) == 8 ? "double" : "float");
  for (const auto& [name, layout] : scenes) {
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), name) == wanted.end()) continue;
    run(name, layout, false);
    run(name, layout, true);
  }
  return 0;
}

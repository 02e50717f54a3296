// The box pile of contact_pile, run in Bullet 3.24 (Debian's libbullet-dev), the established engine
// issue 5 compares against: the same boxes (pile_layout.h), dt = 1/60 s, 10 solver iterations,
// friction 0.5, no restitution, 600 steps. Prints the same line as contact_pile: median ms per
// step of the last 300, contact points, deepest penetration, fastest box, boxes awake.
// Built twice: bullet_pile (float, Bullet's default build) and bullet_pile_double
// (BT_USE_DOUBLE_PRECISION, the precision rbsim computes in).
//   usage: bullet_pile [N ...]   (default 100 1000 4000)
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "bullet_world.h"
#include "pile_layout.h"

using namespace rbsim::bench;

namespace {

void runPile(int count, bool allowSleep) {
  BulletWorld bw(kPileBoxSize, kPileFriction);
  bw.world.setGravity(btVector3(0, btScalar(-9.81), 0));
  bw.world.getSolverInfo().m_numIterations = kPileSolverIterations;
  bw.add(&bw.groundShape, 0, btVector3(0, 0, 0));
  std::vector<btRigidBody*> boxes;
  for (int i = 0; i < count; ++i) {
    const PileCentre c = pileBoxCentre(i, count);
    btRigidBody* box = bw.add(&bw.boxShape, btScalar(kPileBoxMass), btVector3(btScalar(c.x), btScalar(c.y), btScalar(c.z)));
    if (!allowSleep) box->setActivationState(DISABLE_DEACTIVATION);
    boxes.push_back(box);
  }
  std::vector<double> ms;
  for (int step = 0; step < kPileSteps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    // maxSubSteps = 0: exactly one step of kPileTimeStep, no interpolation.
    bw.world.stepSimulation(btScalar(kPileTimeStep), 0);
    ms.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::vector<double> tail(ms.end() - kPileTimedSteps, ms.end());
  std::nth_element(tail.begin(), tail.begin() + kPileTimedSteps / 2, tail.end());
  double deepest = 0.0, fastest = 0.0;
  std::size_t points = 0;
  for (int m = 0; m < bw.dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = bw.dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      // Like rbsim's speculative points, Bullet keeps points up to its breaking threshold apart.
      ++points;
      deepest = std::max(deepest, -static_cast<double>(manifold->getContactPoint(p).getDistance()));
    }
  }
  std::size_t awake = 0;
  for (const btRigidBody* box : boxes) {
    fastest = std::max(fastest, static_cast<double>(box->getLinearVelocity().length()));
    if (box->isActive()) ++awake;
  }
  std::printf("N = %5d, sleep %-3s: %8.3f ms/step (median of last %d of %d), %6zu contact points, deepest %.4f m, "
              "fastest %.4f m/s (%s), %zu awake\n",
              count, allowSleep ? "on" : "off", tail[kPileTimedSteps / 2], kPileTimedSteps, kPileSteps, points, deepest,
              fastest, fastest < kPileRestSpeed ? "at rest" : "moving", awake);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> counts;
  for (int i = 1; i < argc; ++i) counts.push_back(std::atoi(argv[i]));
  if (counts.empty()) counts = {100, 1000, 4000};
  std::printf("Bullet %d, %s precision\n", btGetVersion(), sizeof(btScalar) == 8 ? "double" : "float");
  for (int count : counts) {
    if (count <= 0) {
      std::fprintf(stderr, "bullet_pile: expected positive box counts\n");
      return 2;
    }
    runPile(count, true);
    runPile(count, false);
  }
  return 0;
}

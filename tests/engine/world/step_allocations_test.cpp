// A step in a steady state allocates nothing (issue 34): once a scene has settled and every
// buffer has grown to its size, World::step reuses them. This executable replaces the global
// operator new with a counting one (so it is its own test program, not part of engine_tests), and
// counts what 60 steps of a settled scene ask for: piles of boxes, spheres and capsules on the
// ground, the same pile as convex hulls (GJK, EPA and feature clipping instead of the boxes' SAT)
// and a chain of ball joints, at 1/60 and 1/240 s, on one thread and on two. (A round body against
// a hull still allocates its core and the hull's world vertices: not covered here.)
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>

#include "test_util.h"
#include "rbsim/math/parallel.h"
#include "rbsim/world/world.h"

namespace {
std::atomic<long> gAllocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++gAllocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
// Every operator new above allocates with malloc, so every delete frees with free.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace rbsim {
namespace {

using test::boxDef;

enum class Scene { Boxes, Hulls, Spheres, Capsules, BallChain };

struct Case {
  Scene scene;
  double dt;
  int threads;
};

std::string sceneName(Scene s) {
  switch (s) {
    case Scene::Boxes: return "Boxes";
    case Scene::Hulls: return "Hulls";
    case Scene::Spheres: return "Spheres";
    case Scene::Capsules: return "Capsules";
    case Scene::BallChain: return "BallChain";
  }
  return "?";
}

void build(World& world, Scene scene) {
  const Material material{0.0, 0.6, 0.6};
  world.addPlane(Plane{}, material);
  if (scene == Scene::BallChain) {
    // A chain of 20 small boxes on ball joints hanging straight down at rest: joints and no
    // contacts. (A swinging one keeps finding new largest broad-phase pair counts for a while,
    // and its buffers grow to them: growth to a high-water mark, not a steady state.)
    BodyId previous;
    for (int i = 0; i < 20; ++i) {
      BodyDef def = boxDef(Vec3::Constant(0.4), 1.0);
      def.shape = Shape::box(Vec3::Constant(0.2));
      def.position = Vec3(0.0, 20.0 - 0.5 * (i + 1), 0.0);
      const BodyId body = world.addBody(def);
      JointDef joint;
      joint.type = JointDef::Type::Ball;
      joint.bodyA = body;
      joint.bodyB = i == 0 ? kWorldAnchor : previous;
      joint.anchor = Vec3(0.0, 20.0 - 0.5 * i - 0.25, 0.0);
      world.addJoint(joint);
      previous = body;
    }
    return;
  }
  // Two layers of a 6 x 6 grid, the upper offset so that it rests on the lower; spheres, which
  // would roll off the lower layer forever, in one layer 1 cm apart (their pairs still collide,
  // within the contact margin).
  const int layers = scene == Scene::Spheres ? 1 : 2;
  for (int layer = 0; layer < layers; ++layer) {
    for (int i = 0; i < 36; ++i) {
      BodyDef def = boxDef(Vec3::Ones(), 1.0);
      def.material = material;
      if (scene == Scene::Boxes) def.shape = Shape::box(Vec3::Constant(0.5));
      if (scene == Scene::Hulls) def.shape = Shape::convexHull(*def.mesh);  // GJK, EPA, feature clipping
      if (scene == Scene::Spheres) def.shape = Shape::sphere(0.5);
      if (scene == Scene::Capsules) def.shape = Shape::capsule(0.3, 0.3);
      const double shift = 0.3 * layer;
      def.position = Vec3(1.01 * (i % 6) + shift, 0.5 + 1.01 * layer, 1.01 * (i / 6) + shift);
      world.addBody(def);
    }
  }
}

constexpr std::size_t kPoolMinItems = 16;  // [items]

class StepAllocations : public ::testing::TestWithParam<Case> {};

TEST_P(StepAllocations, NoneInASteadyState) {
  Settings settings;
  settings.timeStep = GetParam().dt;
  settings.gravity = Vec3(0.0, -9.81, 0.0);
  settings.allowSleep = false;  // every stage runs every step
  settings.threads = GetParam().threads;
  // On two threads every loop of these 72 bodies goes to the pool (its default threshold is
  // above them), whose hand-offs must not allocate either.
  const detail::ScopedMinParallelItems pool(GetParam().threads > 1 ? kPoolMinItems : kDefaultMinParallelItems);
  World world(settings);
  build(world, GetParam().scene);
  const int settle = static_cast<int>(8.0 / settings.timeStep);  // 8 s: the piles have come to rest
  for (int s = 0; s < settle; ++s) world.step();
  const long before = gAllocations.load();
  for (int s = 0; s < 60; ++s) world.step();
  EXPECT_EQ(gAllocations.load() - before, 0) << "allocations in 60 steps";
  EXPECT_GT(world.contacts().size() + world.joints().size(), 0u) << "the scene has something to solve";
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  return sceneName(info.param.scene) + "_dt_1_over_" + std::to_string(static_cast<int>(std::lround(1.0 / info.param.dt))) +
         "_threads_" + std::to_string(info.param.threads);
}

INSTANTIATE_TEST_SUITE_P(Scenes, StepAllocations,
                         ::testing::Values(Case{Scene::Boxes, 1.0 / 60.0, 1}, Case{Scene::Boxes, 1.0 / 240.0, 2},
                                           Case{Scene::Hulls, 1.0 / 60.0, 2}, Case{Scene::Hulls, 1.0 / 240.0, 1},
                                           Case{Scene::Spheres, 1.0 / 60.0, 2}, Case{Scene::Spheres, 1.0 / 240.0, 1},
                                           Case{Scene::Capsules, 1.0 / 60.0, 1}, Case{Scene::Capsules, 1.0 / 240.0, 2},
                                           Case{Scene::BallChain, 1.0 / 60.0, 2}, Case{Scene::BallChain, 1.0 / 240.0, 1}),
                         caseName);

}  // namespace
}  // namespace rbsim

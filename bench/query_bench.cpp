// Rays per second through the World's query tree (issue 57, engine/include/rbsim/world/
// world_queries.h) at 1e3, 1e4 and 1e5 bodies, beside every body tested in turn (the ray cast
// before issue 57) and, where Debian's libbullet-dev is installed, Bullet's
// btCollisionWorld::rayTest over a btDbvtBroadphase holding the same bodies. Random boxes and
// spheres (half sizes 0.25 to 0.5 m) at one body per kVolumePerBody, so the volume grows with n;
// random rays of kRayLength from points inside it. Times are the thread's CPU time (the machine
// is shared; wall time would count other processes), after one untimed pass.
// Also the tree's build after the World changed, once per step at most.
//   usage: query_bench [n ...]   (default 1000 10000 100000)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <random>
#include <vector>

#include "rbsim/body/shape_body.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_queries.h"
#include "world/body_queries.h"

#ifdef RBSIM_BENCH_BULLET
#include <btBulletCollisionCommon.h>
#endif

namespace {

using namespace rbsim;

constexpr double kVolumePerBody = 8.0;     // [m^3] one body per 2 m cube
constexpr double kMinHalfSize = 0.25;      // [m]
constexpr double kMaxHalfSize = 0.5;       // [m]
constexpr double kRayLength = 10.0;        // [m]
constexpr int kRays = 100000;              // per measurement [rays]
constexpr int kBruteRays = 200;            // every body per ray: fewer [rays]
constexpr unsigned kSeed = 57;

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct BodySpec {
  bool sphere;
  Vec3 half;  // box half extents, or the sphere's radius in x [m]
  Vec3 position;
  Quat orientation;
};

struct Scene {
  std::vector<BodySpec> bodies;
  std::vector<Vec3> origins, directions;
  double side = 0.0;  // [m]
};

Scene makeScene(int n) {
  Scene s;
  std::mt19937 rng(kSeed);
  s.side = std::cbrt(kVolumePerBody * n);
  std::uniform_real_distribution<double> at(0.0, s.side), size(kMinHalfSize, kMaxHalfSize), unit(-1.0, 1.0);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < n; ++i) {
    BodySpec b;
    b.sphere = i % 2 == 0;
    b.half = Vec3(size(rng), size(rng), size(rng));
    b.position = Vec3(at(rng), at(rng), at(rng));
    b.orientation = Quat(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized());
    s.bodies.push_back(b);
  }
  for (int i = 0; i < kRays; ++i) {
    s.origins.emplace_back(at(rng), at(rng), at(rng));
    s.directions.push_back(Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized());
  }
  return s;
}

World makeWorld(const Scene& s) {
  World world{Settings{}};
  for (const BodySpec& b : s.bodies) {
    BodyDef def = shapeBodyDef(b.sphere ? Shape::sphere(b.half.x()) : Shape::box(b.half), 1.0);
    def.position = b.position;
    def.orientation = b.orientation;
    def.isStatic = true;
    world.addBody(def);
  }
  return world;
}

struct Timing {
  double nsPerRay = 0.0;
  int hits = 0;
};

template <typename Cast>
Timing timeRays(int rays, Cast cast) {
  cast(std::min(rays, 1000));  // warm the caches and the tree
  const double start = cpuSeconds();
  const int hits = cast(rays);
  return {1e9 * (cpuSeconds() - start) / rays, hits};
}

#ifdef RBSIM_BENCH_BULLET
Timing bulletRays(const Scene& s) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btCollisionWorld world(&dispatcher, &broadphase, &configuration);
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> objects;
  for (const BodySpec& b : s.bodies) {
    if (b.sphere) {
      shapes.push_back(std::make_unique<btSphereShape>(btScalar(b.half.x())));
    } else {
      shapes.push_back(std::make_unique<btBoxShape>(btVector3(btScalar(b.half.x()), btScalar(b.half.y()), btScalar(b.half.z()))));
      shapes.back()->setMargin(0);  // the box's own faces, as rbsim's
    }
    auto object = std::make_unique<btCollisionObject>();
    btTransform t;
    t.setOrigin(btVector3(btScalar(b.position.x()), btScalar(b.position.y()), btScalar(b.position.z())));
    t.setRotation(btQuaternion(btScalar(b.orientation.x()), btScalar(b.orientation.y()), btScalar(b.orientation.z()),
                               btScalar(b.orientation.w())));
    object->setWorldTransform(t);
    object->setCollisionShape(shapes.back().get());
    world.addCollisionObject(object.get(), btBroadphaseProxy::StaticFilter,
                             btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    objects.push_back(std::move(object));
  }
  world.updateAabbs();
  return timeRays(kRays, [&](int rays) {
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
      const Vec3 a = s.origins[i], b = s.origins[i] + kRayLength * s.directions[i];
      const btVector3 from(btScalar(a.x()), btScalar(a.y()), btScalar(a.z())), to(btScalar(b.x()), btScalar(b.y()), btScalar(b.z()));
      btCollisionWorld::ClosestRayResultCallback callback(from, to);
      world.rayTest(from, to, callback);
      hits += callback.hasHit() ? 1 : 0;
    }
    return hits;
  });
}
#endif

void run(int n) {
  const Scene s = makeScene(n);
  World world = makeWorld(s);
  const Timing one = timeRays(kRays, [&](int rays) {
    int hits = 0;
    for (int i = 0; i < rays; ++i) hits += castRay(world, s.origins[i], s.directions[i], kRayLength) ? 1 : 0;
    return hits;
  });
  const Timing batch = timeRays(kRays, [&](int rays) {
    const std::vector<Vec3> o(s.origins.begin(), s.origins.begin() + rays), d(s.directions.begin(), s.directions.begin() + rays);
    int hits = 0;
    for (const auto& hit : castRays(world, o, d, kRayLength)) hits += hit ? 1 : 0;
    return hits;
  });
  // Every body tested in turn, as rayCast did before issue 57.
  const Timing brute = timeRays(kBruteRays, [&](int rays) {
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
      double reach = kRayLength;
      bool hit = false;
      for (const RigidBody& body : world.bodies()) {
        if (const auto h = rayBody(body, s.origins[i], s.directions[i], reach, QueryFilter{})) {
          reach = h->distance;
          hit = true;
        }
      }
      hits += hit ? 1 : 0;
    }
    return hits;
  });
  // The tree's build on the first query after a change (here: a body handed out by World::body).
  constexpr int kBuilds = 5;
  const double buildStart = cpuSeconds();
  for (int i = 0; i < kBuilds; ++i) {
    world.body(world.idAt(0));
    castRay(world, s.origins[0], s.directions[0], kRayLength);
  }
  const double buildMs = 1e3 * (cpuSeconds() - buildStart) / kBuilds;
  std::printf("%7d bodies, side %5.1f m: one ray %7.0f ns (%5.2f M rays/s, %d of %d hit); batch %7.0f ns "
              "(%5.2f M rays/s); every body %9.0f ns; tree build %6.2f ms",
              n, s.side, one.nsPerRay, 1e3 / one.nsPerRay, one.hits, kRays, batch.nsPerRay, 1e3 / batch.nsPerRay,
              brute.nsPerRay, buildMs);
#ifdef RBSIM_BENCH_BULLET
  const Timing bullet = bulletRays(s);
  std::printf("; Bullet rayTest %7.0f ns (%5.2f M rays/s, %d hit)", bullet.nsPerRay, 1e3 / bullet.nsPerRay, bullet.hits);
#endif
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> counts;
  for (int i = 1; i < argc; ++i) counts.push_back(std::atoi(argv[i]));
  if (counts.empty()) counts = {1000, 10000, 100000};
  for (const int n : counts) run(n);
  return 0;
}

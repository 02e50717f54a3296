// Narrow phase per pair type (issue 20): ns per query for the analytic round pairs, the box SAT,
// GJK/EPA on hulls (scanning every vertex against climbing the vertex graph), and each shape
// against a plane. Each pair is posed touching (1 cm deep), as in a resting scene, at one of 64
// fixed random orientations, cycled so that no branch predictor learns one pose.
//   build/bench/narrowphase_bench [--benchmark_filter=...]
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "collision/narrowphase/box_box.h"
#include "collision/narrowphase/convex_convex.h"
#include "collision/narrowphase/shape_pairs.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/math/rotation.h"

using namespace rbsim;

namespace {

constexpr int kPoses = 64;          // distinct orientations cycled through [1]
constexpr double kDepth = 0.01;     // overlap of the posed pairs [m]
constexpr double kMargin = 0.01;    // speculative margin, as Settings::contactMargin [m]

std::vector<Mat3> randomRotations() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<Mat3> out;
  for (int i = 0; i < kPoses; ++i) out.push_back(rotationFromAxisAngle(Vec3(u(rng), u(rng), u(rng))));
  return out;
}

// B is placed along +x from A at the distance of their support points, less kDepth.
PosedShape placedAgainst(const PosedShape& a, const Shape& b, const Mat3& rotation) {
  const Vec3 x = Vec3::UnitX();
  const double reachA = x.dot(a.rotation * a.shape->support(a.rotation.transpose() * x));
  const double reachB = x.dot(rotation * b.support(-(rotation.transpose() * x)));
  return {&b, rotation, Vec3((reachA - reachB) - kDepth, 0.0, 0.0)};
}

void roundPair(benchmark::State& state, const Shape& a, const Shape& b) {
  const std::vector<Mat3> rotations = randomRotations();
  std::vector<std::pair<PosedShape, PosedShape>> poses;
  for (int i = 0; i < kPoses; ++i) {
    const PosedShape pa{&a, rotations[i], Vec3::Zero()};
    poses.emplace_back(pa, placedAgainst(pa, b, rotations[(i + 1) % kPoses]));
  }
  int i = 0;
  for (auto _ : state) {
    const auto& [pa, pb] = poses[i++ % kPoses];
    benchmark::DoNotOptimize(collideRoundPair(pa, pb, kMargin));
  }
}

const Shape kSphere = Shape::sphere(0.5);
const Shape kCapsule = Shape::capsule(0.25, 0.5);
const Shape kBox = Shape::box(Vec3(0.5, 0.5, 0.5));

void BM_SphereSphere(benchmark::State& s) { roundPair(s, kSphere, kSphere); }
void BM_SphereCapsule(benchmark::State& s) { roundPair(s, kSphere, kCapsule); }
void BM_CapsuleCapsule(benchmark::State& s) { roundPair(s, kCapsule, kCapsule); }
void BM_SphereBox(benchmark::State& s) { roundPair(s, kSphere, kBox); }
void BM_CapsuleBox(benchmark::State& s) { roundPair(s, kCapsule, kBox); }

// Boxes turned about x only, so that A's +x face rests on B's -x face (a full manifold): turned
// at random, their corners would often miss each other and the SAT would stop at the first gap.
void BM_BoxBoxSat(benchmark::State& state) {
  std::vector<std::pair<OrientedBox, OrientedBox>> poses;
  for (int i = 0; i < kPoses; ++i) {
    const PosedShape pa{&kBox, rotationFromAxisAngle(Vec3(0.1 * i, 0.0, 0.0)), Vec3::Zero()};
    const PosedShape pb = placedAgainst(pa, kBox, rotationFromAxisAngle(Vec3(0.07 * i + 0.2, 0.0, 0.0)));
    poses.emplace_back(OrientedBox{pa.position, pa.rotation, kBox.halfExtents},
                       OrientedBox{pb.position, pb.rotation, kBox.halfExtents});
  }
  int i = 0;
  for (auto _ : state) {
    const auto& [a, b] = poses[i++ % kPoses];
    benchmark::DoNotOptimize(collideBoxes(a, b, kMargin));
  }
}

// Two hulls of a 48 x 24 sphere mesh (1106 vertices): GJK/EPA scanning, or climbing.
void hullPair(benchmark::State& state, bool climb) {
  const Shape hull = Shape::convexHull(makeUvSphere(0.5, 48, 24));
  const std::vector<Mat3> rotations = randomRotations();
  struct Pose {
    PosedShape a, b;
    std::vector<Vec3> va, vb;
  };
  std::vector<Pose> poses;
  for (int i = 0; i < kPoses; ++i) {
    const PosedShape pa{&hull, rotations[i], Vec3::Zero()};
    const PosedShape pb = placedAgainst(pa, hull, rotations[(i + 1) % kPoses]);
    poses.push_back({pa, pb, worldHullVertices(pa), worldHullVertices(pb)});
  }
  int i = 0;
  for (auto _ : state) {
    const Pose& p = poses[i++ % kPoses];
    if (climb) {
      benchmark::DoNotOptimize(collideConvex(PosedHullSupport(p.a), p.va, PosedHullSupport(p.b), p.vb, kMargin));
    } else {
      benchmark::DoNotOptimize(collideConvex(p.va, p.vb, kMargin));
    }
  }
}
void BM_HullHullScan(benchmark::State& s) { hullPair(s, false); }
void BM_HullHullClimb(benchmark::State& s) { hullPair(s, true); }

void planePair(benchmark::State& state, const Shape& shape) {
  const std::vector<Mat3> rotations = randomRotations();
  std::vector<PosedShape> poses;
  for (const Mat3& R : rotations) {
    const double reach = -Vec3::UnitY().dot(R * shape.support(-(R.transpose() * Vec3::UnitY())));
    poses.push_back({&shape, R, Vec3(0.0, reach - kDepth, 0.0)});
  }
  const Plane ground;
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(collidePlaneShape(ground, poses[i++ % kPoses], kMargin));
}
void BM_SpherePlane(benchmark::State& s) { planePair(s, kSphere); }
void BM_CapsulePlane(benchmark::State& s) { planePair(s, kCapsule); }
void BM_BoxPlane(benchmark::State& s) { planePair(s, kBox); }

}  // namespace

BENCHMARK(BM_SphereSphere);
BENCHMARK(BM_SphereCapsule);
BENCHMARK(BM_CapsuleCapsule);
BENCHMARK(BM_SphereBox);
BENCHMARK(BM_CapsuleBox);
BENCHMARK(BM_BoxBoxSat);
BENCHMARK(BM_HullHullScan);
BENCHMARK(BM_HullHullClimb);
BENCHMARK(BM_SpherePlane);
BENCHMARK(BM_CapsulePlane);
BENCHMARK(BM_BoxPlane);

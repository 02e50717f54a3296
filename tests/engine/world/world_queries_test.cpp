// Scene queries through the tree (engine/include/rbsim/world/world_queries.h, issue 57): each
// query on random scenes of every shape type (sphere, box, rounded box, capsule, hull, compound,
// mesh, planes), some bodies static or asleep, random filters, against brute force (every body
// and plane answered by world/body_queries.h); the tree's answers right after bodies are added,
// destroyed, moved by hand or by a step.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "rbsim/body/compound_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_queries.h"
#include "world/body_queries.h"
#include "world/query_tree.h"

namespace rbsim {
namespace {

constexpr double kBruteTolerance = 1e-9;       // [m] both sides run the same exact per-body tests
constexpr double kSceneHalfWidth = 10.0;           // [m] bodies' centres within +-kSceneHalfWidth
constexpr int kSceneBodies = 160;              // per random scene [bodies]
constexpr std::uint64_t kFilterBits = 3;  // filters draw categories and masks from 3 bits

struct RandomQueryScene {
  World world{Settings{}};
  std::mt19937 rng;
  explicit RandomQueryScene(unsigned seed) : rng(seed) {
    std::uniform_real_distribution<double> at(-kSceneHalfWidth, kSceneHalfWidth), size(0.1, 0.8), unit(-1.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 6), bits(1, (1 << kFilterBits) - 1);
    world.addPlane(Plane{Vec3::UnitY(), -kSceneHalfWidth});
    world.addPlane(Plane{Vec3(1.0, 1.0, 0.0).normalized(), 2.0 * kSceneHalfWidth});
    for (int i = 0; i < kSceneBodies; ++i) {
      const double a = size(rng), b = size(rng);
      BodyDef def;
      switch (kind(rng)) {
        case 0: def = shapeBodyDef(Shape::sphere(a), 1.0); break;
        case 1: def = shapeBodyDef(Shape::box(Vec3(a, b, 0.5 * (a + b))), 1.0); break;
        case 2: def = shapeBodyDef(Shape::capsule(a, b), 1.0); break;
        case 3: {
          def.mesh = std::make_shared<Mesh>(makeRoundedBox(Vec3(a, b, a), 0.1, 2));
          def.shape = Shape::roundedBox(Vec3(a, b, a), 0.1);
          break;
        }
        case 4: {
          def.mesh = std::make_shared<Mesh>(makeUvSphere(a, 7, 4));
          def.shape = Shape::convexHull(*def.mesh);
          break;
        }
        case 5: {
          CompoundPart p, q;
          p.shape = Shape::box(Vec3(a, 0.1, 0.1));
          q.shape = Shape::sphere(b);
          q.position = Vec3(a, 0.0, 0.0);
          q.filter.category = static_cast<std::uint64_t>(bits(rng));
          def = compoundBodyDef({p, q});
          break;
        }
        default: {
          def.mesh = std::make_shared<Mesh>(makeTorus(a + 0.5, 0.4 * b, 12, 6));
          def.shape = Shape::mesh(*def.mesh);
          def.isStatic = true;
          break;
        }
      }
      def.name = "b" + std::to_string(i);
      def.position = Vec3(at(rng), at(rng), at(rng));
      def.orientation = Quat(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized());
      def.isStatic = def.isStatic || i % 5 == 0;
      def.filter.category = static_cast<std::uint64_t>(bits(rng));
      def.filter.mask = static_cast<std::uint64_t>(bits(rng));
      const BodyId id = world.addBody(def);
      if (i % 7 == 0 && !def.isStatic) world.body(id).sleep();
    }
  }
  Vec3 point() {
    std::uniform_real_distribution<double> at(-1.3 * kSceneHalfWidth, 1.3 * kSceneHalfWidth);
    return {at(rng), at(rng), at(rng)};
  }
  QueryFilter filter() {
    std::uniform_int_distribution<int> bits(1, (1 << kFilterBits) - 1), planes(0, 1);
    if (planes(rng) == 0) return QueryFilter{};
    return {static_cast<std::uint64_t>(bits(rng)), static_cast<std::uint64_t>(bits(rng)), planes(rng) == 0};
  }
  QueryShape shape() {
    std::uniform_real_distribution<double> size(0.05, 1.0), unit(-1.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 2);
    const Quat q(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized());
    switch (kind(rng)) {
      case 0: return QueryShape::sphere(size(rng), point());
      case 1: return QueryShape::box(Vec3(size(rng), size(rng), size(rng)), point(), q);
      default: return QueryShape::capsule(size(rng), size(rng), point(), q);
    }
  }
};

// Brute force: every body and plane by world/body_queries.h, the nearest kept.
template <typename BodyQuery, typename PlaneQuery>
std::optional<QueryHit> nearestOfAll(const World& world, const QueryFilter& filter, BodyQuery body, PlaneQuery plane) {
  std::optional<QueryHit> best;
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    std::optional<QueryHit> hit = body(world.bodies()[i]);
    if (hit && (!best || hit->distance < best->distance)) {
      hit->body = world.idAt(i);
      best = hit;
    }
  }
  for (std::size_t k = 0; filter.planes && planePasses(filter) && k < world.planes().size(); ++k) {
    std::optional<QueryHit> hit = plane(world.planes()[k]);
    if (hit && (!best || hit->distance < best->distance)) {
      hit->plane = k;
      best = hit;
    }
  }
  return best;
}

void expectSameHit(const std::optional<QueryHit>& tree, const std::optional<QueryHit>& brute, int query) {
  ASSERT_EQ(tree.has_value(), brute.has_value()) << "query " << query;
  if (!tree) return;
  EXPECT_NEAR(tree->distance, brute->distance, kBruteTolerance) << "query " << query;
  if (std::abs(tree->distance - brute->distance) > kBruteTolerance) return;
  // Two things at the same distance (a start inside both) may answer in either order.
  if (tree->isPlane == brute->isPlane && tree->body == brute->body && tree->plane == brute->plane) {
    EXPECT_EQ(tree->child, brute->child) << "query " << query;
    EXPECT_NEAR((tree->point - brute->point).norm(), 0.0, kBruteTolerance) << "query " << query;
    EXPECT_NEAR((tree->normal - brute->normal).norm(), 0.0, kBruteTolerance) << "query " << query;
  }
}

TEST(WorldQueries, RaysMatchBruteForceOnRandomScenes) {
  int hits = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    RandomQueryScene scene(seed);
    for (int q = 0; q < 300; ++q) {
      const Vec3 origin = scene.point(), d = (scene.point() - origin).normalized();
      const QueryFilter filter = scene.filter();
      const double reach = q % 3 == 0 ? std::numeric_limits<double>::infinity() : 12.0;
      const std::optional<QueryHit> tree = castRay(scene.world, origin, d, reach, filter);
      const std::optional<QueryHit> brute = nearestOfAll(
          scene.world, filter, [&](const RigidBody& b) { return rayBody(b, origin, d, reach, filter); },
          [&](const Plane& p) { return rayPlane(p, origin, d, reach); });
      expectSameHit(tree, brute, q);
      hits += tree ? 1 : 0;
    }
  }
  EXPECT_GT(hits, 300) << "the scenes are hit, so the comparison compares something";
}

TEST(WorldQueries, ABatchAnswersAsOneRayAtATime) {
  RandomQueryScene scene(7);
  std::vector<Vec3> origins, directions;
  for (int q = 0; q < 200; ++q) {
    origins.push_back(scene.point());
    directions.push_back(scene.point() - origins.back());
  }
  const QueryFilter filter{0b011, 0b101, true};
  const std::vector<std::optional<QueryHit>> batch = castRays(scene.world, origins, directions, 30.0, filter);
  ASSERT_EQ(batch.size(), origins.size());
  for (std::size_t q = 0; q < origins.size(); ++q) {
    expectSameHit(batch[q], castRay(scene.world, origins[q], directions[q], 30.0, filter), static_cast<int>(q));
  }
  directions[5] = Vec3::Zero();
  EXPECT_THROW(castRays(scene.world, origins, directions, 30.0), std::invalid_argument);
  directions.pop_back();
  EXPECT_THROW(castRays(scene.world, origins, directions, 30.0), std::invalid_argument);
}

TEST(WorldQueries, ClosestPointsMatchBruteForce) {
  for (unsigned seed = 11; seed <= 12; ++seed) {
    RandomQueryScene scene(seed);
    for (int q = 0; q < 200; ++q) {
      const Vec3 p = scene.point();
      const QueryFilter filter = scene.filter();
      const double reach = q % 2 == 0 ? std::numeric_limits<double>::infinity() : 1.5;
      const std::optional<QueryHit> tree = closestPoint(scene.world, p, reach, filter);
      std::optional<QueryHit> brute = nearestOfAll(
          scene.world, filter, [&](const RigidBody& b) { return closestOnBody(b, p, filter); },
          [&](const Plane& plane) { return std::optional<QueryHit>(closestOnPlane(plane, p)); });
      if (brute && brute->distance > reach) brute.reset();
      expectSameHit(tree, brute, q);
    }
  }
}

TEST(WorldQueries, OverlapsAndBoxesAreExactlyTheBruteForceSets) {
  RandomQueryScene scene(21);
  std::size_t found = 0;
  for (int q = 0; q < 300; ++q) {
    const QueryShape shape = scene.shape();
    const QueryFilter filter = scene.filter();
    const Shape s = shape.kind == QueryShape::Kind::Sphere ? Shape::sphere(shape.radius)
                    : shape.kind == QueryShape::Kind::Box  ? Shape::box(shape.halfExtents)
                                                           : Shape::capsule(shape.radius, shape.halfLength);
    const Mat3 R = shape.orientation.toRotationMatrix();
    std::vector<std::pair<bool, std::size_t>> expected, got;
    for (std::size_t i = 0; i < scene.world.bodies().size(); ++i) {
      if (overlapBody(scene.world.bodies()[i], s, R, shape.position, filter)) expected.emplace_back(false, i);
    }
    for (std::size_t k = 0; planePasses(filter) && k < scene.world.planes().size(); ++k) {
      if (overlapsPlane(scene.world.planes()[k], s, R, shape.position)) expected.emplace_back(true, k);
    }
    for (const QueryHit& hit : overlapShape(scene.world, shape, filter)) {
      got.emplace_back(hit.isPlane, hit.isPlane ? hit.plane : scene.world.indexOf(hit.body));
    }
    EXPECT_EQ(got, expected) << "query " << q;
    found += got.size();

    const Aabb box{shape.position - Vec3::Constant(2.0), shape.position + Vec3::Constant(2.0)};
    std::vector<BodyId> inBox;
    for (std::size_t i = 0; i < scene.world.bodies().size(); ++i) {
      if (queryBounds(scene.world.bodies()[i]).overlaps(box) && anyShapePasses(scene.world.bodies()[i], filter)) {
        inBox.push_back(scene.world.idAt(i));
      }
    }
    EXPECT_EQ(queryAabb(scene.world, box, filter), inBox) << "query " << q;
  }
  EXPECT_GT(found, 50u);
}

TEST(WorldQueries, ShapeCastsMatchBruteForce) {
  RandomQueryScene scene(31);
  int hits = 0;
  for (int q = 0; q < 200; ++q) {
    const QueryShape shape = scene.shape();
    const Vec3 d = (scene.point() - shape.position).normalized();
    const QueryFilter filter = scene.filter();
    const Shape s = shape.kind == QueryShape::Kind::Sphere ? Shape::sphere(shape.radius)
                    : shape.kind == QueryShape::Kind::Box  ? Shape::box(shape.halfExtents)
                                                           : Shape::capsule(shape.radius, shape.halfLength);
    const Mat3 R = shape.orientation.toRotationMatrix();
    const std::optional<QueryHit> tree = castShape(scene.world, shape, d, 15.0, filter);
    const std::optional<QueryHit> brute = nearestOfAll(
        scene.world, filter, [&](const RigidBody& b) { return castBody(b, s, R, shape.position, d, 15.0, filter); },
        [&](const Plane& p) { return castPlane(p, s, R, shape.position, d, 15.0); });
    ASSERT_EQ(tree.has_value(), brute.has_value()) << "query " << q;
    if (!tree) continue;
    ++hits;
    // Each is within kShapeCastTolerance of the contact, from before it.
    EXPECT_NEAR(tree->distance, brute->distance, 2.0 * kShapeCastTolerance) << "query " << q;
  }
  EXPECT_GT(hits, 50);
}

}  // namespace
}  // namespace rbsim

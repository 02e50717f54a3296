// collision/narrowphase/mesh_mesh: Moller's triangle-triangle test in use (issue 36). The
// hierarchies find exactly the crossing triangle pairs a brute force over all pairs finds, two box
// meshes sunk 1 cm into each other give the 1 cm along the face normal, and a torus dropped on a
// torus with world.mesh_contact = triangles rests on it, tube on tube, with both solvers.
#include "collision/narrowphase/mesh_mesh.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collision/narrowphase/triangle_triangle.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "../../../sanitized_build.h"

namespace rbsim {
namespace {

std::vector<std::pair<std::uint32_t, std::uint32_t>> bruteForce(const PosedMesh& a, const PosedMesh& b) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const auto world = [](const PosedMesh& m, std::uint32_t t, int k) {
    return Vec3(m.rotation * m.mesh->vertices[m.mesh->triangles[t][k]] + m.position);
  };
  // In A's frame, as collideMeshes works, so that rounding treats both the same way.
  const auto inA = [&](const Vec3& w) { return Vec3(a.rotation.transpose() * (w - a.position)); };
  for (std::uint32_t i = 0; i < a.mesh->triangles.size(); ++i) {
    for (std::uint32_t j = 0; j < b.mesh->triangles.size(); ++j) {
      const Vec3& a0 = a.mesh->vertices[a.mesh->triangles[i][0]];
      const Vec3& a1 = a.mesh->vertices[a.mesh->triangles[i][1]];
      const Vec3& a2 = a.mesh->vertices[a.mesh->triangles[i][2]];
      if (trianglesIntersect(a0, a1, a2, inA(world(b, j, 0)), inA(world(b, j, 1)), inA(world(b, j, 2)))) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

TEST(MeshMesh, TheHierarchiesFindExactlyTheBruteForcePairs) {
  const Mesh torus = makeTorus(0.5, 0.15, 32, 12);
  const Mesh letter = makeLetterU(0.8, 0.9, 0.2, 0.3);
  const TriangleBvh torusTree(torus), letterTree(letter);
  UniformRandom random(20261128);
  std::size_t crossing = 0, apart = 0;
  // Half the trials under the sanitizers, where the brute force dominates (40 in the normal build).
  const int trials = test::kSanitizedBuild ? 20 : 40;
  for (int trial = 0; trial < trials; ++trial) {
    const bool tori = trial % 2 == 0;
    PosedMesh a{&torus, &torusTree, Mat3(Eigen::AngleAxisd(random.between(0.0, M_PI), random.direction())),
                Vec3(random.between(-1, 1), random.between(-1, 1), random.between(-1, 1))};
    PosedMesh b{tori ? &torus : &letter, tori ? &torusTree : &letterTree,
                Mat3(Eigen::AngleAxisd(random.between(0.0, M_PI), random.direction())),
                a.position + random.between(0.0, 1.3) * random.direction()};
    const auto expected = bruteForce(a, b);
    EXPECT_EQ(crossingTriangles(a, b), expected) << "trial " << trial;
    (expected.empty() ? apart : crossing) += 1;
  }
  // Both outcomes occur, so the comparison is not vacuous either way.
  EXPECT_GE(crossing, static_cast<std::size_t>(trials / 4));
  EXPECT_GE(apart, static_cast<std::size_t>(trials * 3 / 40));
}

TEST(MeshMesh, TwoBoxesSunkOneCentimetreGiveOneCentimetreAlongTheFaceNormal) {
  const Mesh box = makeBox(Vec3::Ones());
  const TriangleBvh tree(box);
  // B on A, offset sideways so no edges coincide, 0.01 m deep; turned a little about the normal.
  const Mat3 turn = Mat3(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
  for (const Mat3& base : {Mat3(Mat3::Identity()), Mat3(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))}) {
    const PosedMesh a{&box, &tree, base, Vec3(0.1, -0.2, 0.3)};
    const PosedMesh b{&box, &tree, base * turn, a.position + base * Vec3(0.2, 0.99, 0.1)};
    const std::vector<ContactManifold> manifolds = collideMeshes(a, b);
    ASSERT_EQ(manifolds.size(), 1u);
    const ContactManifold& m = manifolds[0];
    EXPECT_LT((m.normal - base * Vec3::UnitY()).norm(), 1e-12);
    EXPECT_GE(m.count, 3);
    for (int k = 0; k < m.count; ++k) {
      EXPECT_NEAR(m.points[k].depth, 0.01, 1e-9);
      // On the crossing of the two surfaces: in A's top face's plane, within 0.01 of B's bottom.
      const Vec3 local = base.transpose() * (m.points[k].position - a.position);
      EXPECT_GE(local.y(), 0.49 - 1e-9);
      EXPECT_LE(local.y(), 0.5 + 1e-9);
    }
  }
}

Scene toriScene(const std::string& solver, double dt) {
  using nlohmann::json;
  const json torus = {{"type", "torus"}, {"major_radius", 0.4}, {"minor_radius", 0.1}};
  return parseScene({{"world", {{"dt", dt}, {"solver", solver}, {"mesh_contact", "triangles"}, {"sleep", false}}},
                     {"bodies",
                      {{{"name", "below"}, {"shape", torus}, {"mass", 1.0}, {"static", true}},
                       {{"name", "above"}, {"shape", torus}, {"density", 200.0}, {"position", {0.0, 0.21, 0.0}}}}}},
                    "test.json", RBSIM_TEST_DATA_DIR);
}

TEST(MeshMesh, ATorusRestsOnATorusTubeOnTube) {
  for (const char* solver : {"soft-step", "pgs"}) {
    // Under the sanitizers at 1/60 s alone: 1/240 is the same code four times as often.
    for (double dt : test::kSanitizedBuild ? std::vector<double>{1.0 / 60.0} : std::vector<double>{1.0 / 60.0, 1.0 / 240.0}) {
      const Scene scene = toriScene(solver, dt);
      ASSERT_TRUE(scene.bodies[1].triangles);
      World world = buildWorld(scene);
      for (int s = 0; s < static_cast<int>(std::lround(2.0 / dt)); ++s) world.step();
      const RigidBody& above = world.bodies()[1];
      // The tubes' top and bottom rings are 0.1 m from their centres: 0.2 m apart at rest. Soft
      // step holds that to 0.01 mm. PGS lets the six manifolds of the ring sink 18 mm at 1/60 s and
      // 5 mm at 1/240 s, and as much with the sample contacts (15 mm at 1/60 s): its split-impulse
      // pass, not the contacts, sets the depth.
      const bool soft = std::string(solver) == "soft-step";
      EXPECT_NEAR(above.position().y(), 0.2, soft ? 1e-3 : 0.02) << solver << " dt " << dt;
      EXPECT_LT(std::hypot(above.position().x(), above.position().z()), 0.01) << solver << " dt " << dt;
      EXPECT_LT(above.velocity().norm(), 1e-3) << solver << " dt " << dt;
    }
  }
}

}  // namespace
}  // namespace rbsim

// geometry/mesh: the seed's box vertex list, the topology checks that guard exact inertia, and the
// convexity test that decides whether a closed mesh needs a signed distance grid.
#include "rbsim/geometry/mesh.h"

#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/geometry/mesh_generators.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

Vec3 triangleNormal(const Mesh& m, const Triangle& t) {
  return (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
}

TEST(MakeBox, HasTheSeedVerticesScaledByTheExtents) {
  // Seed 004, "Rigid body geometry": p0..p7 of the unit cube, in this order.
  const double seed[8][3] = {{-0.5, -0.5, -0.5}, {+0.5, -0.5, -0.5}, {+0.5, +0.5, -0.5},
                             {-0.5, +0.5, -0.5}, {-0.5, -0.5, +0.5}, {+0.5, -0.5, +0.5},
                             {+0.5, +0.5, +0.5}, {-0.5, +0.5, +0.5}};
  const Vec3 extents(2.0, 0.3, 7.0);
  const Mesh box = makeBox(extents);
  ASSERT_EQ(box.vertices.size(), 8u);
  for (int i = 0; i < 8; ++i) {
    const Vec3 expected = Vec3(seed[i][0], seed[i][1], seed[i][2]).cwiseProduct(extents);
    EXPECT_TRUE(allNear(box.vertices[i], expected, 0.0)) << "p" << i;
  }
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_TRUE(allNear(box.boundsMin(), -0.5 * extents, 0.0));
  EXPECT_TRUE(allNear(box.boundsMax(), 0.5 * extents, 0.0));
}

TEST(MakeBox, IsClosedConsistentAndWoundOutward) {
  const Mesh box = makeBox(Vec3(1.0, 2.0, 3.0));
  const MeshCheck check = checkMesh(box);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.consistentlyOriented);
  EXPECT_EQ(check.degenerateTriangles, 0u);
  EXPECT_EQ(check.problem, "");
  // Outward: each face normal points away from the centre (the origin), along one axis.
  for (const Triangle& t : box.triangles) {
    const Vec3 n = triangleNormal(box, t);
    const Vec3 centroid = (box.vertices[t[0]] + box.vertices[t[1]] + box.vertices[t[2]]) / 3.0;
    EXPECT_GT(n.dot(centroid), 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), n.norm(), 1e-15) << "box faces are axis-aligned";
  }
}

TEST(CheckMesh, FlagsAnOpenMesh) {
  Mesh box = makeBox(Vec3::Ones());
  box.triangles.pop_back();
  const MeshCheck check = checkMesh(box);
  EXPECT_FALSE(check.closed);
  EXPECT_NE(check.problem.find("exactly twice"), std::string::npos) << check.problem;
}

TEST(CheckMesh, FlagsAFlippedTriangle) {
  Mesh box = makeBox(Vec3::Ones());
  std::swap(box.triangles[5][1], box.triangles[5][2]);
  const MeshCheck check = checkMesh(box);
  EXPECT_TRUE(check.closed) << "flipping keeps every edge used twice";
  EXPECT_FALSE(check.consistentlyOriented);
  EXPECT_NE(check.problem.find("inconsistent winding"), std::string::npos) << check.problem;
}

TEST(CheckMesh, FlagsDegenerateTriangles) {
  // Moving p2 onto p1 keeps the topology closed and consistent but collapses the two triangles
  // that use both vertices: (0, 2, 1) and (1, 2, 6).
  Mesh box = makeBox(Vec3::Ones());
  box.vertices[2] = box.vertices[1];
  const MeshCheck check = checkMesh(box);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.consistentlyOriented);
  EXPECT_EQ(check.degenerateTriangles, 2u);
  EXPECT_NE(check.problem.find("degenerate"), std::string::npos) << check.problem;

  Mesh repeated;  // a repeated index is degenerate whatever the coordinates
  repeated.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  repeated.triangles = {{0, 1, 1}};
  EXPECT_EQ(checkMesh(repeated).degenerateTriangles, 1u);
}

TEST(CheckMesh, FlagsAnEmptyMeshAndABadIndex) {
  const MeshCheck empty = checkMesh(Mesh{});
  EXPECT_FALSE(empty.closed);
  EXPECT_NE(empty.problem.find("no triangles"), std::string::npos) << empty.problem;

  Mesh bad = makeBox(Vec3::Ones());
  bad.triangles[3][0] = 8;
  const MeshCheck check = checkMesh(bad);
  EXPECT_FALSE(check.closed);
  EXPECT_NE(check.problem.find("indexes vertex 8"), std::string::npos) << check.problem;
}

TEST(TranslateMesh, MovesEveryVertexByMinusTheOffset) {
  const Mesh box = makeBox(Vec3(1.0, 2.0, 3.0));
  Mesh moved = box;
  const Vec3 offset(0.25, -1.5, 4.0);
  translateMesh(moved, offset);
  for (std::size_t i = 0; i < box.vertices.size(); ++i) {
    EXPECT_TRUE(allNear(moved.vertices[i], box.vertices[i] - offset, 0.0));
  }
  EXPECT_EQ(moved.triangles, box.triangles);
}


// Two meshes as one (the second's indices shifted past the first's vertices).
Mesh merged(const Mesh& a, const Mesh& b) {
  Mesh out = a;
  const auto shift = static_cast<std::uint32_t>(a.vertices.size());
  out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) out.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  return out;
}

// A closed slab of n x n cells whose top is the dish y = depth (x^2 + z^2) on [-1, 1]^2 (concave
// seen from above) and whose other five sides are flat.
Mesh dishSlab(int n, double depth) {
  Mesh m;
  const auto id = [n](int i, int j, int layer) { return static_cast<std::uint32_t>(layer * (n + 1) * (n + 1) + j * (n + 1) + i); };
  for (int layer = 0; layer < 2; ++layer) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const double x = -1.0 + 2.0 * i / n, z = -1.0 + 2.0 * j / n;
        m.vertices.emplace_back(x, layer == 1 ? 1.0 + depth * (x * x + z * z) : 0.0, z);
      }
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j, 1), id(i, j + 1, 1), id(i + 1, j + 1, 1)});  // top, normal +y
      m.triangles.push_back({id(i, j, 1), id(i + 1, j + 1, 1), id(i + 1, j, 1)});
      m.triangles.push_back({id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});  // bottom, -y
      m.triangles.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0)});
    }
  }
  for (int k = 0; k < n; ++k) {  // the four walls, each cell split along its diagonal
    const std::uint32_t walls[4][4] = {{id(k, 0, 0), id(k + 1, 0, 0), id(k + 1, 0, 1), id(k, 0, 1)},
                                       {id(k + 1, n, 0), id(k, n, 0), id(k, n, 1), id(k + 1, n, 1)},
                                       {id(0, k + 1, 0), id(0, k, 0), id(0, k, 1), id(0, k + 1, 1)},
                                       {id(n, k, 0), id(n, k + 1, 0), id(n, k + 1, 1), id(n, k, 1)}};
    for (const auto& w : walls) {
      m.triangles.push_back({w[0], w[2], w[1]});  // outward
      m.triangles.push_back({w[0], w[3], w[2]});
    }
  }
  return m;
}

TEST(IsConvexSurface, AgreesWithTheDefinitionOnConvexAndNonConvexMeshes) {
  EXPECT_TRUE(isConvexSurface(makeBox(Vec3(1, 2, 3)), 1e-9));
  EXPECT_TRUE(isConvexSurface(makeUvSphere(1.0, 48, 24), 1e-9));
  EXPECT_FALSE(isConvexSurface(makeTorus(1.0, 0.3, 24, 12), 1e-9));
  EXPECT_FALSE(isConvexSurface(makeLetterU(1.0, 1.0, 0.25, 0.5), 1e-9));
  // Every edge is convex, but there are two boxes: the centroid lies between them.
  Mesh apart = makeBox(Vec3::Ones());
  translateMesh(apart, Vec3(3, 0, 0));
  EXPECT_FALSE(isConvexSurface(merged(makeBox(Vec3::Ones()), apart), 1e-9));
  // A box inside a box: one sheet around the centroid twice.
  EXPECT_FALSE(isConvexSurface(merged(makeBox(Vec3::Ones() * 2), makeBox(Vec3::Ones())), 1e-9));
  // A vertex no triangle uses, outside the box.
  Mesh stray = makeBox(Vec3::Ones());
  stray.vertices.emplace_back(5, 0, 0);
  EXPECT_FALSE(isConvexSurface(stray, 1e-9));
  stray.vertices.back() = Vec3::Zero();
  EXPECT_TRUE(isConvexSurface(stray, 1e-9));
}

TEST(IsConvexSurface, CatchesADentTooGentleForAnyEdgeToShow) {
  // 200 x 200 cells on a dish 1e-3 deep: across one edge the surface bends by ~1e-3 x (2/200)^2
  // = 1e-7 m, under the 1e-6 m tolerance, but the rim stands 1e-3 m above the centre's plane.
  const Mesh dish = dishSlab(200, 1e-3);
  EXPECT_FALSE(isConvexSurface(dish, 1e-6));
  EXPECT_TRUE(isConvexSurface(dishSlab(200, -1e-3), 1e-6)) << "the same dish bulging out is convex";
}

TEST(IsConvexSurface, IsLinearInPracticeOnAMillionTriangles) {
  const Mesh sphere = makeUvSphere(1.0, 1000, 500);
  ASSERT_GT(sphere.triangles.size(), 990000u);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(isConvexSurface(sphere, 1e-6 * 2 * std::sqrt(3.0)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 20.0) << "testing every vertex against every face would take hours";
}

}  // namespace
}  // namespace rbsim

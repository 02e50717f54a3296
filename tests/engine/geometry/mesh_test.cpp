// geometry/mesh: the seed's box vertex list and the topology checks that guard exact inertia.
#include "geometry/mesh.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rbsim

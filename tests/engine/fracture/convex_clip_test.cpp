// Cutting convex meshes (engine/src/fracture/convex_clip.h, pieces.h): every piece is a closed,
// outward-wound solid, and the pieces fill the body exactly: their volumes, first moments and
// (by parallel axes) inertias sum to the body's.
#include "fracture/convex_clip.h"

#include <gtest/gtest.h>

#include "fracture/pieces.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/uniform_random.h"

namespace rbsim {
namespace {

constexpr double kSumTolerance = 1e-12;  // relative, rounding of sums over a few hundred triangles

void expectSolid(const Mesh& piece) {
  const MeshCheck check = checkMesh(piece);
  EXPECT_TRUE(check.closed) << check.problem;
  EXPECT_TRUE(check.consistentlyOriented) << check.problem;
  EXPECT_EQ(check.degenerateTriangles, 0u);
  EXPECT_GT(polyhedralMassProperties(piece, 1.0).volume, 0.0);
  EXPECT_TRUE(isConvexSurface(piece, 1e-9));  // [m]: face normals of small triangles carry rounding
}

// Volumes, first moments and inertias about the whole body's centre of mass sum to the body's.
void expectFills(const Mesh& body, const std::vector<Mesh>& pieces) {
  const MassProperties whole = polyhedralMassProperties(body, 1.0);
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  for (const Mesh& piece : pieces) {
    expectSolid(piece);
    const MassProperties p = polyhedralMassProperties(piece, 1.0);
    const Vec3 r = p.centerOfMass - whole.centerOfMass;
    volume += p.volume;
    moment += p.volume * r;
    inertia += p.inertia + p.mass * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  const double size = (body.boundsMax() - body.boundsMin()).norm();
  EXPECT_NEAR(volume, whole.volume, kSumTolerance * whole.volume);
  EXPECT_LT(moment.norm(), kSumTolerance * whole.volume * size);
  EXPECT_LT((inertia - whole.inertia).norm(), kSumTolerance * whole.inertia.norm());
}

TEST(ConvexClip, BoxCutOffCentreGivesTheAnalyticParts) {
  const Mesh box = makeBox(Vec3(1.0, 2.0, 3.0));
  // x <= 0.2 keeps 0.7 of the box, centred at x = (-0.5 + 0.2) / 2.
  const Mesh kept = clipConvexMesh(box, Vec3::UnitX(), 0.2, clipTolerance(box));
  expectSolid(kept);
  const MassProperties p = polyhedralMassProperties(kept, 1.0);
  EXPECT_NEAR(p.volume, 0.7 * 6.0, 1e-14);
  EXPECT_NEAR(p.centerOfMass.x(), -0.15, 1e-14);
  EXPECT_NEAR(p.centerOfMass.y(), 0.0, 1e-14);
  EXPECT_NEAR(kept.boundsMax().x(), 0.2, 1e-15);
  const Mat3 exact = cuboidInertia(p.mass, Vec3(0.7, 2.0, 3.0));
  EXPECT_LT((p.inertia - exact).norm(), 1e-13);
}

TEST(ConvexClip, PlaneMissingTheMeshKeepsAllOrNothing) {
  const Mesh box = makeBox(Vec3::Ones());
  EXPECT_EQ(clipConvexMesh(box, Vec3::UnitY(), 2.0, 0.0).triangles.size(), box.triangles.size());
  EXPECT_TRUE(clipConvexMesh(box, Vec3::UnitY(), -2.0, 0.0).triangles.empty());
  // A plane through a face keeps the whole box on one side and nothing on the other.
  EXPECT_EQ(clipConvexMesh(box, Vec3::UnitY(), 0.5, 1e-12).triangles.size(), box.triangles.size());
  EXPECT_TRUE(clipConvexMesh(box, -Vec3::UnitY(), -0.5, 1e-12).triangles.empty());
}

TEST(ConvexClip, PlanesThroughEdgesAndVerticesStayClosed) {
  // The diagonal plane x = y passes through two vertical edges of the box; x + y + z = 0 through
  // two vertices: the snapping to the plane must not leave slivers or open edges.
  const Mesh box = makeBox(Vec3::Ones());
  for (const Vec3& n : {Vec3(1.0, -1.0, 0.0).normalized(), Vec3(1.0, 1.0, 1.0).normalized()}) {
    const double tolerance = clipTolerance(box);
    const std::vector<Mesh> halves = {clipConvexMesh(box, n, 0.0, tolerance), clipConvexMesh(box, -n, 0.0, tolerance)};
    expectFills(box, halves);
    EXPECT_NEAR(polyhedralMassProperties(halves[0], 1.0).volume, 0.5, 1e-15);
  }
}

TEST(ConvexClip, ThreePlanesCutABoxIntoEightOctants) {
  const Mesh box = makeBox(Vec3(2.0, 2.0, 2.0));
  const std::vector<Mesh> pieces = cutByPlanes(box, {{Vec3::UnitX(), 0.0}, {Vec3::UnitY(), 0.0}, {Vec3::UnitZ(), 0.0}});
  ASSERT_EQ(pieces.size(), 8u);
  for (const Mesh& piece : pieces) {
    const MassProperties p = polyhedralMassProperties(piece, 1.0);
    EXPECT_NEAR(p.volume, 1.0, 1e-14);
    EXPECT_NEAR(p.centerOfMass.cwiseAbs().minCoeff(), 0.5, 1e-14);
    EXPECT_NEAR(p.centerOfMass.cwiseAbs().maxCoeff(), 0.5, 1e-14);
  }
  expectFills(box, pieces);
  EXPECT_THROW(cutByPlanes(box, {{Vec3(1.0, 1.0, 0.0), 0.0}}), std::invalid_argument);
}

TEST(ConvexClip, VoronoiCellsFillABoxAndAnOctahedron) {
  Mesh octahedron;  // a convex solid that is not a box, with slanted faces
  octahedron.vertices = {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {0.0, 0.7, 0.0}, {0.0, -0.7, 0.0}, {0.0, 0.0, 0.5}, {0.0, 0.0, -0.5}};
  octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  ASSERT_TRUE(checkMesh(octahedron).consistentlyOriented);
  for (const Mesh& body : {makeBox(Vec3(2.0, 1.0, 0.2)), octahedron}) {
    const std::vector<Vec3> sites = sitesInside(body, 16, 7);
    const std::vector<Mesh> pieces = voronoiPieces(body, sites);
    EXPECT_EQ(pieces.size(), sites.size());  // every site lies inside, so every cell is non-empty
    expectFills(body, pieces);
  }
}

TEST(ConvexClip, VoronoiCellHoldsThePointsNearestItsSite) {
  const Mesh box = makeBox(Vec3::Ones());
  const std::vector<Vec3> sites = sitesInside(box, 6, 3);
  const std::vector<Mesh> pieces = voronoiPieces(box, sites);
  ASSERT_EQ(pieces.size(), sites.size());
  UniformRandom random(11);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(random.between(-0.5, 0.5), random.between(-0.5, 0.5), random.between(-0.5, 0.5));
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < sites.size(); ++i) {
      if ((p - sites[i]).norm() < (p - sites[nearest]).norm()) nearest = i;
    }
    // Inside a convex cell means behind every face plane; the nearest site's cell must hold p.
    const Mesh& cell = pieces[nearest];
    bool inside = true;
    for (const Triangle& t : cell.triangles) {
      const Vec3& a = cell.vertices[t[0]];
      const Vec3 n = (cell.vertices[t[1]] - a).cross(cell.vertices[t[2]] - a);
      inside = inside && n.dot(p - a) <= 1e-12 * n.norm();
    }
    EXPECT_TRUE(inside) << "point " << p.transpose() << " outside the cell of its nearest site";
  }
}

TEST(ConvexClip, SitesAreReproducibleAndInside) {
  const Mesh box = makeBox(Vec3(1.0, 2.0, 0.5));
  const std::vector<Vec3> a = sitesInside(box, 20, 5), b = sitesInside(box, 20, 5);
  ASSERT_EQ(a.size(), 20u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i], b[i]);
    EXPECT_TRUE((a[i].cwiseAbs().array() < Vec3(0.5, 1.0, 0.25).array()).all());
  }
  EXPECT_THROW(sitesInside(box, 1, 5), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim

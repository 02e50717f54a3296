// collision/narrowphase/convex_convex: the World's pair function. Known boxes and a tetrahedron
// through GJK + EPA + feature clipping, agreement with the box SAT path, speculative margins,
// and random pairs checked against the geometry.
#include "collision/narrowphase/convex_convex.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "collision/narrowphase/epa.h"
#include "collision/narrowphase/gjk.h"
#include "geometry/box3d_convex_pile_hull.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/shapes/shape.h"
#include "narrowphase_test_util.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxCorners;
using test::makeOrientedBox;
using test::rotationAbout;

const Vec3 kConvexHalf = Vec3::Constant(0.5);

bool convexHolds(const ContactManifold& m, const Vec3& p, double tol = 1e-9) {
  for (int i = 0; i < m.count; ++i) {
    if ((m.points[i].position - p).norm() <= tol) return true;
  }
  return false;
}

TEST(CollideConvex, PenetratingCubesThroughGjkAndEpa) {
  const ConvexContact c = collideConvex(boxCorners(makeOrientedBox(Vec3::Zero(), kConvexHalf)),
                                        boxCorners(makeOrientedBox(Vec3(0.9, 0, 0), kConvexHalf)));
  EXPECT_FALSE(c.usedBoxSat);
  EXPECT_TRUE(c.overlap);
  EXPECT_NEAR(c.depth, 0.1, 1e-9);
  EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitX(), 1e-9));
  ASSERT_EQ(c.manifold.count, 4);
  for (double y : {-0.5, 0.5}) {
    for (double z : {-0.5, 0.5}) EXPECT_TRUE(convexHolds(c.manifold, Vec3(0.45, y, z))) << y << " " << z;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(c.manifold.points[i].depth, 0.1, 1e-9);
}

TEST(CollideConvex, SeparatedCubesReportTheGjkDistance) {
  const std::vector<Vec3> a = boxCorners(makeOrientedBox(Vec3::Zero(), kConvexHalf));
  const std::vector<Vec3> b = boxCorners(makeOrientedBox(Vec3(1.5, 0, 0), kConvexHalf));
  ConvexContact c = collideConvex(a, b);
  EXPECT_FALSE(c.overlap);
  EXPECT_EQ(c.manifold.count, 0);
  EXPECT_NEAR(c.distance, 0.5, 1e-12);
  EXPECT_NEAR(c.pointA.x(), 0.5, 1e-12);
  EXPECT_NEAR(c.pointB.x(), 1.0, 1e-12);
  // Within a 0.6 m margin: four speculative points, 0.5 m apart.
  c = collideConvex(a, b, 0.6);
  ASSERT_EQ(c.manifold.count, 4);
  EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitX(), 1e-12));
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c.manifold.points[i].depth, -0.5, 1e-12);
    EXPECT_NEAR(c.manifold.points[i].position.x(), 0.75, 1e-12);
  }
  const ConvexDistance d = convexDistance(a, b);
  EXPECT_FALSE(d.overlap);
  EXPECT_NEAR(d.distance, 0.5, 1e-12);
}

TEST(CollideConvex, RestingBoxMatchesTheSatPath) {
  const OrientedBox slab = makeOrientedBox(Vec3::Zero(), Vec3(1, 0.5, 1));
  const OrientedBox cube = makeOrientedBox(Vec3(0.2, 0.99, -0.1), kConvexHalf, rotationAbout(Vec3::UnitY(), 0.3));
  const std::vector<Vec3> a = boxCorners(slab), b = boxCorners(cube);
  const ConvexContact general = collideConvex(a, b);
  const ConvexContact sat = collideConvex(a, b, 0.0, &slab, &cube);
  EXPECT_TRUE(sat.usedBoxSat);
  ASSERT_EQ(general.manifold.count, 4);
  ASSERT_EQ(sat.manifold.count, 4);
  EXPECT_TRUE(allNear(general.manifold.normal, sat.manifold.normal, 1e-9));
  EXPECT_NEAR(general.depth, sat.depth, 1e-9);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(convexHolds(general.manifold, sat.manifold.points[i].position)) << i;
    EXPECT_NEAR(general.manifold.points[i].depth, 0.01, 1e-9);
  }
}

TEST(CollideConvex, EdgeOnEdgeCrossingBoxesGiveOnePoint) {
  const double delta = 0.01, h = std::sqrt(0.5);
  const std::vector<Vec3> a = boxCorners(makeOrientedBox(Vec3::Zero(), kConvexHalf, rotationAbout(Vec3::UnitX(), M_PI / 4)));
  const std::vector<Vec3> b =
      boxCorners(makeOrientedBox(Vec3(0, 2 * h - delta, 0), kConvexHalf, rotationAbout(Vec3::UnitZ(), M_PI / 4)));
  const ConvexContact c = collideConvex(a, b);
  EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitY(), 1e-9));
  ASSERT_EQ(c.manifold.count, 1);
  EXPECT_TRUE(allNear(c.manifold.points[0].position, Vec3(0, h - delta / 2, 0), 1e-9));
  EXPECT_NEAR(c.manifold.points[0].depth, delta, 1e-9);
}

TEST(CollideConvex, TetrahedronTipIntoABoxHasOnePoint) {
  const std::vector<Vec3> box = boxCorners(makeOrientedBox(Vec3::Zero(), kConvexHalf));
  const std::vector<Vec3> tetra = {Vec3(0.1, 0.45, 0.05), Vec3(-0.2, 1.2, -0.1), Vec3(0.4, 1.2, -0.1),
                                   Vec3(0.1, 1.2, 0.4)};
  const ConvexContact c = collideConvex(box, tetra);
  EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitY(), 1e-9));
  EXPECT_NEAR(c.depth, 0.05, 1e-9);
  ASSERT_EQ(c.manifold.count, 1);
  EXPECT_TRUE(allNear(c.manifold.points[0].position, Vec3(0.1, 0.475, 0.05), 1e-9));
  EXPECT_NEAR(c.manifold.points[0].depth, 0.05, 1e-9);
}

TEST(CollideConvex, TetrahedronFaceDownOnABoxHasThreePoints) {
  const std::vector<Vec3> box = boxCorners(makeOrientedBox(Vec3::Zero(), kConvexHalf));
  const std::vector<Vec3> tetra = {Vec3(-0.2, 0.48, -0.1), Vec3(0.3, 0.48, -0.1), Vec3(0.05, 0.48, 0.3),
                                   Vec3(0.05, 1.2, 0.03)};
  // Tetrahedron as A this time: the normal points from it down into the box.
  const ConvexContact c = collideConvex(tetra, box);
  EXPECT_TRUE(allNear(c.manifold.normal, -Vec3::UnitY(), 1e-9));
  ASSERT_EQ(c.manifold.count, 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(convexHolds(c.manifold, Vec3(tetra[k].x(), 0.49, tetra[k].z()))) << k;
    EXPECT_NEAR(c.manifold.points[k].depth, 0.02, 1e-9);
  }
}

TEST(CollideConvex, ATiltedFacePressedIntoAFaceKeepsEveryPenetratingCorner) {
  // A unit cube turned 5 degrees about z, its lowest edge 0.1 m into a slab whose top is y = 0:
  // its other bottom edge is sin 5 deg higher, still 0.1 - 0.0872 = 0.0128 m in. The manifold
  // holds all four bottom corners at their own depths; with only the lowest edge (the corners
  // within kSupportFeatureTolerance of the deepest) the cube turned about that edge deeper into
  // the slab, as the hulls of Box3D's convex pile did (issue 56). Either body may be A.
  const double depth = 0.1, tilt = 5.0 * M_PI / 180.0;
  const Mat3 R = rotationAbout(Vec3::UnitZ(), tilt);
  const Vec3 centre(0.0, -depth + 0.5 * (std::sin(tilt) + std::cos(tilt)), 0.0);
  const std::vector<Vec3> cube = boxCorners(makeOrientedBox(centre, kConvexHalf, R));
  const std::vector<Vec3> slab = boxCorners(makeOrientedBox(Vec3(0.0, -0.5, 0.0), Vec3(2.0, 0.5, 2.0)));
  for (const bool slabIsA : {true, false}) {
    const ConvexContact c = slabIsA ? collideConvex(slab, cube) : collideConvex(cube, slab);
    EXPECT_NEAR(c.depth, depth, 1e-9) << "the analytic overlap, slab is A: " << slabIsA;
    EXPECT_TRUE(allNear(c.manifold.normal, slabIsA ? Vec3::UnitY() : Vec3(-Vec3::UnitY()), 1e-9));
    ASSERT_EQ(c.manifold.count, 4) << "slab is A: " << slabIsA;
    EXPECT_NEAR(c.manifold.maxDepth(), depth, 1e-9);
    for (const Vec3& corner : cube) {
      if (corner.y() >= 0.0) continue;  // above the slab
      // Each corner in the slab is a point of depth -y, midway between the surfaces.
      EXPECT_TRUE(convexHolds(c.manifold, Vec3(corner.x(), 0.5 * corner.y(), corner.z())))
          << corner.transpose() << ", slab is A: " << slabIsA;
    }
    for (int k = 0; k < c.manifold.count; ++k) {
      EXPECT_NEAR(c.manifold.points[k].depth, -2.0 * c.manifold.points[k].position.y(), 1e-9);
    }
  }
}

// Apart, the box path reports the SAT separation: the distance when faces are closest, a lower
// bound (the gap along one axis) when corners are.
TEST(CollideConvex, BoxPathReportsTheSatSeparationWhenApart) {
  const OrientedBox a = makeOrientedBox(Vec3::Zero(), kConvexHalf);
  const OrientedBox faceToFace = makeOrientedBox(Vec3(1.75, 0.2, -0.1), kConvexHalf);
  ConvexContact c = collideConvex(boxCorners(a), boxCorners(faceToFace), 0.0, &a, &faceToFace);
  EXPECT_TRUE(c.usedBoxSat);
  EXPECT_FALSE(c.overlap);
  EXPECT_EQ(c.manifold.count, 0);
  EXPECT_NEAR(c.distance, 0.75, 1e-12);
  const OrientedBox cornerToCorner = makeOrientedBox(Vec3(2, 2, 2), kConvexHalf);
  c = collideConvex(boxCorners(a), boxCorners(cornerToCorner), 0.0, &a, &cornerToCorner);
  EXPECT_FALSE(c.overlap);
  EXPECT_NEAR(c.distance, 1.0, 1e-12);
  EXPECT_LT(c.distance, convexDistance(boxCorners(a), boxCorners(cornerToCorner)).distance);
}

// Random box pairs through the general path: every point midway between the surfaces (on the
// hull of each box after moving half its depth along the normal), no point deeper than EPA's
// depth, and a contact whenever the exact SAT says the boxes overlap.
TEST(CollideConvex, RandomBoxPairsPutEveryPointBetweenTheTwoSurfaces) {
  std::mt19937 rng(414);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.1, 1.0), reach(0.0, 1.5);
  int overlapping = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const OrientedBox a = makeOrientedBox(Vec3(u(rng), u(rng), u(rng)), Vec3(size(rng), size(rng), size(rng)),
                                          test::randomRotation(rng));
    const OrientedBox b = makeOrientedBox(a.centre + Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng),
                                          Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    const double sat = test::satSeparation(a, b);
    if (std::abs(sat) < 1e-6) continue;  // touching: either answer is right
    const ConvexContact c = collideConvex(boxCorners(a), boxCorners(b));
    ASSERT_EQ(c.overlap, sat < 0.0) << "trial " << trial;
    ASSERT_EQ(c.manifold.count > 0, sat < 0.0) << "trial " << trial;
    if (!c.overlap) continue;
    ++overlapping;
    ASSERT_NEAR(c.depth, -sat, 1e-8) << "trial " << trial;
    const Vec3& n = c.manifold.normal;
    for (int i = 0; i < c.manifold.count; ++i) {
      const ContactPoint& p = c.manifold.points[i];
      ASSERT_NEAR(test::boxSignedDistance(a, p.position + n * (0.5 * p.depth)), 0.0, 1e-6) << "trial " << trial;
      ASSERT_NEAR(test::boxSignedDistance(b, p.position - n * (0.5 * p.depth)), 0.0, 1e-6) << "trial " << trial;
      ASSERT_LE(p.depth, c.depth + 1e-9) << "trial " << trial;
      ASSERT_GE(p.depth, -1e-9) << "trial " << trial;
    }
    ASSERT_NEAR(c.manifold.maxDepth(), c.depth, 1e-6) << "trial " << trial;
  }
  EXPECT_GT(overlapping, 600);
}

// The same pairs through collideHulls, each box a hull with its face planes: where EPA's axis is
// two edges' and a face's is within kFaceAxisPreference (and kDeepFaceAxisPreference of the
// depth) of it, the face's manifold is taken. Every point still lies between the two surfaces,
// none deeper than the face axis allows, and the deepest is within that preference of EPA's depth (a reference face whose prism missed
// the overlap once gave 3 mm for 0.26 m).
TEST(CollideConvex, RandomBoxHullsThroughTheirFacesKeepTheDepth) {
  std::mt19937 rng(415);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.1, 1.0), reach(0.0, 1.5);
  int overlapping = 0, facePathPoints = 0, plainPoints = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const OrientedBox a = makeOrientedBox(Vec3(u(rng), u(rng), u(rng)), Vec3(size(rng), size(rng), size(rng)),
                                          test::randomRotation(rng));
    const OrientedBox b = makeOrientedBox(a.centre + Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng),
                                          Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    if (std::abs(test::satSeparation(a, b)) < 1e-6) continue;  // touching: either answer is right
    const Shape hullA = Shape::convexHull(makeBox(2.0 * a.halfExtents));
    const Shape hullB = Shape::convexHull(makeBox(2.0 * b.halfExtents));
    const std::vector<Vec3> cornersA = boxCorners(a), cornersB = boxCorners(b);
    const PointSetSupport supportA(cornersA), supportB(cornersB);
    const ConvexContact c = collideHulls(supportA, cornersA, PosedFaces{hullA.faces.get(), a.rotation, a.centre},
                                         supportB, cornersB, PosedFaces{hullB.faces.get(), b.rotation, b.centre});
    if (!c.overlap) continue;
    ++overlapping;
    const Vec3& n = c.manifold.normal;
    for (int i = 0; i < c.manifold.count; ++i) {
      const ContactPoint& p = c.manifold.points[i];
      ASSERT_NEAR(test::boxSignedDistance(a, p.position + n * (0.5 * p.depth)), 0.0, 1e-6) << "trial " << trial;
      ASSERT_NEAR(test::boxSignedDistance(b, p.position - n * (0.5 * p.depth)), 0.0, 1e-6) << "trial " << trial;
      ASSERT_LE(p.depth, c.depth + kFaceAxisPreference + kDeepFaceAxisPreference * c.depth + 1e-9) << "trial " << trial;
    }
    ASSERT_GE(c.manifold.maxDepth(), c.depth - kFaceAxisPreference - kDeepFaceAxisPreference * c.depth - 1e-9) << "trial " << trial;
    facePathPoints += c.manifold.count;
    plainPoints += collideConvex(cornersA, cornersB).manifold.count;
  }
  EXPECT_GT(overlapping, 600);
  EXPECT_GT(facePathPoints, plainPoints) << "faces give the pairs more points than EPA's axis alone";
}

// How far a world point lies outside a posed hull's face planes (0 on its surface, < 0 inside).
double hullSignedDistance(const PosedFaces& hull, const Vec3& p) {
  const Vec3 local = hull.rotation.transpose() * (p - hull.position);
  double d = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < hull.planes->normals.size(); ++k) {
    d = std::max(d, hull.planes->normals[k].dot(local) - hull.planes->offsets[k]);
  }
  return d;
}

// A square pyramid pressed apex first 0.1 m into a small triangular face of a larger
// tetrahedron (the face: side 0.6 m, centred under the apex). The apex is the pyramid's only
// vertex in the face's prism, and its neighbours lie far outside it; with them alone the manifold
// was the apex's one point, about which the pyramid turned deeper (Box3D's convex pile, whose
// hulls have triangular faces, issue 56). The pyramid's incident face clipped to the prism gives
// the points where that face crosses the prism's walls, each on both surfaces at its own depth.
TEST(CollideConvex, AVertexPressedIntoASmallFaceMeetsItWithItsIncidentFace) {
  const double depth = 0.1, side = 0.6;
  const double r = side / std::sqrt(3.0);  // the face's circumradius
  Mesh tetra;
  tetra.vertices = {Vec3(r, 0, 0), Vec3(-0.5 * r, 0, 0.5 * side), Vec3(-0.5 * r, 0, -0.5 * side), Vec3(0, -1.5, 0)};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  // The pyramid, apex down at y = -depth, its base 0.2 m above (faces sloping 1 in 5, as the
  // pile hull's faces meet at shallow angles), turned a little about y and tilted about x so
  // that one slanted face is the most against the tetrahedron's face normal.
  Mesh pyramid;
  pyramid.vertices = {Vec3(0, 0, 0), Vec3(-1, 0.2, -1), Vec3(1, 0.2, -1), Vec3(1, 0.2, 1), Vec3(-1, 0.2, 1)};
  pyramid.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {1, 4, 3}, {1, 3, 2}};
  const Shape a = Shape::convexHull(tetra), b = Shape::convexHull(pyramid);
  const Mat3 turn = rotationAbout(Vec3::UnitX(), 0.1) * rotationAbout(Vec3::UnitY(), 0.3);
  const Vec3 apex(0.02, -depth, -0.01);
  std::vector<Vec3> va = tetra.vertices, vb;
  for (const Vec3& v : pyramid.vertices) vb.push_back(apex + turn * v);
  const PosedFaces facesA{a.faces.get(), Mat3::Identity(), Vec3::Zero()}, facesB{b.faces.get(), turn, apex};
  for (const bool tetraIsA : {true, false}) {
    const ConvexContact c = tetraIsA ? collideHulls(PointSetSupport(va), va, facesA, PointSetSupport(vb), vb, facesB)
                                     : collideHulls(PointSetSupport(vb), vb, facesB, PointSetSupport(va), va, facesA);
    EXPECT_NEAR(c.depth, depth, 1e-9) << "the apex's depth below the face, tetrahedron is A: " << tetraIsA;
    EXPECT_TRUE(allNear(c.manifold.normal, tetraIsA ? Vec3::UnitY() : Vec3(-Vec3::UnitY()), 1e-9));
    EXPECT_GE(c.manifold.count, 3) << "tetrahedron is A: " << tetraIsA;
    EXPECT_NEAR(c.manifold.maxDepth(), depth, 1e-9);
    double widest = 0.0;  // the points' spread about the apex in the face's plane
    const Vec3& n = c.manifold.normal;
    for (int k = 0; k < c.manifold.count; ++k) {
      const ContactPoint& p = c.manifold.points[k];
      const Vec3 onA = p.position + n * (0.5 * p.depth), onB = p.position - n * (0.5 * p.depth);
      EXPECT_NEAR(hullSignedDistance(tetraIsA ? facesA : facesB, onA), 0.0, 1e-9) << k;
      EXPECT_NEAR(hullSignedDistance(tetraIsA ? facesB : facesA, onB), 0.0, 1e-9) << k;
      EXPECT_GE(p.depth, 0.0) << k;
      widest = std::max(widest, Vec3(p.position.x() - apex.x(), 0.0, p.position.z() - apex.z()).norm());
    }
    EXPECT_GT(widest, 0.1) << "points away from the apex hold the pyramid from turning about it";
  }
}

// Copies of Box3D's convex pile hull (32 points on a sphere of radius 2, 60 triangles) at random
// turns, pressed 0.05 to 1.5 m into each other as in the pile: every point lies on both hulls'
// surfaces, the deepest is within the face preference of EPA's depth, and the pairs get several
// points where the feature manifold alone gave most of them one.
TEST(CollideConvex, PileHullsPressedDeepMeetAtPointsOnBothSurfaces) {
  const Mesh mesh = test::box3dConvexPileHull();
  const Shape hull = Shape::convexHull(mesh);
  std::mt19937 rng(56);
  std::uniform_real_distribution<double> u(-1.0, 1.0), gap(2.2, 4.0);
  int deep = 0, points = 0, featurePoints = 0, single = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Mat3 ra = test::randomRotation(rng), rb = test::randomRotation(rng);
    const Vec3 xa(u(rng), u(rng), u(rng)), xb = xa + Vec3(u(rng), u(rng), u(rng)).normalized() * gap(rng);
    std::vector<Vec3> va, vb;
    for (const Vec3& v : mesh.vertices) {
      va.push_back(xa + ra * v);
      vb.push_back(xb + rb * v);
    }
    const PosedFaces fa{hull.faces.get(), ra, xa}, fb{hull.faces.get(), rb, xb};
    const ConvexContact c = collideHulls(PointSetSupport(va), va, fa, PointSetSupport(vb), vb, fb);
    if (!c.overlap || c.depth < 0.05) continue;
    ++deep;
    const double preference = kFaceAxisPreference + kDeepFaceAxisPreference * c.depth;
    const Vec3& n = c.manifold.normal;
    for (int k = 0; k < c.manifold.count; ++k) {
      const ContactPoint& p = c.manifold.points[k];
      ASSERT_NEAR(hullSignedDistance(fa, p.position + n * (0.5 * p.depth)), 0.0, kSupportFeatureTolerance) << "trial " << trial;
      ASSERT_NEAR(hullSignedDistance(fb, p.position - n * (0.5 * p.depth)), 0.0, kSupportFeatureTolerance) << "trial " << trial;
      ASSERT_LE(p.depth, c.depth + preference + 1e-9) << "trial " << trial;
    }
    ASSERT_GE(c.manifold.maxDepth(), c.depth - preference - 1e-9) << "trial " << trial;
    points += c.manifold.count;
    if (c.manifold.count == 1) ++single;
    featurePoints += collideConvex(va, vb).manifold.count;
  }
  EXPECT_GT(deep, 300);
  EXPECT_GT(points, 3 * deep) << "more than three points a pair on average";
  EXPECT_GT(points, 2 * featurePoints) << "twice the feature manifold's points, which gave most pairs one";
  // Two edges' axis still gives one point where no face is near it (Box3D's edge contact):
  // 53 of 448 pairs here.
  EXPECT_LT(single, deep / 5) << "one pair in five at most meets at one point";
  std::printf("deep pairs %d: %.2f points a pair (feature manifold alone %.2f), %d at one point\n", deep,
              static_cast<double>(points) / deep, static_cast<double>(featurePoints) / deep, single);
}

TEST(CollideConvex, RandomPointSetsGiveFiniteConsistentManifolds) {
  std::mt19937 rng(415);
  std::uniform_real_distribution<double> u(-1.0, 1.0), reach(0.0, 2.5);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Vec3> a, b;
    const Vec3 offset = Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng);
    for (int i = 0; i < 10; ++i) a.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < 10; ++i) b.push_back(Vec3(u(rng), u(rng), u(rng)) + offset);
    const double margin = 0.05;
    const ConvexContact c = collideConvex(a, b, margin);
    const GjkResult g = gjk(a, b);
    ASSERT_EQ(c.overlap, g.overlap) << "trial " << trial;
    ASSERT_EQ(c.manifold.count > 0, g.overlap || g.distance <= margin) << "trial " << trial;
    ASSERT_NEAR(c.manifold.normal.norm(), 1.0, 1e-12) << "trial " << trial;
    for (int i = 0; i < c.manifold.count; ++i) {
      const ContactPoint& p = c.manifold.points[i];
      ASSERT_FALSE(p.position.hasNaN()) << "trial " << trial;
      ASSERT_GE(p.depth, -margin - 1e-9) << "trial " << trial;
      ASSERT_LE(p.depth, (c.overlap ? c.depth : -c.distance) + 1e-9) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace rbsim

// geometry/sdf_slice: a layer of a built grid read back with the stage that set each value and
// the flood fill's region, checked against the analytic solid: phi within the grid's error of the
// true distance, the narrow band exactly the points within its width, every sign that of its
// region (a torus's hole outside though the slice encloses it, a hollow sphere's cavity), and the
// zero contour on the true surface.
#include "rbsim/geometry/sdf_slice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "geometry/implicit_surface.h"
#include "rbsim/geometry/mesh_generators.h"

namespace rbsim {
namespace {

Mesh hollowBallMesh(double outer, double inner) {
  Mesh m = makeUvSphere(outer, 48, 24);
  Mesh cavity = makeUvSphere(inner, 32, 16);
  const std::uint32_t offset = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), cavity.vertices.begin(), cavity.vertices.end());
  for (Triangle t : cavity.triangles) {
    std::swap(t[1], t[2]);  // facing into the cavity
    for (auto& v : t) v += offset;
    m.triangles.push_back(t);
  }
  m.name = "hollow sphere";
  return m;
}

// Every sample of every layer along every axis.
template <class F>
void forEverySample(const SignedDistanceGrid& g, const F& f) {
  for (int axis = 0; axis < 3; ++axis) {
    for (int layer = 0; layer < g.dims()[axis]; ++layer) {
      const SdfSlice s = sdfSlice(g, axis, g.origin()[axis] + layer * g.cellSize());
      for (int v = 0; v < s.height; ++v) {
        for (int u = 0; u < s.width; ++u) f(s, u, v);
      }
    }
  }
}

TEST(SdfSlice, SpherePhiMatchesTheAnalyticDistanceWithinEachStagesError) {
  const double radius = 1.0;
  const Mesh mesh = makeUvSphere(radius, 96, 48);  // faceting error R (1 - cos(pi / 48)) = 2e-3 m = 0.03 h
  const SignedDistanceGrid g = SignedDistanceGrid::build(mesh, {32, 3, 2});
  const double h = g.cellSize();
  const SdfSlice s = sdfSlice(g, 2, 0.13);
  EXPECT_LE(std::abs(s.offset - 0.13), 0.5 * h);  // the nearest layer
  EXPECT_NEAR(std::remainder(s.offset - g.origin().z(), h), 0.0, 1e-12);  // on the lattice
  double exactWorst = 0.0, marchedWorst = 0.0;
  int exact = 0, marched = 0;
  for (int v = 0; v < s.height; ++v) {
    for (int u = 0; u < s.width; ++u) {
      const std::size_t i = s.index(u, v);
      const double error = std::abs(s.phi[i] - (s.point(u, v).norm() - radius)) / h;
      if (s.stage[i] == SdfStage::ExactBand) {
        exactWorst = std::max(exactWorst, error);
        ++exact;
      } else {
        ASSERT_EQ(s.stage[i], SdfStage::Marched);
        marchedWorst = std::max(marchedWorst, error);
        ++marched;
      }
    }
  }
  std::printf("sphere slice z = %.4f m: %d exact (worst %.4f h), %d marched (worst %.3f h)\n", s.offset, exact,
              exactWorst, marched, marchedWorst);
  EXPECT_GT(exact, 100);
  EXPECT_GT(marched, 100);
  EXPECT_LT(exactWorst, 0.05);   // the distance to the facets: only their faceting error
  EXPECT_LT(marchedWorst, 1.25);  // first-order fast marching, under a cell's diagonal (body_solid.h)
}

TEST(SdfSlice, NarrowBandIsExactlyThePointsWithinTheBandWidth) {
  const Vec3 extents(1.0, 0.62, 0.81);
  const BoxSurface box{0.5 * extents};  // the mesh is this box exactly: |phi| is the mesh distance
  for (int band : {1, 2, 3}) {
    const SignedDistanceGrid g = SignedDistanceGrid::build(makeBox(extents), {32, 3, band});
    const double width = band * g.cellSize();
    std::size_t exact = 0, checked = 0;
    forEverySample(g, [&](const SdfSlice& s, int u, int v) {
      const double d = std::abs(box.phi(s.point(u, v)));
      const bool isExact = s.stage[s.index(u, v)] == SdfStage::ExactBand;
      if (s.axis == 0) exact += isExact;  // each point once
      if (std::abs(d - width) < 1e-9 * g.cellSize()) return;  // on the band's edge: rounding decides
      ++checked;
      ASSERT_EQ(isExact, d <= width) << "band " << band << " cells, distance " << d / g.cellSize() << " cells";
    });
    EXPECT_EQ(exact, g.stats().exactPoints);
    EXPECT_GT(checked, 2 * g.pointCount());
  }
}

TEST(SdfSlice, EverySignIsThatOfItsFloodFillRegion) {
  for (const Mesh& mesh : {makeTorus(1.0, 0.3, 64, 24), hollowBallMesh(1.0, 0.6), makeUvSphere(0.5, 48, 24)}) {
    const SignedDistanceGrid g = SignedDistanceGrid::build(mesh, {32, 3, 2});
    forEverySample(g, [&](const SdfSlice& s, int u, int v) {
      const std::size_t i = s.index(u, v);
      switch (s.region[i]) {
        case SdfFillRegion::Outside:
        case SdfFillRegion::Cavity: ASSERT_GT(s.phi[i], 0.0) << mesh.name; break;
        case SdfFillRegion::Inside: ASSERT_LT(s.phi[i], 0.0) << mesh.name; break;
        case SdfFillRegion::OnSurface: ASSERT_LE(std::abs(s.phi[i]), 1e-9 * g.cellSize()); break;
        case SdfFillRegion::Unknown: FAIL() << "a built grid has every region";
      }
    });
  }
}

TEST(SdfSlice, TorusHoleIsOutsideThoughTheSliceEnclosesIt) {
  const double major = 1.0, minor = 0.3;  // about the y axis
  const SignedDistanceGrid g = SignedDistanceGrid::build(makeTorus(major, minor, 64, 24), {40, 3, 2});
  const double faceting = minor * (1 - std::cos(kPi / 24)) + (major + minor) * (1 - std::cos(kPi / 64));
  const SdfSlice s = sdfSlice(g, 1, 0.0);  // the torus's middle plane: a ring around the hole
  const int u = (s.width - 1) / 2, v = (s.height - 1) / 2;
  ASSERT_LT(s.point(u, v).norm(), 1e-9);
  // The fill reached the hole through the 3D grid, around the ring, not across this layer.
  EXPECT_EQ(s.region[s.index(u, v)], SdfFillRegion::Outside);
  EXPECT_NEAR(s.phi[s.index(u, v)], major - minor, 1.25 * g.cellSize());
  int inside = 0;
  for (int b = 0; b < s.height; ++b) {
    for (int a = 0; a < s.width; ++a) {
      const Vec3 p = s.point(a, b);
      const double exact = std::hypot(std::hypot(p.x(), p.z()) - major, p.y()) - minor;
      if (std::abs(exact) <= faceting) continue;
      ASSERT_EQ(s.region[s.index(a, b)] == SdfFillRegion::Inside, exact < 0.0) << p.transpose();
      inside += exact < 0.0;
    }
  }
  EXPECT_GT(inside, 100);
}

TEST(SdfSlice, HollowSphereCavityIsAnEnclosedOutsideRegion) {
  const SignedDistanceGrid g = SignedDistanceGrid::build(hollowBallMesh(1.0, 0.6), {32, 3, 2});
  const double faceting = 1.0 * (1 - std::cos(kPi / 24));
  const SdfSlice s = sdfSlice(g, 0, 0.0);
  int cavity = 0;
  for (int v = 0; v < s.height; ++v) {
    for (int u = 0; u < s.width; ++u) {
      const double r = s.point(u, v).norm();
      if (std::abs(r - 1.0) <= faceting || std::abs(r - 0.6) <= faceting) continue;
      const SdfFillRegion expected = r < 0.6 ? SdfFillRegion::Cavity : r < 1.0 ? SdfFillRegion::Inside : SdfFillRegion::Outside;
      ASSERT_EQ(s.region[s.index(u, v)], expected) << "r = " << r;
      cavity += expected == SdfFillRegion::Cavity;
    }
  }
  EXPECT_GT(cavity, 50);
}

TEST(SdfSlice, ZeroContourLiesWithinACellOfTheSurfaceAndCloses) {
  const double radius = 1.0;
  const SignedDistanceGrid g = SignedDistanceGrid::build(makeUvSphere(radius, 96, 48), {32, 3, 2});
  const double h = g.cellSize();
  const SdfSlice s = sdfSlice(g, 1, 0.4);
  const double circle = std::sqrt(radius * radius - s.offset * s.offset);  // the true section's radius
  double worst = 0.0, length = 0.0;
  const std::vector<ContourSegment> contour = sdfZeroContour(s);
  for (const ContourSegment& c : contour) {
    for (const Eigen::Vector2d& e : {c.a, c.b}) worst = std::max(worst, std::abs(s.point(e.x(), e.y()).norm() - radius));
    length += (s.point(c.a.x(), c.a.y()) - s.point(c.b.x(), c.b.y())).norm();
  }
  std::printf("sphere slice y = %.4f m: %zu segments, worst %.4f h off the sphere, length %.4f m of %.4f m\n", s.offset,
              contour.size(), worst / h, length, 2 * kPi * circle);
  EXPECT_LT(worst, h);          // within a cell, as the contour of any grid should be
  EXPECT_LT(worst, 0.05 * h);   // of exact band values, linear along each edge: measured 0.013 h
  EXPECT_NEAR(length, 2 * kPi * circle, 0.01 * 2 * kPi * circle);  // one closed loop, all of it
  // Every segment end lies on an edge between samples of opposite sign: the loop has no loose end.
  for (const ContourSegment& c : contour) {
    int ends = 0;
    for (const ContourSegment& d : contour) ends += (d.a - c.a).norm() < 1e-12 || (d.b - c.a).norm() < 1e-12;
    EXPECT_EQ(ends, 2);
  }
  // A layer beyond the body has no contour.
  EXPECT_TRUE(sdfZeroContour(sdfSlice(g, 1, g.origin().y())).empty());
}

TEST(SdfSlice, SaddleCellsFollowTheCentreMean) {
  // One layer of 2 x 2 samples: corners (0, 0) and (1, 1) inside, the others outside.
  GridLattice lattice;
  lattice.dims = Vec3i(2, 2, 2);
  lattice.cellSize = 1.0;
  const auto slice = [&](double inside) {
    // x fastest: (0,0) (1,0) (0,1) (1,1) in each z layer.
    return sdfSlice(SignedDistanceGrid::fromValues(lattice, {inside, 1, 1, inside, inside, 1, 1, inside}), 2, 0.0);
  };
  // Mean below zero: the inside corners join across the centre, the outside ones are cut off.
  const std::vector<ContourSegment> joined = sdfZeroContour(slice(-3.0));
  ASSERT_EQ(joined.size(), 2u);
  for (const ContourSegment& c : joined) {
    const Eigen::Vector2d mid = 0.5 * (c.a + c.b);
    EXPECT_GT(std::abs(mid.x() - mid.y()), 0.4);  // both segments off the inside diagonal
  }
  // Mean above zero: the inside corners are cut off each on its own.
  const std::vector<ContourSegment> apart = sdfZeroContour(slice(-0.5));
  ASSERT_EQ(apart.size(), 2u);
  for (const ContourSegment& c : apart) {
    const Eigen::Vector2d mid = 0.5 * (c.a + c.b);
    EXPECT_LT(std::abs(mid.x() - mid.y()), 1e-12);  // centred on the inside diagonal
  }
}

TEST(SdfSlice, GivenGridsHaveNoBuildStagesAndBadSlicesThrow) {
  GridLattice lattice;
  lattice.dims = Vec3i(3, 3, 3);
  lattice.cellSize = 0.5;
  const SignedDistanceGrid g = SignedDistanceGrid::fromValues(lattice, std::vector<double>(27, 1.0));
  const SdfSlice s = sdfSlice(g, 0, 0.9);
  EXPECT_EQ(s.layer, 2);
  EXPECT_EQ(s.stage[0], SdfStage::Given);
  EXPECT_EQ(s.region[0], SdfFillRegion::Unknown);
  EXPECT_THROW(sdfSlice(g, 3, 0.0), std::invalid_argument);
  EXPECT_THROW(sdfSlice(g, 0, 1.26), std::invalid_argument);  // beyond the last layer by more than h / 2
  EXPECT_THROW(sdfSlice(g, 0, -0.26), std::invalid_argument);
  EXPECT_THROW(sdfSlice(g, 0, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim

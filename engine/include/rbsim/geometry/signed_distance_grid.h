#pragma once
// Discrete implicit surface (seed 000 "Discrete Implicit Surfaces", "Constructing Signed Distance
// Functions"): signed distances phi [m] at the points of a grid laid over a padded bounding box of
// a closed triangle mesh, trilinearly interpolated between them; phi < 0 inside, > 0 outside.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/geometry/grid_lattice.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Bounds of the resolution option; a grid also has to fit kMaxSdfGridPoints, which for a mesh as
// wide as it is long allows a resolution of about 240 only (1024 fits a slender mesh: a rod).
inline constexpr int kMinSdfResolution = 4;
inline constexpr int kMaxSdfResolution = 1024;
// Budget of one grid, counted before anything is allocated: building holds ~kSdfBytesPerPoint per
// point (distances, labels, marks, the flood fill's regions and stack, the marching heap).
inline constexpr double kSdfBytesPerPoint = 40.0;      // [bytes / point], peak ~30 measured at 9e6
inline constexpr double kMaxSdfGridPoints = 1.6e7;     // [points]: ~640 MB and ~10 s processor time
// Budget of marking the exact band: each triangle visits the grid points of its box grown by the
// band; a mesh of many long triangles crossing the whole grid would visit points x triangles.
inline constexpr double kMaxSdfBandVisits = 1e9;       // [point visits], ~1 s

// Which stage of build() set a grid point's value (seed 000 "Constructing Signed Distance
// Functions"): the exact distance to the mesh within the narrow band, or fast marching beyond it.
// Given: a grid made by fromValues (an implicit shape's samples, a file), no stage of build().
enum class SdfStage : std::uint8_t { Given, ExactBand, Marched };
// Where the sign flood fill (seed 000 "Sign of phi") put a grid point: Outside, in a region that
// reached the grid's boundary; Inside, in an enclosed region the mesh's normals vote inside;
// Cavity, in an enclosed region they vote outside (a hollow body's hole); OnSurface, a point on
// the surface itself, cut off from every neighbour. Unknown for a grid made by fromValues.
enum class SdfFillRegion : std::uint8_t { Unknown, Outside, Inside, Cavity, OnSurface };

struct SdfGridOptions {
  int resolution = 32;     // cells along the longest side of the mesh's bounding box [1], >= 4
  int paddingCells = 3;    // cells of padding on every side [1], >= 1
  int exactBandCells = 2;  // points within this many cells of the surface get exact distances
                           // [1], >= 1 (the sign pass needs every point within one cell exact)
};

// The grid build() lays over the mesh (padded bounding box, cells of longest side / resolution),
// and the point visits of its exact band. Options must be in range (build() checks them).
GridLattice sdfGridLattice(const Mesh& mesh, const SdfGridOptions& options);
double sdfBandVisits(const Mesh& mesh, const GridLattice& shape, const SdfGridOptions& options);
// "resolution 1024 lays a 1031 x 1031 x 1031 grid over mesh 'm' (1.1e+09 points, ~44 GB); the limit
// is 1.6e+07 points (~640 MB)", or empty when both budgets hold.
std::string sdfBudgetProblem(const Mesh& mesh, const SdfGridOptions& options);

class SignedDistanceGrid {
 public:
  struct BuildStats {
    std::size_t exactPoints = 0;    // distances from the closest point on the mesh
    std::size_t marchedPoints = 0;  // distances by fast marching
    int regions = 0;                // regions of the sign flood fill (not counting single grid
                                    // points on the surface, which it cuts off)
    double seconds = 0.0;           // processor time of build() [s], of which:
    double exactSeconds = 0.0;      //   the exact band (BVH built and queried) [s]
    double marchSeconds = 0.0;      //   fast marching [s]
    double signSeconds = 0.0;       //   occlusion tests and the flood fill [s]
  };

  // Throws std::invalid_argument (naming the mesh and what is wrong) for an open, inconsistently
  // oriented, inside-out or degenerate mesh, non-finite vertices, options out of range, or a grid
  // over budget (sdfBudgetProblem).
  static SignedDistanceGrid build(const Mesh& mesh, const SdfGridOptions& options = {});
  // A grid of given values (x fastest, as GridLattice::index), e.g. one read back from a file.
  // Throws std::invalid_argument when the counts disagree, an axis has fewer than 2 points, the
  // cell size is not positive or a value is not finite.
  static SignedDistanceGrid fromValues(const GridLattice& shape, std::vector<double> values);

  // Trilinear interpolation of the grid values [m]. Outside the grid's box: the distance to the
  // box plus phi at the nearest point of the box.
  double phi(const Vec3& p) const;
  // The exact derivative of phi() above (of the trilinear interpolant inside the box; outside, the
  // direction away from the box along the clamped axes and the interpolant's derivative along the
  // others). On a cell face, the cell on the + side.
  Vec3 gradient(const Vec3& p) const;
  // phi(p), and gradient(p) into `gradient`, with one interpolation.
  double phiAndGradient(const Vec3& p, Vec3& gradient) const;
  // gradient / |gradient| (seed 000 "Collision Detection"); the zero vector where the gradient
  // vanishes (a point of the medial axis where the interpolant is flat).
  Vec3 normal(const Vec3& p) const;

  const Vec3& origin() const { return shape_.origin; }
  double cellSize() const { return shape_.cellSize; }
  const Vec3i& dims() const { return shape_.dims; }
  std::size_t pointCount() const { return shape_.pointCount(); }
  Vec3 point(int i, int j, int k) const { return shape_.point(i, j, k); }
  double value(int i, int j, int k) const { return values_[shape_.index(i, j, k)]; }
  const BuildStats& stats() const { return stats_; }
  // How build() came to value(i, j, k): kept (one byte a point) so that a slice can show the
  // narrow band and the flood fill's regions (geometry/sdf_slice.h).
  SdfStage stage(int i, int j, int k) const;
  SdfFillRegion fillRegion(int i, int j, int k) const;

 private:
  // phi and its gradient at a point of the grid's box.
  double interpolate(const Vec3& p, Vec3* gradient) const;

  GridLattice shape_;
  std::vector<double> values_;
  // Per point: SdfStage in bits 0-1, SdfFillRegion in bits 2-4; empty for fromValues grids.
  std::vector<std::uint8_t> provenance_;
  BuildStats stats_;
};

}  // namespace rbsim

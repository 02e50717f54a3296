#include "rbsim/geometry/signed_distance_grid.h"

#include <algorithm>
#include <ctime>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/fast_marching.h"
#include "geometry/sign_flood_fill.h"
#include "geometry/triangle_bvh.h"

namespace rbsim {

namespace {

void requireOption(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("SignedDistanceGrid: " + what);
}

void validate(const Mesh& mesh, const SdfGridOptions& options) {
  requireOption(options.resolution >= kMinSdfResolution && options.resolution <= kMaxSdfResolution,
                "resolution is " + std::to_string(options.resolution) + ", expected " +
                    std::to_string(kMinSdfResolution) + " to " + std::to_string(kMaxSdfResolution));
  requireOption(options.paddingCells >= 1,
                "paddingCells is " + std::to_string(options.paddingCells) + ", expected >= 1");
  requireOption(options.exactBandCells >= 1,
                "exactBandCells is " + std::to_string(options.exactBandCells) + ", expected >= 1");
  const std::string prefix = "SignedDistanceGrid: mesh '" + mesh.name + "' ";
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      throw std::invalid_argument(prefix + "vertex " + std::to_string(v) + " is not finite");
    }
  }
  const MeshCheck check = checkMesh(mesh);
  if (!check.closed || !check.consistentlyOriented || check.degenerateTriangles > 0) {
    throw std::invalid_argument(prefix + "is not a closed, consistently oriented mesh without "
                                "degenerate triangles: " + check.problem);
  }
  // Six times the enclosed volume by the divergence theorem: positive when the triangles face out.
  double sixVolume = 0.0;
  for (const Triangle& t : mesh.triangles) {
    sixVolume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  if (!(sixVolume > 0.0)) {
    throw std::invalid_argument(prefix + "encloses a volume of " + std::to_string(sixVolume / 6.0) +
                                " m^3; expected > 0 (triangles counter-clockwise seen from outside)");
  }
}

// The grid points of triangle t's box grown by `radius`, as index ranges [first, last] per axis.
void bandRange(const Mesh& mesh, const Triangle& t, const GridLattice& shape, double radius, Vec3i& first, Vec3i& last) {
  Aabb box;
  for (std::uint32_t v : t) box.grow(mesh.vertices[v]);
  const Vec3 lo = (box.min.array() - radius - shape.origin.array()) / shape.cellSize;
  const Vec3 hi = (box.max.array() + radius - shape.origin.array()) / shape.cellSize;
  first = lo.array().ceil().cast<int>().max(0);
  last = hi.array().floor().cast<int>().min((shape.dims - Vec3i::Ones()).array());
}

std::string megabytes(double bytes) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << bytes / 1e6 << " MB";
  return out.str();
}

}  // namespace

// Padded bounding box (seed 000 "Constructing Signed Distance Functions"), centred on the mesh.
GridLattice sdfGridLattice(const Mesh& mesh, const SdfGridOptions& options) {
  const Vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax();
  GridLattice shape;
  shape.cellSize = (hi - lo).maxCoeff() / options.resolution;
  for (int axis = 0; axis < 3; ++axis) {
    // In [1, resolution] before the cast, whatever the box (a flat or non-finite one gives NaN).
    double cells = std::ceil((hi[axis] - lo[axis]) / shape.cellSize - 1e-9);
    if (!(cells >= 1.0)) cells = 1.0;
    cells = std::min(cells, double(options.resolution));
    shape.dims[axis] = static_cast<int>(cells) + 2 * options.paddingCells + 1;
  }
  shape.origin = 0.5 * (lo + hi) - 0.5 * shape.cellSize * (shape.dims - Vec3i::Ones()).cast<double>();
  return shape;
}

double sdfBandVisits(const Mesh& mesh, const GridLattice& shape, const SdfGridOptions& options) {
  double visits = 0.0;
  Vec3i first, last;
  for (const Triangle& t : mesh.triangles) {
    bandRange(mesh, t, shape, options.exactBandCells * shape.cellSize, first, last);
    if ((last.array() >= first.array()).all()) visits += (last - first + Vec3i::Ones()).cast<double>().prod();
  }
  return visits;
}

std::string sdfBudgetProblem(const Mesh& mesh, const SdfGridOptions& options) {
  const GridLattice shape = sdfGridLattice(mesh, options);
  const double points = shape.dims.cast<double>().prod();
  std::ostringstream problem;
  problem << std::setprecision(3) << "resolution " << options.resolution << " lays a " << shape.dims.x() << " x "
          << shape.dims.y() << " x " << shape.dims.z() << " grid over mesh '" << mesh.name << "' (";
  if (points > kMaxSdfGridPoints) {
    problem << points << " points, ~" << megabytes(points * kSdfBytesPerPoint) << " to build); the limit is "
            << kMaxSdfGridPoints << " points (~" << megabytes(kMaxSdfGridPoints * kSdfBytesPerPoint) << ")";
    return problem.str();
  }
  const double visits = sdfBandVisits(mesh, shape, options);
  if (visits > kMaxSdfBandVisits) {
    problem << points << " points) whose exact band needs " << visits << " point visits by its "
            << mesh.triangles.size() << " triangles; the limit is " << kMaxSdfBandVisits << " visits";
    return problem.str();
  }
  return "";
}

SignedDistanceGrid SignedDistanceGrid::build(const Mesh& mesh, const SdfGridOptions& options) {
  // Processor time (the build is single-threaded): on a shared machine wall time would also count
  // the time other processes hold the core.
  const auto since = [](std::clock_t t) { return double(std::clock() - t) / CLOCKS_PER_SEC; };
  const std::clock_t start = std::clock();
  validate(mesh, options);
  const std::string overBudget = sdfBudgetProblem(mesh, options);
  if (!overBudget.empty()) throw std::invalid_argument("SignedDistanceGrid: " + overBudget);
  SignedDistanceGrid grid;
  GridLattice& shape = grid.shape_;
  shape = sdfGridLattice(mesh, options);
  const double h = shape.cellSize;
  const std::size_t n = shape.pointCount();
  std::clock_t phase = std::clock();
  const TriangleBvh bvh(mesh);

  // Exact band: the seed's sphere of a few cells around each grid point, asked only of points
  // inside some triangle's box grown by the radius (the others cannot meet a triangle).
  const double radius = options.exactBandCells * h;
  std::vector<bool> candidate(n, false);
  Vec3i first, last;
  for (const Triangle& t : mesh.triangles) {
    bandRange(mesh, t, shape, radius, first, last);
    for (int k = first.z(); k <= last.z(); ++k) {
      for (int j = first.y(); j <= last.y(); ++j) {
        for (int i = first.x(); i <= last.x(); ++i) candidate[shape.index(i, j, k)] = true;
      }
    }
  }
  std::vector<MarchLabel> labels(n, MarchLabel::White);
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<SurfaceProximity> proximity(n, SurfaceProximity::Far);
  for (std::size_t p = 0; p < n; ++p) {
    if (!candidate[p]) continue;
    const Vec3i c = shape.coordinates(p);
    const auto hit = bvh.closestWithin(shape.point(c.x(), c.y(), c.z()), radius);
    if (!hit) {
      candidate[p] = false;  // kept below as the band's points (SdfStage::ExactBand)
      continue;
    }
    labels[p] = MarchLabel::Black;
    distance[p] = hit->distance;
    if (hit->distance <= kOnSurfaceCells * h) {
      proximity[p] = SurfaceProximity::OnSurface;
    } else if (hit->distance <= h) {
      proximity[p] = SurfaceProximity::WithinOneCell;
    }
    ++grid.stats_.exactPoints;
  }

  const std::vector<bool>& exact = candidate;  // now exactly the points the band valued
  grid.stats_.exactSeconds = since(phase);
  phase = std::clock();
  grid.stats_.marchedPoints = fastMarch(shape, labels, distance);
  grid.stats_.marchSeconds = since(phase);
  phase = std::clock();
  const SignRegions sign = floodFillSigns(shape, bvh, mesh, proximity);
  grid.stats_.signSeconds = since(phase);
  grid.stats_.regions = sign.regions;
  grid.values_ = std::move(distance);
  grid.provenance_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (sign.inside[p]) grid.values_[p] = -grid.values_[p];
    // Points the exact band left White were marched (fastMarch leaves every point Black).
    const SdfStage stage = exact[p] ? SdfStage::ExactBand : SdfStage::Marched;
    grid.provenance_[p] = static_cast<std::uint8_t>(static_cast<unsigned>(stage) | static_cast<unsigned>(sign.kind[p]) << 2);
  }
  grid.stats_.seconds = since(start);
  return grid;
}

SignedDistanceGrid SignedDistanceGrid::fromValues(const GridLattice& shape, std::vector<double> values) {
  requireOption((shape.dims.array() >= 2).all(), "fromValues: every axis needs >= 2 points");
  requireOption(shape.cellSize > 0.0 && shape.origin.allFinite(),
                "fromValues: cell size " + std::to_string(shape.cellSize) +
                    " m and the origin must be positive and finite");
  requireOption(values.size() == shape.pointCount(),
                "fromValues: " + std::to_string(values.size()) + " values for " +
                    std::to_string(shape.pointCount()) + " grid points");
  for (std::size_t p = 0; p < values.size(); ++p) {
    requireOption(std::isfinite(values[p]), "fromValues: value " + std::to_string(p) + " is not finite");
  }
  SignedDistanceGrid grid;
  grid.shape_ = shape;
  grid.values_ = std::move(values);
  return grid;
}

SdfStage SignedDistanceGrid::stage(int i, int j, int k) const {
  if (provenance_.empty()) return SdfStage::Given;
  return static_cast<SdfStage>(provenance_[shape_.index(i, j, k)] & 0x3u);
}

SdfFillRegion SignedDistanceGrid::fillRegion(int i, int j, int k) const {
  if (provenance_.empty()) return SdfFillRegion::Unknown;
  return static_cast<SdfFillRegion>(provenance_[shape_.index(i, j, k)] >> 2 & 0x7u);
}

double SignedDistanceGrid::interpolate(const Vec3& p, Vec3* gradient) const {
  // Seed 000 "Discrete Implicit Surfaces": trilinear interpolation, like 3D textures.
  const Vec3 s = (p - shape_.origin) / shape_.cellSize;
  Vec3i cell;
  Vec3 t;
  for (int axis = 0; axis < 3; ++axis) {
    cell[axis] = std::clamp(static_cast<int>(std::floor(s[axis])), 0, shape_.dims[axis] - 2);
    t[axis] = s[axis] - cell[axis];
  }
  const std::size_t base = shape_.index(cell.x(), cell.y(), cell.z());
  const std::size_t sx = shape_.stride(0), sy = shape_.stride(1), sz = shape_.stride(2);
  const double v000 = values_[base], v100 = values_[base + sx];
  const double v010 = values_[base + sy], v110 = values_[base + sx + sy];
  const double v001 = values_[base + sz], v101 = values_[base + sx + sz];
  const double v011 = values_[base + sy + sz], v111 = values_[base + sx + sy + sz];
  // Along x, then y, then z; the derivatives follow from the same products.
  const double v00 = v000 + t.x() * (v100 - v000), v10 = v010 + t.x() * (v110 - v010);
  const double v01 = v001 + t.x() * (v101 - v001), v11 = v011 + t.x() * (v111 - v011);
  const double v0 = v00 + t.y() * (v10 - v00), v1 = v01 + t.y() * (v11 - v01);
  if (gradient != nullptr) {
    const double dx0 = (1 - t.y()) * (v100 - v000) + t.y() * (v110 - v010);
    const double dx1 = (1 - t.y()) * (v101 - v001) + t.y() * (v111 - v011);
    *gradient = Vec3((1 - t.z()) * dx0 + t.z() * dx1, (1 - t.z()) * (v10 - v00) + t.z() * (v11 - v01),
                     v1 - v0) / shape_.cellSize;
  }
  return v0 + t.z() * (v1 - v0);
}

double SignedDistanceGrid::phi(const Vec3& p) const {
  const Vec3 hi = shape_.origin + shape_.cellSize * (shape_.dims - Vec3i::Ones()).cast<double>();
  const Vec3 q = p.cwiseMax(shape_.origin).cwiseMin(hi);
  return (p - q).norm() + interpolate(q, nullptr);
}

double SignedDistanceGrid::phiAndGradient(const Vec3& p, Vec3& gradient) const {
  const Vec3 hi = shape_.origin + shape_.cellSize * (shape_.dims - Vec3i::Ones()).cast<double>();
  const Vec3 q = p.cwiseMax(shape_.origin).cwiseMin(hi);
  const double inside = interpolate(q, &gradient);
  const Vec3 away = p - q;
  const double length = away.norm();
  if (length == 0.0) return inside;
  for (int axis = 0; axis < 3; ++axis) {
    if (away[axis] != 0.0) gradient[axis] = away[axis] / length;
  }
  return length + inside;
}

Vec3 SignedDistanceGrid::gradient(const Vec3& p) const {
  Vec3 g;
  phiAndGradient(p, g);
  return g;
}

Vec3 SignedDistanceGrid::normal(const Vec3& p) const {
  const Vec3 g = gradient(p);
  const double length = g.norm();
  return length > 0.0 ? Vec3(g / length) : Vec3::Zero();
}

}  // namespace rbsim

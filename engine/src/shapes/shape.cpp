#include "rbsim/shapes/shape.h"

#include <algorithm>
#include <array>
#include <string>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace rbsim {

namespace {

// Vertices this close [m] are one vertex of the hull graph (a UV sphere's pole and seam copies).
constexpr double kWeldDistance = 1e-12;

std::shared_ptr<const HullAdjacency> adjacencyPtr(const Mesh& mesh) {
  return std::make_shared<const HullAdjacency>(hullAdjacencyOf(mesh));
}

Vec3 scanSupport(const std::vector<Vec3>& points, const Vec3& d) {
  std::size_t best = 0;
  double bestDot = points[0].dot(d);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double dot = points[i].dot(d);
    if (dot > bestDot) bestDot = dot, best = i;
  }
  return points[best];
}

// The corner of the box of half extents h furthest along d (ties to +).
Vec3 boxSupport(const Vec3& h, const Vec3& d) {
  return Vec3(d.x() >= 0.0 ? h.x() : -h.x(), d.y() >= 0.0 ? h.y() : -h.y(), d.z() >= 0.0 ? h.z() : -h.z());
}

// The integral of x^2 over a rounded box with core half extents (a, b, c), a along x, and radius r
// [m^5], summed over its pieces. A quarter disc of radius r has area pi r^2 / 4, first moment
// r^3 / 3 and second moment pi r^4 / 16 about its edges; a ball eighth has volume pi r^3 / 6,
// first moment pi r^4 / 16 and second moment pi r^5 / 30 about its faces.
double roundedBoxSecondMoment(double a, double b, double c, double r) {
  const double a3 = a * a * a;
  const double core = 8.0 * a3 * b * c / 3.0;
  const double slabsX = 8.0 * b * c * ((a + r) * (a + r) * (a + r) - a3) / 3.0;  // the two faces normal to x
  const double slabsYZ = 8.0 * a3 * r * (b + c) / 3.0;                              // the four others
  const double edgesX = 2.0 * kPi * r * r * a3 / 3.0;  // along x: a cylinder of area pi r^2, length 2a
  // Along y and z: four quarter discs at x = +-a, each integrating (a + u)^2, over lengths 2b, 2c.
  const double edgesYZ = 2.0 * (b + c) * (kPi * r * r * a * a + 8.0 * a * r * r * r / 3.0 + kPi * r * r * r * r / 4.0);
  const double corners = 4.0 * kPi * a * a * r * r * r / 3.0 + kPi * a * r * r * r * r + 4.0 * kPi * r * r * r * r * r / 15.0;
  return core + slabsX + slabsYZ + edgesX + edgesYZ + corners;
}

}  // namespace

const char* shapeTypeName(ShapeType type) {
  switch (type) {
    case ShapeType::Sphere: return "sphere";
    case ShapeType::Capsule: return "capsule";
    case ShapeType::Box: return "box";
    case ShapeType::RoundedBox: return "rounded box";
    case ShapeType::ConvexHull: return "convex hull";
    case ShapeType::Mesh: return "mesh";
  }
  return "?";
}

HullAdjacency hullAdjacencyOf(const Mesh& mesh) {
  HullAdjacency out;
  // Weld by exact position after rounding to the weld distance: the generators write the pole
  // and seam copies as the same doubles, and an OBJ repeats a vertex's text.
  std::map<std::array<long long, 3>, unsigned> index;
  std::vector<unsigned> welded(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const std::array<long long, 3> key{std::llround(p.x() / kWeldDistance), std::llround(p.y() / kWeldDistance),
                                       std::llround(p.z() / kWeldDistance)};
    const auto [it, added] = index.emplace(key, static_cast<unsigned>(out.vertices.size()));
    if (added) out.vertices.push_back(p);
    welded[i] = it->second;
  }
  std::vector<std::set<unsigned>> edges(out.vertices.size());
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const unsigned a = welded[t[k]], b = welded[t[(k + 1) % 3]];
      if (a == b) continue;
      edges[a].insert(b);
      edges[b].insert(a);
    }
  }
  out.neighbours.reserve(edges.size());
  for (const auto& e : edges) out.neighbours.emplace_back(e.begin(), e.end());
  return out;
}

namespace {

void requirePositive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("shape: ") + what + " must be a positive finite length [m]");
  }
}

}  // namespace

Shape shapeOfMesh(const Mesh& mesh, bool hasGrid) {
  if (hasGrid) return Shape::mesh(mesh);
  if (mesh.vertices.size() == 8) {
    const Vec3 h = mesh.vertices[0].cwiseAbs();
    int corners = 0;  // bit k set: the corner with signs k seen
    for (const Vec3& p : mesh.vertices) {
      if (p.cwiseAbs() != h) break;
      corners |= 1 << ((p.x() > 0.0 ? 1 : 0) | (p.y() > 0.0 ? 2 : 0) | (p.z() > 0.0 ? 4 : 0));
    }
    if (corners == 0xff && (h.array() > 0.0).all()) return Shape::box(h);
  }
  return Shape::convexHull(mesh);
}

Shape Shape::sphere(double radius) {
  requirePositive(radius, "a sphere's radius");
  Shape s;
  s.type = ShapeType::Sphere;
  s.radius = radius;
  return s;
}

Shape Shape::capsule(double radius, double halfLength) {
  requirePositive(radius, "a capsule's radius");
  if (!(halfLength >= 0.0) || !std::isfinite(halfLength)) {
    throw std::invalid_argument("shape: a capsule's half length must be a finite length >= 0 [m]");
  }
  Shape s;
  s.type = ShapeType::Capsule;
  s.radius = radius;
  s.halfLength = halfLength;
  return s;
}

Shape Shape::roundedBox(const Vec3& coreHalfExtents, double radius) {
  requirePositive(radius, "a rounded box's radius");
  for (int k = 0; k < 3; ++k) {
    if (!(coreHalfExtents[k] >= 0.0) || !std::isfinite(coreHalfExtents[k])) {
      throw std::invalid_argument("shape: a rounded box's core half extents must be finite lengths >= 0 [m]");
    }
  }
  Shape s;
  s.type = ShapeType::RoundedBox;
  s.radius = radius;
  s.halfExtents = coreHalfExtents;
  return s;
}

Shape Shape::box(const Vec3& halfExtents) {
  for (int k = 0; k < 3; ++k) requirePositive(halfExtents[k], "a box's half extent");
  Shape s;
  s.type = ShapeType::Box;
  s.halfExtents = halfExtents;
  return s;
}

Shape Shape::convexHull(const Mesh& mesh) {
  if (mesh.vertices.empty()) throw std::invalid_argument("shape: a hull needs at least one vertex");
  Shape s;
  s.type = ShapeType::ConvexHull;
  s.hull = adjacencyPtr(mesh);
  s.faces = std::make_shared<const FacePlanes>(facePlanesOf(mesh));
  return s;
}

Shape Shape::mesh(const Mesh& mesh) {
  if (mesh.vertices.empty()) throw std::invalid_argument("shape: a mesh needs at least one vertex");
  Shape s;
  s.type = ShapeType::Mesh;
  s.hull = adjacencyPtr(mesh);
  return s;
}

Vec3 Shape::support(const Vec3& d, unsigned* hint) const {
  switch (type) {
    case ShapeType::Sphere: return radius * d.normalized();
    case ShapeType::Capsule:
      return Vec3(0.0, d.y() >= 0.0 ? halfLength : -halfLength, 0.0) + radius * d.normalized();
    case ShapeType::Box: return boxSupport(halfExtents, d);
    case ShapeType::RoundedBox: return boxSupport(halfExtents, d) + radius * d.normalized();  // the core's, pushed out by r
    case ShapeType::ConvexHull:
    case ShapeType::Mesh: break;
  }
  const HullAdjacency& h = *hull;
  if (h.vertices.size() <= kHillClimbMinVertices || hint == nullptr) return scanSupport(h.vertices, d);
  unsigned at = *hint < h.vertices.size() ? *hint : 0;
  double best = h.vertices[at].dot(d);
  for (bool moved = true; moved;) {
    moved = false;
    for (const unsigned n : h.neighbours[at]) {
      const double dot = h.vertices[n].dot(d);
      if (dot > best) best = dot, at = n, moved = true;
    }
  }
  *hint = at;
  return h.vertices[at];
}

double Shape::boundingRadius() const {
  switch (type) {
    case ShapeType::Sphere: return radius;
    case ShapeType::Capsule: return halfLength + radius;
    case ShapeType::Box: return halfExtents.norm();
    case ShapeType::RoundedBox: return halfExtents.norm() + radius;
    case ShapeType::ConvexHull:
    case ShapeType::Mesh: break;
  }
  double r = 0.0;
  for (const Vec3& p : hull->vertices) r = std::max(r, p.norm());
  return r;
}

std::pair<Vec3, Vec3> Shape::worldBounds(const Mat3& R, const Vec3& x) const {
  Vec3 half = Vec3::Zero();
  switch (type) {
    case ShapeType::Sphere: half = Vec3::Constant(radius); break;
    // The segment's ends at x +- h R e_y, each grown by r.
    case ShapeType::Capsule: half = (halfLength * R.col(1)).cwiseAbs() + Vec3::Constant(radius); break;
    // |R| h: the box's extent along each world axis (Ericson 4.2.6).
    case ShapeType::Box: half = R.cwiseAbs() * halfExtents; break;
    case ShapeType::RoundedBox: half = R.cwiseAbs() * halfExtents + Vec3::Constant(radius); break;
    case ShapeType::ConvexHull:
    case ShapeType::Mesh: {
      Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
      for (const Vec3& p : hull->vertices) {
        const Vec3 w = R * p;
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
      }
      return {lo + x, hi + x};
    }
  }
  return {x - half, x + half};
}

std::pair<double, Vec3> Shape::roundDistance(const Vec3& local) const {
  if (type == ShapeType::RoundedBox) {
    // The nearest point of the core box, then r beyond it. Inside the core, the nearest face.
    const Vec3 core = local.cwiseMax(-halfExtents).cwiseMin(halfExtents);
    const Vec3 out = local - core;
    const double distance = out.norm();
    if (distance > 0.0) return {distance - radius, Vec3(out / distance)};
    int axis = 0;
    (halfExtents - local.cwiseAbs()).minCoeff(&axis);
    Vec3 normal = Vec3::Zero();
    normal[axis] = local[axis] >= 0.0 ? 1.0 : -1.0;
    return {local.cwiseAbs()[axis] - halfExtents[axis] - radius, normal};
  }
  Vec3 centre = Vec3::Zero();  // the nearest point of the sphere's centre or the capsule's segment
  if (type == ShapeType::Capsule) centre.y() = std::clamp(local.y(), -halfLength, halfLength);
  const Vec3 out = local - centre;
  const double distance = out.norm();
  // At the centre itself every direction is as good; +y keeps the normal unit.
  return {distance - radius, distance > 0.0 ? Vec3(out / distance) : Vec3(Vec3::UnitY())};
}

double roundOrBoxVolume(const Shape& shape) {
  const double r = shape.radius;
  switch (shape.type) {
    case ShapeType::Sphere: return 4.0 / 3.0 * kPi * r * r * r;
    case ShapeType::Capsule: return kPi * r * r * (2.0 * shape.halfLength) + 4.0 / 3.0 * kPi * r * r * r;
    case ShapeType::Box: return 8.0 * shape.halfExtents.prod();
    case ShapeType::RoundedBox: {
      // Core, six face slabs of thickness r, twelve quarter-cylinders along the edges (four per
      // axis, one cylinder of length 2 h_k each), eight ball eighths at the corners (one ball).
      const Vec3& h = shape.halfExtents;
      return 8.0 * h.prod() + 8.0 * r * (h.x() * h.y() + h.y() * h.z() + h.z() * h.x()) + 2.0 * kPi * r * r * h.sum() +
             4.0 / 3.0 * kPi * r * r * r;
    }
    default: throw std::logic_error("roundOrBoxVolume: a hull's volume is the polyhedral integral's");
  }
}

Mat3 roundOrBoxInertia(const Shape& shape, double mass) {
  const double r = shape.radius;
  switch (shape.type) {
    case ShapeType::Sphere: return Mat3::Identity() * (0.4 * mass * r * r);
    case ShapeType::Capsule: {
      // Mass split by volume between the cylinder (height H) and the two caps (one sphere).
      const double H = 2.0 * shape.halfLength;
      const double cylinder = kPi * r * r * H, caps = 4.0 / 3.0 * kPi * r * r * r;
      const double mc = mass * cylinder / (cylinder + caps), ms = mass - mc;
      const double axial = mc * r * r / 2.0 + ms * 0.4 * r * r;
      const double transverse = mc * (H * H / 12.0 + r * r / 4.0) + ms * (0.4 * r * r + H * H / 4.0 + 3.0 * H * r / 8.0);
      return Vec3(transverse, axial, transverse).asDiagonal();
    }
    case ShapeType::Box: {
      const Vec3 e = 2.0 * shape.halfExtents;
      return Vec3(e.y() * e.y() + e.z() * e.z(), e.x() * e.x() + e.z() * e.z(), e.x() * e.x() + e.y() * e.y())
                 .asDiagonal() * (mass / 12.0);
    }
    case ShapeType::RoundedBox: {
      // I_xx = rho (S_y + S_z), S_k the second moment along axis k (roundedBoxSecondMoment).
      const Vec3& h = shape.halfExtents;
      const double density = mass / roundOrBoxVolume(shape);
      const double sx = roundedBoxSecondMoment(h.x(), h.y(), h.z(), r);
      const double sy = roundedBoxSecondMoment(h.y(), h.z(), h.x(), r);
      const double sz = roundedBoxSecondMoment(h.z(), h.x(), h.y(), r);
      return Vec3(sy + sz, sx + sz, sx + sy).asDiagonal() * density;
    }
    default: throw std::logic_error("roundOrBoxInertia: a hull's inertia is the polyhedral integral's");
  }
}

}  // namespace rbsim

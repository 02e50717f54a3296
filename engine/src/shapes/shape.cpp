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

constexpr double kPi = 3.14159265358979323846;

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

}  // namespace

const char* shapeTypeName(ShapeType type) {
  switch (type) {
    case ShapeType::Sphere: return "sphere";
    case ShapeType::Capsule: return "capsule";
    case ShapeType::Box: return "box";
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
  return s;
}

Shape Shape::mesh(const Mesh& mesh) {
  Shape s = convexHull(mesh);
  s.type = ShapeType::Mesh;
  return s;
}

Vec3 Shape::support(const Vec3& d, unsigned* hint) const {
  switch (type) {
    case ShapeType::Sphere: return radius * d.normalized();
    case ShapeType::Capsule:
      return Vec3(0.0, d.y() >= 0.0 ? halfLength : -halfLength, 0.0) + radius * d.normalized();
    case ShapeType::Box:
      return Vec3(d.x() >= 0.0 ? halfExtents.x() : -halfExtents.x(), d.y() >= 0.0 ? halfExtents.y() : -halfExtents.y(),
                  d.z() >= 0.0 ? halfExtents.z() : -halfExtents.z());
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
    default: throw std::logic_error("roundOrBoxInertia: a hull's inertia is the polyhedral integral's");
  }
}

}  // namespace rbsim

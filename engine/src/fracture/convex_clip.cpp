#include "fracture/convex_clip.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rbsim {

namespace {

constexpr std::uint32_t kUnused = 0xffffffffu;

// Vertices of the clipped mesh, welded: a point on an edge is computed from the edge's two end
// vertices in index order, so the two triangles sharing the edge produce the same bits and share
// the vertex, which keeps the result closed.
class WeldedVertices {
 public:
  explicit WeldedVertices(const Mesh& source) : source_(source) {}

  std::uint32_t original(std::uint32_t v) { return intern({v, v}, source_.vertices[v]); }
  std::uint32_t onEdge(std::uint32_t a, std::uint32_t b, const std::vector<double>& distance) {
    if (a > b) std::swap(a, b);
    const double t = distance[a] / (distance[a] - distance[b]);  // the ends are on opposite sides
    return intern({a, b}, source_.vertices[a] + t * (source_.vertices[b] - source_.vertices[a]));
  }
  std::uint32_t add(const Vec3& p) {
    vertices_.push_back(p);
    return static_cast<std::uint32_t>(vertices_.size() - 1);
  }
  std::vector<Vec3>& vertices() { return vertices_; }

 private:
  std::uint32_t intern(std::pair<std::uint32_t, std::uint32_t> key, const Vec3& p) {
    const auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(vertices_.size()));
    if (inserted) vertices_.push_back(p);
    return it->second;
  }

  const Mesh& source_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> index_;
  std::vector<Vec3> vertices_;
};

}  // namespace

double clipTolerance(const Mesh& mesh) {
  if (mesh.vertices.empty()) return 0.0;
  return kClipRelativeTolerance * (mesh.boundsMax() - mesh.boundsMin()).norm();
}

Mesh clipConvexMesh(const Mesh& convex, const Vec3& normal, double offset, double tolerance) {
  if (!(tolerance >= 0.0)) throw std::invalid_argument("clipConvexMesh: tolerance must be >= 0");
  std::vector<double> distance(convex.vertices.size());
  bool anyInside = false, anyOutside = false;
  for (std::size_t i = 0; i < convex.vertices.size(); ++i) {
    double d = normal.dot(convex.vertices[i]) - offset;
    if (std::abs(d) <= tolerance) d = 0.0;  // on the plane
    distance[i] = d;
    anyInside = anyInside || d < 0.0;
    anyOutside = anyOutside || d > 0.0;
  }
  Mesh out;
  out.name = convex.name;
  if (!anyOutside) return convex;
  if (!anyInside) return out;

  // Sutherland-Hodgman on each triangle, keeping d <= 0; the kept polygon (at most 4 corners) is
  // fanned into triangles. Polygons with fewer than 3 corners lie in the plane and are dropped.
  WeldedVertices welded(convex);
  std::vector<Triangle> triangles;
  for (const Triangle& tri : convex.triangles) {
    std::uint32_t polygon[4];
    int corners = 0;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
      if (distance[a] <= 0.0) polygon[corners++] = welded.original(a);
      if ((distance[a] < 0.0 && distance[b] > 0.0) || (distance[a] > 0.0 && distance[b] < 0.0)) {
        polygon[corners++] = welded.onEdge(a, b, distance);
      }
    }
    if (corners < 3) continue;
    bool allOnPlane = true;  // a face lying in the cutting plane is replaced by the cap
    for (int e = 0; e < 3; ++e) allOnPlane = allOnPlane && distance[tri[e]] == 0.0;
    if (allOnPlane) continue;
    for (int k = 1; k + 1 < corners; ++k) triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
  }

  // The cap: every directed edge u->v of the kept surface without its twin v->u lies on the cut;
  // the cap supplies the twins as triangles (centroid, v, u), which face +normal because the
  // surface is wound outward.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const Triangle& t : triangles) {
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> border;
  for (const auto& [edge, count] : directed) {
    if (directed.find({edge.second, edge.first}) == directed.end()) border.push_back(edge);
  }
  if (!border.empty()) {
    Vec3 centroid = Vec3::Zero();
    for (const auto& [u, v] : border) centroid += welded.vertices()[u];
    centroid /= static_cast<double>(border.size());
    const std::uint32_t c = welded.add(centroid);
    for (const auto& [u, v] : border) triangles.push_back({c, v, u});
  }

  // Keep only the vertices some triangle uses: a kept vertex whose polygons all lay in the plane
  // was interned but belongs to no face, and the vertex list is also the body's collision shape.
  const std::vector<Vec3>& all = welded.vertices();
  std::vector<std::uint32_t> remap(all.size(), kUnused);
  for (Triangle& t : triangles) {
    for (std::uint32_t& index : t) {
      if (remap[index] == kUnused) {
        remap[index] = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(all[index]);
      }
      index = remap[index];
    }
  }
  out.triangles = std::move(triangles);
  return out;
}

}  // namespace rbsim

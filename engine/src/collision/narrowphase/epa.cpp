#include "collision/narrowphase/epa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/distance.h"
#include "rbsim/math/types.h"

namespace rbsim {

namespace {

// A polytope with more faces than this has stopped converging; the best face so far is used.
constexpr std::size_t kEpaMaxFaces = 1024;
// A face the new support point is less than this far behind [m] counts as seeing it: coplanar
// faces are replaced too, so a point on the line of a horizon edge never makes a flat new face.
constexpr double kEpaCoplanarTolerance = 1e-10;

// Distance [m] of p from the affine hull of pts (1 to 3 points).
double distanceFromHull(const std::vector<SupportPoint>& pts, const Vec3& p) {
  const Vec3& o = pts[0].w;
  if (pts.size() == 1) return (p - o).norm();
  const Vec3 d = pts[1].w - o;
  if (pts.size() == 2) return d.cross(p - o).norm() / d.norm();
  return std::abs((d.cross(pts[2].w - o)).normalized().dot(p - o));
}

// Directions to search for a point off the current affine hull (van den Bergen 2001 §4: a point
// is blown up along the axes, a segment around itself, a triangle along its normal).
std::vector<Vec3> searchDirections(const std::vector<SupportPoint>& pts) {
  if (pts.size() == 1) {
    return {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  }
  if (pts.size() == 2) {
    const Vec3 d = (pts[1].w - pts[0].w).normalized();
    int minAxis;
    d.cwiseAbs().minCoeff(&minAxis);
    const Vec3 u = d.cross(Vec3::Unit(minAxis)).normalized();
    const Vec3 v = d.cross(u);
    std::vector<Vec3> dirs;
    for (int k = 0; k < 6; ++k) {
      const double angle = k * kPi / 3.0;
      dirs.push_back(std::cos(angle) * u + std::sin(angle) * v);
    }
    return dirs;
  }
  const Vec3 n = (pts[1].w - pts[0].w).cross(pts[2].w - pts[0].w).normalized();
  return {n, -n};
}

// Four affinely independent support points containing the start simplex's hull, or false.
bool buildTetrahedron(const SupportMap& a, const SupportMap& b, const GjkSimplex& start,
                      std::vector<SupportPoint>& pts) {
  pts.clear();
  for (int k = 0; k < start.size; ++k) {
    if (pts.empty() || distanceFromHull(pts, start.points[k].w) > kEpaBlowUpTolerance) {
      if (pts.size() < 4) pts.push_back(start.points[k]);
    }
  }
  if (pts.size() == 4) {
    const Vec3 n = (pts[1].w - pts[0].w).cross(pts[2].w - pts[0].w).normalized();
    if (std::abs(n.dot(pts[3].w - pts[0].w)) > kEpaBlowUpTolerance) return true;
    pts.pop_back();
  }
  while (pts.size() < 4) {
    bool grew = false;
    for (const Vec3& dir : searchDirections(pts)) {
      const SupportPoint s = minkowskiSupport(a, b, dir);
      if (distanceFromHull(pts, s.w) > kEpaBlowUpTolerance) {
        pts.push_back(s);
        grew = true;
        break;
      }
    }
    if (!grew) return false;
  }
  return true;
}

// Faces of the polytope, each with its neighbours, so the faces seen from a new point can be
// found by flood fill from the nearest face: the seen region is then connected and its boundary
// (the horizon) one loop, even when rounding makes far faces look marginally visible.
struct Face {
  std::array<int, 3> v;    // vertex indices, counter-clockwise seen from outside
  std::array<int, 3> adj;  // adj[e]: the face across edge (v[e], v[e + 1])
  Vec3 normal;             // unit, outward
  double dist;             // normal . vertex: signed distance of the face's plane from the origin
  bool alive;
};

bool setPlane(const std::vector<SupportPoint>& verts, Face& f) {
  const Vec3& a = verts[f.v[0]].w;
  const Vec3 n = (verts[f.v[1]].w - a).cross(verts[f.v[2]].w - a);
  const double len = n.norm();
  const double edge = std::max((verts[f.v[1]].w - a).norm(), (verts[f.v[2]].w - a).norm());
  // The face's height over its longest edge from v[0] must exceed the blow-up tolerance.
  if (!(len > kEpaBlowUpTolerance * edge)) return false;
  f.normal = n / len;
  f.dist = f.normal.dot(a);
  return true;
}

// The index of the edge of f that runs from a to b.
int edgeIndex(const Face& f, int a, int b) {
  for (int e = 0; e < 3; ++e) {
    if (f.v[e] == a && f.v[(e + 1) % 3] == b) return e;
  }
  return -1;
}

struct HorizonEdge {
  int a, b;        // from a to b, as in the removed face
  int outer;       // the kept face across it
  int outerEdge;   // the edge index of (b, a) in that face
};

}  // namespace

EpaResult epa(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const GjkSimplex& start) {
  if (a.empty() || b.empty()) return EpaResult{};
  return epa(PointSetSupport(a), PointSetSupport(b), start);
}

EpaResult epa(const SupportMap& a, const SupportMap& b, const GjkSimplex& start) {
  EpaResult result;
  if (start.size < 1) return result;
  // Scratch kept per thread (the narrow phase collides on several), so that a steady step of a
  // pile of hulls allocates nothing; epa does not call itself.
  thread_local std::vector<SupportPoint> verts;
  thread_local std::vector<Face> faces;
  thread_local std::vector<int> stack, removed;
  thread_local std::vector<HorizonEdge> horizon;
  faces.clear();
  if (!buildTetrahedron(a, b, start, verts)) return result;

  static constexpr int kTetra[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
  for (const auto& t : kTetra) {
    Face f{{t[0], t[1], t[2]}, {-1, -1, -1}, Vec3::Zero(), 0.0, true};
    const Vec3 n = (verts[t[1]].w - verts[t[0]].w).cross(verts[t[2]].w - verts[t[0]].w);
    if (n.dot(verts[t[3]].w - verts[t[0]].w) > 0.0) std::swap(f.v[1], f.v[2]);  // outward
    if (!setPlane(verts, f)) return result;
    faces.push_back(f);
  }
  for (Face& f : faces) {
    for (int e = 0; e < 3; ++e) {
      for (int g = 0; g < 4; ++g) {
        if (edgeIndex(faces[g], f.v[(e + 1) % 3], f.v[e]) >= 0) f.adj[e] = g;
      }
    }
  }

  int best = 0;
  while (true) {
    best = -1;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (faces[f].alive && (best < 0 || faces[f].dist < faces[best].dist)) best = static_cast<int>(f);
    }
    if (result.iterations >= kEpaMaxIterations || faces.size() > kEpaMaxFaces) break;
    ++result.iterations;
    const SupportPoint s = minkowskiSupport(a, b, faces[best].normal);
    if (faces[best].normal.dot(s.w) - faces[best].dist <= kEpaTolerance) {
      result.converged = true;
      break;
    }

    // Flood fill the faces that see s (coplanar ones included, so no new face is flat).
    const int wi = static_cast<int>(verts.size());
    verts.push_back(s);
    stack.assign(1, best);
    removed.assign(1, best);
    horizon.clear();
    faces[best].alive = false;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int e = 0; e < 3; ++e) {
        const int g = faces[f].adj[e];
        if (!faces[g].alive) continue;
        if (faces[g].normal.dot(s.w - verts[faces[g].v[0]].w) > -kEpaCoplanarTolerance) {
          faces[g].alive = false;
          stack.push_back(g);
          removed.push_back(g);
        } else {
          const int p = faces[f].v[e], q = faces[f].v[(e + 1) % 3];
          horizon.push_back({p, q, g, edgeIndex(faces[g], q, p)});
        }
      }
    }

    // One new face per horizon edge; the horizon must be a single loop (each vertex starting
    // and ending one edge) and no new face flat, or rounding has broken the polytope.
    const std::size_t first = faces.size();
    bool broken = horizon.size() < 3;
    for (const HorizonEdge& h : horizon) {
      Face f{{h.a, h.b, wi}, {h.outer, -1, -1}, Vec3::Zero(), 0.0, true};
      broken |= !setPlane(verts, f) || h.outerEdge < 0;
      faces.push_back(f);
    }
    for (std::size_t i = first; i < faces.size() && !broken; ++i) {
      int next = -1, prev = -1, starts = 0, ends = 0;
      for (std::size_t j = first; j < faces.size(); ++j) {
        if (faces[j].v[0] == faces[i].v[1]) {
          next = static_cast<int>(j);
          ++starts;
        }
        if (faces[j].v[1] == faces[i].v[0]) {
          prev = static_cast<int>(j);
          ++ends;
        }
      }
      broken |= starts != 1 || ends != 1;
      faces[i].adj[1] = next;
      faces[i].adj[2] = prev;
    }
    if (broken) {
      faces.resize(first);
      for (int f : removed) faces[f].alive = true;
      verts.pop_back();
      break;
    }
    for (std::size_t i = 0; i < horizon.size(); ++i) {
      faces[horizon[i].outer].adj[horizon[i].outerEdge] = static_cast<int>(first + i);
    }
  }

  // The witness points come from the face holding the origin's projection: with coplanar faces
  // (common on boxes) the nearest face found may be a neighbour of it in the same plane.
  const Face& f = faces[best];
  const Vec3 foot = f.normal * f.dist;
  const auto onFaceOf = [&](const Face& g) {
    return closestPointOnTriangle(foot, verts[g.v[0]].w, verts[g.v[1]].w, verts[g.v[2]].w);
  };
  PointTriangleResult onFace = onFaceOf(f);
  const Face* home = &f;
  for (const Face& g : faces) {
    if (!g.alive || onFace.distance == 0.0 || std::abs(g.dist - f.dist) > kEpaTolerance) continue;
    const PointTriangleResult r = onFaceOf(g);
    if (r.distance < onFace.distance) {
      onFace = r;
      home = &g;
    }
  }
  result.valid = true;
  result.normal = f.normal;
  result.depth = f.dist;
  result.pointA = Vec3::Zero();
  result.pointB = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    result.pointA += onFace.barycentric[k] * verts[home->v[k]].a;
    result.pointB += onFace.barycentric[k] * verts[home->v[k]].b;
  }
  return result;
}

}  // namespace rbsim

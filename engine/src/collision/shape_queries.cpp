#include "rbsim/collision/shape_queries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "collision/narrowphase/epa.h"
#include "collision/narrowphase/gjk.h"

namespace rbsim {

namespace {

// A ray cast that has not closed on the hull by then stops where it is (each iteration moves
// to a new support plane; a few dozen suffice for hulls of thousands of vertices).
constexpr int kRayIterations = 128;

void refuseMesh(const Shape& shape, const char* query) {
  if (shape.type == ShapeType::Mesh) {
    throw std::invalid_argument(std::string(query) +
                                ": a mesh shape's solid is its signed distance grid; query the body's BodySolid");
  }
}

// A shape's support mapping in its body frame, for GJK.
class ShapeSupport final : public SupportMap {
 public:
  explicit ShapeSupport(const Shape& shape) : shape_(shape) {}
  Vec3 support(const Vec3& direction) const override { return shape_.support(direction, &hint_); }
  Vec3 anyPoint() const override { return shape_.support(Vec3::UnitX(), &hint_); }

 private:
  const Shape& shape_;
  mutable unsigned hint_ = 0;
};

// Exact signed distance to the box of half extents h: outside, to its nearest point; inside, to
// its nearest face.
ShapeDistance boxDistance(const Vec3& h, const Vec3& local) {
  const Vec3 out = local - local.cwiseMax(-h).cwiseMin(h);
  const double distance = out.norm();
  if (distance > 0.0) return {distance, out / distance};
  int axis = 0;
  (h - local.cwiseAbs()).minCoeff(&axis);
  Vec3 normal = Vec3::Zero();
  normal[axis] = local[axis] >= 0.0 ? 1.0 : -1.0;
  return {local.cwiseAbs()[axis] - h[axis], normal};
}

// A hull's distance through its support mapping: GJK from the point outside, EPA's penetration
// depth inside (van den Bergen 2003, ch. 4 and 5), each to its tolerance (kGjkDistanceTolerance,
// kEpaTolerance). A flat hull has no inside: a point in it is at 0.
ShapeDistance hullDistance(const Shape& shape, const Vec3& local) {
  const ShapeSupport hull(shape);
  const std::vector<Vec3> point{local};
  const PointSetSupport at(point);
  const GjkResult g = gjk(hull, at);
  if (!g.overlap) return {g.distance, (local - g.pointA) / g.distance};
  const EpaResult e = epa(hull, at, g.simplex);
  if (!e.valid) return {0.0, Vec3::UnitY()};
  return {-e.depth, e.normal};
}

// Ray against the ball of radius r about c, origin outside it.
std::optional<RayHit> raySphere(const Vec3& c, double r, const Vec3& o, const Vec3& d, double maxFraction) {
  const Vec3 m = o - c;
  const double a = d.squaredNorm(), b = m.dot(d), k = m.squaredNorm() - r * r;
  const double discriminant = b * b - a * k;
  if (k > 0.0 && b > 0.0) return std::nullopt;  // outside and heading away
  if (discriminant < 0.0) return std::nullopt;
  const double t = std::max((-b - std::sqrt(discriminant)) / a, 0.0);
  if (t > maxFraction) return std::nullopt;
  const Vec3 n = o + t * d - c;
  return RayHit{t, n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3(-d.normalized())};
}

// Slabs (Kay and Kajiya 1986) against the box of half extents h about c, origin outside it.
std::optional<RayHit> rayBox(const Vec3& c, const Vec3& h, const Vec3& o, const Vec3& d, double maxFraction) {
  double enter = -std::numeric_limits<double>::infinity(), exit = maxFraction;
  int axis = -1;
  double sign = 1.0;
  for (int i = 0; i < 3; ++i) {
    const double p = o[i] - c[i];
    if (d[i] == 0.0) {
      if (std::abs(p) > h[i]) return std::nullopt;
      continue;
    }
    double t1 = (-h[i] - p) / d[i], t2 = (h[i] - p) / d[i];
    double s = -1.0;  // entering through the -h face
    if (t1 > t2) {
      std::swap(t1, t2);
      s = 1.0;
    }
    if (t1 > enter) {
      enter = t1;
      axis = i;
      sign = s;
    }
    exit = std::min(exit, t2);
  }
  if (axis < 0 || enter > exit || exit < 0.0) return std::nullopt;
  Vec3 n = Vec3::Zero();
  n[axis] = sign;
  return RayHit{std::max(enter, 0.0), n};
}

// The capsule of radius r around the segment c +- h e_axis: its cylinder's side, then its caps.
std::optional<RayHit> rayCapsule(const Vec3& c, int axis, double h, double r, const Vec3& o, const Vec3& d,
                                 double maxFraction) {
  std::optional<RayHit> best;
  const auto keep = [&](const std::optional<RayHit>& hit) {
    if (hit && (!best || hit->fraction < best->fraction)) best = hit;
  };
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double pu = o[u] - c[u], pv = o[v] - c[v];
  const double a = d[u] * d[u] + d[v] * d[v];
  if (a > 0.0) {
    const double b = pu * d[u] + pv * d[v], k = pu * pu + pv * pv - r * r;
    const double discriminant = b * b - a * k;
    if (discriminant >= 0.0) {
      const double t = (-b - std::sqrt(discriminant)) / a;
      const double along = o[axis] + t * d[axis] - c[axis];
      if (t >= 0.0 && t <= maxFraction && std::abs(along) <= h) {
        Vec3 n = Vec3::Zero();
        n[u] = (pu + t * d[u]) / r;
        n[v] = (pv + t * d[v]) / r;
        keep(RayHit{t, n});
      }
    }
  }
  Vec3 e = Vec3::Zero();
  e[axis] = h;
  keep(raySphere(c + e, r, o, d, maxFraction));
  keep(raySphere(c - e, r, o, d, maxFraction));
  return best;
}

// The rounded box as a union: the core grown by r along each axis (three boxes), and a capsule
// of radius r along each of the core's twelve edges. A ray from outside first meets the union
// where it first meets one of its pieces.
std::optional<RayHit> rayRoundedBox(const Vec3& h, double r, const Vec3& o, const Vec3& d, double maxFraction) {
  std::optional<RayHit> best;
  const auto keep = [&](const std::optional<RayHit>& hit) {
    if (hit && (!best || hit->fraction < best->fraction)) best = hit;
  };
  for (int i = 0; i < 3; ++i) {
    Vec3 grown = h;
    grown[i] += r;
    keep(rayBox(Vec3::Zero(), grown, o, d, maxFraction));
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const double su : {-1.0, 1.0}) {
      for (const double sv : {-1.0, 1.0}) {
        Vec3 c = Vec3::Zero();
        c[u] = su * h[u];
        c[v] = sv * h[v];
        keep(rayCapsule(c, axis, h[axis], r, o, d, maxFraction));
      }
    }
  }
  return best;
}

// GJK ray cast (van den Bergen 2004, "Ray Casting against General Convex Objects"): x moves
// along the ray to each support plane that separates it from the hull, until the simplex of
// x - p over support points p closes on x; origin outside.
std::optional<RayHit> rayHull(const Shape& shape, const Vec3& o, const Vec3& d, double maxFraction) {
  const ShapeSupport hull(shape);
  double fraction = 0.0;
  Vec3 x = o, normal = Vec3::Zero();
  Vec3 v = x - hull.anyPoint();
  GjkSimplex s;
  std::array<double, 4> weights{};
  for (int i = 0; i < kRayIterations && v.squaredNorm() > kGjkDistanceTolerance * kGjkDistanceTolerance; ++i) {
    const Vec3 p = hull.support(v);
    const Vec3 w = x - p;
    if (v.dot(w) > 0.0) {
      if (v.dot(d) >= 0.0) return std::nullopt;  // beyond a support plane and not closing on it
      fraction -= v.dot(w) / v.dot(d);
      if (fraction > maxFraction) return std::nullopt;
      x = o + fraction * d;
      normal = v;
    }
    if (s.size == 4) break;  // rounding: a full simplex that does not hold x
    s.points[s.size++] = {w, p, Vec3::Zero()};
    for (int k = 0; k < s.size; ++k) s.points[k].w = x - s.points[k].a;
    v = closestToOrigin(s, weights);
  }
  if (normal.squaredNorm() == 0.0) return std::nullopt;  // never advanced: origin inside (handled)
  return RayHit{fraction, normal.normalized()};
}

}  // namespace

ShapeDistance signedDistance(const Shape& shape, const Vec3& local) {
  refuseMesh(shape, "signedDistance");
  if (shape.isRound()) {
    const auto [distance, normal] = shape.roundDistance(local);
    return {distance, normal};
  }
  if (shape.type == ShapeType::Box) return boxDistance(shape.halfExtents, local);
  return hullDistance(shape, local);
}

std::optional<RayHit> rayCast(const Shape& shape, const Vec3& origin, const Vec3& direction, double maxFraction) {
  refuseMesh(shape, "rayCast");
  if (!(direction.squaredNorm() > 0.0) || !(maxFraction >= 0.0)) return std::nullopt;
  const ShapeDistance start = signedDistance(shape, origin);
  if (start.distance <= 0.0) return RayHit{0.0, start.normal};
  switch (shape.type) {
    case ShapeType::Sphere: return raySphere(Vec3::Zero(), shape.radius, origin, direction, maxFraction);
    case ShapeType::Capsule: return rayCapsule(Vec3::Zero(), 1, shape.halfLength, shape.radius, origin, direction, maxFraction);
    case ShapeType::Box: return rayBox(Vec3::Zero(), shape.halfExtents, origin, direction, maxFraction);
    case ShapeType::RoundedBox: return rayRoundedBox(shape.halfExtents, shape.radius, origin, direction, maxFraction);
    default: return rayHull(shape, origin, direction, maxFraction);
  }
}

}  // namespace rbsim

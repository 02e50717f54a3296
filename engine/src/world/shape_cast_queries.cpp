// One body's or plane's answer to a swept shape and to an overlap (world/body_queries.h): GJK on
// the cores of the two convex shapes (a sphere's centre, a capsule's segment, a rounded box's core
// box, a box or hull itself), their radii subtracted, as continuous_collision.cpp measures gaps;
// a mesh body by each of its triangles, whose core is itself.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "collision/narrowphase/gjk.h"
#include "world/body_queries.h"

namespace rbsim {

namespace {

// A cast that has not closed to kShapeCastTolerance by then reports where it got to, which is
// before the contact (each step ends on a separating plane) [iterations].
constexpr int kCastIterations = 64;

double queryCoreRadius(const Shape& shape) { return shape.isRound() ? shape.radius : 0.0; }

// A posed shape's core as GJK sees it, world frame: Shape::support less the radius along d (van
// den Bergen 2003, section 4.3.5), offset by `shift` (how far a cast has moved it).
class QueryCoreSupport final : public SupportMap {
 public:
  QueryCoreSupport(const Shape& shape, const Mat3& R, const Vec3& x) : shape_(shape), R_(R), x_(x) {}
  Vec3 support(const Vec3& d) const override {
    const Vec3 local = R_.transpose() * d;
    Vec3 p = shape_.support(local, &hint_);
    if (shape_.isRound()) p -= shape_.radius * local.normalized();
    return R_ * p + x_ + shift_;
  }
  Vec3 anyPoint() const override { return support(R_.col(0)); }
  void moveTo(const Vec3& shift) { shift_ = shift; }

 private:
  const Shape& shape_;
  Mat3 R_;
  Vec3 x_;
  Vec3 shift_ = Vec3::Zero();
  mutable unsigned hint_ = 0;
};

class QueryTriangleSupport final : public SupportMap {
 public:
  QueryTriangleSupport(const Vec3& a, const Vec3& b, const Vec3& c) : p_{a, b, c} {}
  Vec3 support(const Vec3& d) const override {
    const double da = d.dot(p_[0]), db = d.dot(p_[1]), dc = d.dot(p_[2]);
    return da >= db ? (da >= dc ? p_[0] : p_[2]) : (db >= dc ? p_[1] : p_[2]);
  }
  Vec3 anyPoint() const override { return p_[0]; }

 private:
  std::array<Vec3, 3> p_;
};

// Calls f(support, radius, child) for each convex part of the body the filter lets through: its
// shape, a compound's children, a mesh body's triangles.
template <typename F>
void forEachQueryPart(const RigidBody& body, const QueryFilter& filter, F f) {
  if (body.isCompound()) {
    for (std::size_t k = 0; k < body.children().size(); ++k) {
      const ChildShape& child = body.children()[k];
      if (!passes(child.filter, filter)) continue;
      const QueryCoreSupport core(child.shape, body.rotation() * child.orientation.toRotationMatrix(),
                             body.bodyToWorld(child.position));
      f(core, queryCoreRadius(child.shape), static_cast<int>(k));
    }
    return;
  }
  if (!passes(body.filter(), filter)) return;
  if (body.shape().type == ShapeType::Mesh) {
    const std::vector<Vec3>& v = body.worldVertices();
    for (const Triangle& t : body.mesh().triangles) f(QueryTriangleSupport(v[t[0]], v[t[1]], v[t[2]]), 0.0, -1);
    return;
  }
  f(QueryCoreSupport(body.shape(), body.rotation(), body.position()), queryCoreRadius(body.shape()), -1);
}

// Conservative advancement of the moving core along d against a fixed part (Mirtich 1996; van den
// Bergen 2004's GJK ray cast takes the same steps): at each step GJK gives the gap and the
// separating direction n; nothing of the moving shape can reach the fixed one before it has
// crossed the plane through the fixed part's closest point, gap / (-d . n) further on.
std::optional<QueryHit> advanceCast(QueryCoreSupport& moving, double movingRadius, const SupportMap& fixed, double fixedRadius,
                                const Vec3& d, double reach) {
  double s = 0.0;
  Vec3 lastNormal = -d, lastPoint = Vec3::Zero();  // the last step's, for rounding that lands a step inside
  for (int i = 0; i < kCastIterations; ++i) {
    moving.moveTo(s * d);
    const GjkResult g = gjk(moving, fixed);
    const double gap = g.overlap ? -1.0 : g.distance - movingRadius - fixedRadius;
    if (gap <= kShapeCastTolerance) {
      QueryHit hit;
      hit.distance = s;
      if (s == 0.0) {
        // Touching or overlapping where it starts: no way in to speak of, so against the motion.
        hit.normal = -d;
        hit.point = g.pointB;
      } else if (g.overlap || !(g.distance > 0.0)) {
        hit.normal = lastNormal;
        hit.point = lastPoint;
      } else {
        hit.normal = (g.pointA - g.pointB) / g.distance;  // from the fixed part towards the moving one
        hit.point = g.pointB + fixedRadius * hit.normal;
      }
      return hit;
    }
    const Vec3 n = (g.pointA - g.pointB) / g.distance;
    lastNormal = n;
    lastPoint = g.pointB + fixedRadius * n;
    const double closing = -d.dot(n);
    if (!(closing > 0.0)) return std::nullopt;  // moving along or away: the gap only grows
    s += gap / closing;
    if (s > reach) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<QueryHit> overlapBody(const RigidBody& body, const Shape& shape, const Mat3& R, const Vec3& x,
                                    const QueryFilter& filter) {
  const QueryCoreSupport query(shape, R, x);
  const double radius = queryCoreRadius(shape);
  std::optional<QueryHit> found;
  forEachQueryPart(body, filter, [&](const SupportMap& part, double partRadius, int child) {
    if (found) return;
    const GjkResult g = gjk(query, part);
    if (g.overlap || g.distance <= radius + partRadius) {
      found = QueryHit{};
      found->child = child;
      found->point = g.pointB;
      found->distance = 0.0;
    }
  });
  return found;
}

bool overlapsPlane(const Plane& plane, const Shape& shape, const Mat3& R, const Vec3& x) {
  const Vec3 lowest = R * shape.support(R.transpose() * -plane.normal) + x;
  return plane.signedDistance(lowest) <= 0.0;
}

std::optional<QueryHit> castBody(const RigidBody& body, const Shape& shape, const Mat3& R, const Vec3& x, const Vec3& d,
                                 double reach, const QueryFilter& filter) {
  QueryCoreSupport moving(shape, R, x);
  const double radius = queryCoreRadius(shape);
  std::optional<QueryHit> best;
  forEachQueryPart(body, filter, [&](const SupportMap& part, double partRadius, int child) {
    const double limit = best ? best->distance : reach;
    std::optional<QueryHit> hit = advanceCast(moving, radius, part, partRadius, d, limit);
    if (hit && (!best || hit->distance < best->distance)) {
      hit->child = child;
      best = hit;
    }
  });
  return best;
}

std::optional<QueryHit> castPlane(const Plane& plane, const Shape& shape, const Mat3& R, const Vec3& x, const Vec3& d,
                                  double reach) {
  const Vec3 lowest = R * shape.support(R.transpose() * -plane.normal) + x;
  const double height = plane.signedDistance(lowest);
  QueryHit hit;
  hit.isPlane = true;
  hit.normal = plane.normal;
  if (height <= 0.0) {
    hit.normal = -d;
    hit.point = lowest;
    return hit;
  }
  const double closing = -plane.normal.dot(d);
  if (!(closing > 0.0) || height / closing > reach) return std::nullopt;
  hit.distance = height / closing;
  hit.point = lowest + hit.distance * d;
  return hit;
}

}  // namespace rbsim

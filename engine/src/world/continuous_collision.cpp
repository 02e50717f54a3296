#include "world/continuous_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/narrowphase/gjk.h"

namespace rbsim {

namespace {

// Calls f(shape, R, x) for each convex part of the body at pose: its shape, or each child of a
// compound, with the part's rotation and origin in the world.
template <typename F>
void forEachPart(const SweptBody& body, const BodyState& pose, F f) {
  const Mat3 R = pose.orientation.toRotationMatrix();
  if (body.children == nullptr || body.children->empty()) {
    f(*body.shape, R, pose.position);
    return;
  }
  for (const ChildShape& c : *body.children) f(c.shape, Mat3(R * c.orientation.toRotationMatrix()), Vec3(R * c.position + pose.position));
}

// A round shape is its core grown by its radius (shapes/shape.h); the others are their own core.
double coreRadius(const Shape& shape) { return shape.isRound() ? shape.radius : 0.0; }

// A posed shape's core as GJK sees it, world frame: Shape::support less the radius along d, which
// is the core's support (a sphere's centre, a capsule's segment end, a rounded box's core corner).
// The gap between two shapes is then the cores' GJK distance less both radii, exact where GJK on
// the curved surface itself would only converge towards it (van den Bergen 2003, §4.3.5).
class PosedCoreSupport final : public SupportMap {
 public:
  PosedCoreSupport(const Shape& shape, const Mat3& R, const Vec3& x) : shape_(shape), R_(R), x_(x) {}
  Vec3 support(const Vec3& d) const override {
    const Vec3 local = R_.transpose() * d;
    Vec3 p = shape_.support(local, &hint_);
    if (shape_.isRound()) p -= shape_.radius * local.normalized();
    return R_ * p + x_;
  }
  Vec3 anyPoint() const override { return support(R_.col(0)); }

 private:
  const Shape& shape_;
  Mat3 R_;
  Vec3 x_;
  mutable unsigned hint_ = 0;
};

// The signed distance of the shape's lowest point to the plane: its support along -n, exact for
// every type (a sphere's lowest point is r below its centre, whatever its display mesh).
double planeDistance(const SweptBody& body, const Plane& plane, double s) {
  double lowest = std::numeric_limits<double>::infinity();
  forEachPart(body, poseAt(body, s), [&](const Shape& shape, const Mat3& R, const Vec3& x) {
    const Vec3 deepest = R * shape.support(R.transpose() * -plane.normal) + x;
    lowest = std::min(lowest, plane.signedDistance(deepest));
  });
  return lowest;
}

// The gap between two bodies' shapes (the least over their parts), or -1 when they overlap.
double pairDistance(const SweptBody& a, const SweptBody& b, double s) {
  const BodyState poseA = poseAt(a, s), poseB = poseAt(b, s);
  double least = std::numeric_limits<double>::infinity();
  forEachPart(a, poseA, [&](const Shape& shapeA, const Mat3& RA, const Vec3& xA) {
    forEachPart(b, poseB, [&](const Shape& shapeB, const Mat3& RB, const Vec3& xB) {
      const GjkResult g = gjk(PosedCoreSupport(shapeA, RA, xA), PosedCoreSupport(shapeB, RB, xB));
      const double gap = g.overlap ? -1.0 : g.distance - coreRadius(shapeA) - coreRadius(shapeB);
      least = std::min(least, gap < 0.0 ? -1.0 : gap);
    });
  });
  return least;
}

// Conservative advancement over s in [0, 1] for a distance function and a bound on its rate.
template <typename Distance>
std::optional<double> advance(Distance distance, double bound) {
  const double start = distance(0.0);
  if (start < 0.0) return std::nullopt;  // already penetrating: the narrow phase reports it
  if (!(bound > 0.0)) return std::nullopt;
  if (start <= kImpactSeparation) {
    // Touching at the start: an impact if the first kImpactSeparation of motion brings the
    // bodies closer (the end pose says nothing: it may lie beyond the obstacle), none if the
    // body moves away or along.
    return distance(std::min(1.0, kImpactSeparation / bound)) < start ? std::optional<double>(0.0) : std::nullopt;
  }
  double s = 0.0, d = start;
  for (int i = 0; i < kMaxAdvancementIterations; ++i) {
    s += (d - 0.5 * kImpactSeparation) / bound;  // aim inside the separation band, never past it
    if (s > 1.0) return std::nullopt;
    d = distance(s);
    if (d <= kImpactSeparation) return s;
  }
  return s;  // progress stalled within the cap: report where it got to, conservatively early
}

}  // namespace

BodyState poseAt(const SweptBody& body, double s) {
  BodyState pose = body.end;
  pose.position = body.start.position + s * (body.end.position - body.start.position);
  pose.orientation = body.start.orientation.slerp(s, body.end.orientation);
  return pose;
}

double motionBound(const SweptBody& body) {
  return (body.end.position - body.start.position).norm() +
         body.start.orientation.angularDistance(body.end.orientation) * body.radius;
}

Aabb boundsAt(const SweptBody& body, double s) {
  Aabb box;
  forEachPart(body, poseAt(body, s), [&](const Shape& shape, const Mat3& R, const Vec3& x) {
    const auto [lo, hi] = shape.worldBounds(R, x);
    box.grow(Aabb{lo, hi});
  });
  return box;
}

std::optional<double> timeOfImpact(const SweptBody& body, const Plane& plane) {
  return advance([&](double s) { return planeDistance(body, plane, s); }, motionBound(body));
}

std::optional<double> timeOfImpact(const SweptBody& a, const SweptBody& b) {
  return advance([&](double s) { return pairDistance(a, b, s); }, motionBound(a) + motionBound(b));
}

}  // namespace rbsim

#include "world/continuous_collision.h"

#include <algorithm>
#include <cmath>

#include "collision/narrowphase/convex_convex.h"

namespace rbsim {

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

std::vector<Vec3> worldVerticesAt(const SweptBody& body, double s) {
  const BodyState pose = poseAt(body, s);
  const Mat3 R = pose.orientation.toRotationMatrix();
  std::vector<Vec3> out;
  out.reserve(body.bodyVertices->size());
  for (const Vec3& p : *body.bodyVertices) out.push_back(R * p + pose.position);
  return out;
}

namespace {

double planeDistance(const SweptBody& body, const Plane& plane, double s) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : worldVerticesAt(body, s)) lowest = std::min(lowest, plane.signedDistance(p));
  return lowest;
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

std::optional<double> timeOfImpact(const SweptBody& body, const Plane& plane) {
  return advance([&](double s) { return planeDistance(body, plane, s); }, motionBound(body));
}

std::optional<double> timeOfImpact(const SweptBody& a, const SweptBody& b) {
  const auto distance = [&](double s) {
    const ConvexDistance d = convexDistance(worldVerticesAt(a, s), worldVerticesAt(b, s));
    return d.overlap ? -1.0 : d.distance;
  };
  return advance(distance, motionBound(a) + motionBound(b));
}

}  // namespace rbsim

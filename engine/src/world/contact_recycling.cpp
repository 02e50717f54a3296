#include "world/contact_recycling.h"

#include <algorithm>
#include <cmath>

namespace rbsim {

namespace {

// The part of the turn q about the unit axis n (the swing-twist decomposition: q = swing twist,
// twist = normalize(w, (v . n) n)), as a matrix; the identity when q is a half turn about an axis
// across n.
Mat3 twistAbout(const Vec3& n, const Quat& q) {
  const double along = q.vec().dot(n);
  const double norm = std::hypot(q.w(), along);
  if (norm == 0.0) return Mat3::Identity();
  const Quat twist(q.w() / norm, along / norm * n.x(), along / norm * n.y(), along / norm * n.z());
  return twist.toRotationMatrix();
}

}  // namespace

RecycleFrame recycleFrame(std::uint64_t key, const ContactManifold& manifold, const RecyclePose& a, const RecyclePose& b) {
  RecycleFrame f;
  f.key = key;
  f.normal = manifold.normal;
  f.count = manifold.count;
  const Mat3 RA = a.orientation.toRotationMatrix(), RB = b.orientation.toRotationMatrix();
  for (int i = 0; i < manifold.count; ++i) {
    const ContactPoint& p = manifold.points[i];
    f.localA[i] = RA.transpose() * (p.position - a.position);
    f.localB[i] = RB.transpose() * (p.position - b.position);
    f.armA[i] = p.position - a.position;
    f.armB[i] = p.position - b.position;
    f.base[i] = -p.depth;  // both bodies' copies of the point coincide when computed
    f.touching = f.touching || p.depth >= 0.0;
  }
  f.relativePosition = RA.transpose() * (b.position - a.position);
  f.orientationA = a.orientation;
  f.orientationB = b.orientation;
  return f;
}

std::optional<ContactManifold> recycledManifold(const RecycleFrame& frame, const RecyclePose& a, const RecyclePose& b,
                                                double distance, double nonTouching) {
  // cos(angle / 2) = |q_now . q_then| (either sign of a quaternion is the same turn).
  const double minCos = std::cos(0.5 * kRecycleMaxTurn);
  if (std::abs(a.orientation.dot(frame.orientationA)) < minCos || std::abs(b.orientation.dot(frame.orientationB)) < minCos) {
    return std::nullopt;
  }
  const Mat3 RA = a.orientation.toRotationMatrix(), RB = b.orientation.toRotationMatrix();
  const double tolerance = frame.touching ? distance : std::min(distance, nonTouching);
  const double moved = (RA.transpose() * (b.position - a.position) - frame.relativePosition).norm();
  // The relative turn since, q_r = (qA0^-1 qB0)^-1 (qA^-1 qB): a point r from a centre moves by at
  // most 2 |q_r.vec| r = 2 sin(angle / 2) r (Box3D bounds it the same way, per axis).
  const Quat turn = (frame.orientationA.conjugate() * frame.orientationB).conjugate() * (a.orientation.conjugate() * b.orientation);
  const double swept = 2.0 * turn.vec().norm() * std::max(a.radius, b.radius);
  if (!(moved + swept < tolerance)) return std::nullopt;
  // The arms turn with their bodies about the normal (a box carried round on a turntable) but not
  // with their tilt, which is what a kept arm is for.
  const Mat3 twistA = twistAbout(frame.normal, a.orientation * frame.orientationA.conjugate());
  const Mat3 twistB = twistAbout(frame.normal, b.orientation * frame.orientationB.conjugate());
  ContactManifold m;
  m.normal = frame.normal;
  m.count = frame.count;
  for (int i = 0; i < frame.count; ++i) {
    // The separation between the points both bodies carry; the impulses at the kept arms.
    const Vec3 pA = a.position + RA * frame.localA[i], pB = b.position + RB * frame.localB[i];
    const Vec3 anchorA = a.position + twistA * frame.armA[i], anchorB = b.position + twistB * frame.armB[i];
    m.points[i].position = 0.5 * (anchorA + anchorB);
    m.points[i].offset = anchorB - anchorA;
    m.points[i].depth = -(frame.base[i] + frame.normal.dot(pB - pA));
  }
  return m;
}

}  // namespace rbsim

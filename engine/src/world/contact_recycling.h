#pragma once
// Contact recycling (Box3D, src/physics_world.c, "contact recycling optimization", after
// persistent manifolds such as PhysX's): a pair of polyhedra whose relative pose has moved less
// than Settings::contactRecycleDistance since its manifold was computed keeps that manifold. Its
// normal stays where it was in the world, its points become material points of both bodies, and
// only the separations are brought up to date from the bodies' motion, as the soft step's
// substeps already do within a step (Box2D v3's contact_solver.c comment).
//
// Why it is on: a fresh manifold every step turns its normal with the reference face and moves its
// points with the clipping, and a column of 20 unit cubes on 30 Hz contacts (4 substeps) buckles
// under that; with the manifold kept it stands. Box3D's own column and its large pyramid fall
// without it (docs/speed.md, "Why Box3D stands"). It also saves the narrow phase's cost for every
// pair at rest.
//
// Round shapes are left out: a rolling ball's contact is never a material point of it, and a kept
// one would lift it by r (1 - cos angle) before the manifold was renewed.
#include <array>
#include <cstdint>
#include <optional>

#include "rbsim/collision/contact.h"
#include "rbsim/math/types.h"

namespace rbsim {

// A body's pose, for the recycling test (a plane's: at the origin, unrotated).
struct RecyclePose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  double radius = 0.0;  // farthest point of the body from its centre [m]; 0 for a plane
};

// What a manifold was computed with: enough to rebuild it at later poses.
struct RecycleFrame {
  std::uint64_t key = 0;  // CollisionPipeline::keptKey of the pair
  Vec3 normal = Vec3::UnitY();  // world frame, A towards B, as computed
  int count = 0;
  std::array<Vec3, kMaxManifoldPoints> localA{}, localB{};  // the points in each body's frame [m]
  // The points from each body's centre, world frame, when computed: the lever arms a recycled
  // manifold keeps. Box3D keeps its anchors so; turned with the bodies instead (material points),
  // a tilting box's contacts tilt with it and the column of 20 cubes at 30 Hz on 4 substeps
  // buckles as it does with fresh manifolds (measured) [m].
  std::array<Vec3, kMaxManifoldPoints> armA{}, armB{};
  // s - n . (pB - pA) when computed, so that s = base + n . (pB - pA) at any later pose [m].
  std::array<double, kMaxManifoldPoints> base{};
  Vec3 relativePosition = Vec3::Zero();  // B's centre in A's frame when computed [m]
  Quat orientationA = Quat::Identity(), orientationB = Quat::Identity();
  bool touching = false;  // a point was within the surfaces (depth >= 0) when computed
  std::uint32_t age = 0;  // steps since computed [steps]
};

// The frame of `manifold`, computed with the bodies at `a` and `b`.
RecycleFrame recycleFrame(std::uint64_t key, const ContactManifold& manifold, const RecyclePose& a, const RecyclePose& b);

// The manifold of `frame` at the poses now, or nothing when the pair has moved too far for it:
// B's centre more than `distance` from where it was in A's frame (or, for a pair that was not
// touching, more than `nonTouching`), less what the relative rotation sweeps the farther body's
// points through, or either body turned by more than kRecycleMaxTurn since.
std::optional<ContactManifold> recycledManifold(const RecycleFrame& frame, const RecyclePose& a, const RecyclePose& b,
                                                double distance, double nonTouching);

// Beyond this turn of either body [rad] a world-fixed normal is renewed whatever the relative pose
// (Box3D's B3_CONTACT_RECYCLE_ANGULAR_DISTANCE, cos^2 of half of it, 0.9924: 10 degrees).
inline constexpr double kRecycleMaxTurn = 10.0 * 3.14159265358979323846 / 180.0;  // [rad]

}  // namespace rbsim

#pragma once
// Queries of a World's geometry for views and checks that the step does not need: the broad
// phase's brute-force reference and the distance between two bodies. They go through the World,
// so their callers need none of the collision module's private headers (docs/architecture.md).
#include <vector>

#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/math/types.h"
#include "rbsim/body/body_id.h"

namespace rbsim {

class World;

// Every overlapping pair of the boxes the last step's broad phase was given (static-static pairs
// excluded, as sweep and prune excludes them), found by testing all n (n - 1) / 2 pairs: the
// reference World::collision().candidatePairs() must equal (sorted, a < b).
std::vector<ProxyPair> bruteForcePairs(const World& world);

struct BodyDistance {
  bool overlap = false;
  double distance = 0.0;       // [m], 0 when overlapping
  Vec3 pointA = Vec3::Zero();  // closest point on body a [m]
  Vec3 pointB = Vec3::Zero();  // closest point on body b [m]
};

// The distance between the convex hulls of two bodies' world vertices and their closest points
// (GJK, collision/narrowphase/convex_convex.h). Throws std::invalid_argument on a stale id.
BodyDistance bodyDistance(const World& world, BodyId a, BodyId b);

}  // namespace rbsim

#pragma once
// Queries of a World's geometry for views and checks that the step does not need: what the last
// broad phase saw and found, its brute-force reference, and the distance between two bodies. They
// go through the World, so their callers need none of the collision module's private headers
// (docs/architecture.md).
#include <cstddef>
#include <utility>
#include <vector>

#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/collision/impact.h"
#include "rbsim/math/types.h"
#include "rbsim/body/body_id.h"

namespace rbsim {

class World;

// The candidate pairs of the last broad phase (sweep and prune; proxy ids are body indices until
// a body is destroyed), and per body the AABB it was given, inflated by the contact margin.
const std::vector<ProxyPair>& candidatePairs(const World& world);
const std::vector<Aabb>& broadPhaseBoxes(const World& world);
// The bodies continuous collision stopped in the last step.
const std::vector<Impact>& impacts(const World& world);

// Every overlapping pair of the boxes the last step's broad phase was given (static-static pairs
// excluded, as sweep and prune excludes them), found by testing all n (n - 1) / 2 pairs: the
// reference candidatePairs must equal (sorted, a < b).
std::vector<ProxyPair> bruteForcePairs(const World& world);

// The bodies awake now.
std::size_t awakeCount(const World& world);
// The scripted forces acting on `body` during the step that starts at time t, in world frame:
// (point, force), as stage AccumulateForces applies them (renderers draw them as arrows).
// Throws std::invalid_argument on a stale id.
std::vector<std::pair<Vec3, Vec3>> activeForces(const World& world, BodyId body, double t);

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

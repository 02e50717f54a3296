#pragma once
// Queries of a World's geometry for views and checks that the step does not need: what the last
// broad phase saw and found, its brute-force reference, and the distance between two bodies. They
// go through the World, so their callers need none of the collision module's private headers
// (docs/architecture.md).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/body/material.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/collision/impact.h"
#include "rbsim/math/types.h"
#include "rbsim/world/scripts.h"
#include "rbsim/world/world.h"

namespace rbsim {

// Plain reads of a World's per-body and per-step data, free functions rather than members (the
// World's class keeps its core: docs/architecture.md, "The World's surface").
// The material a body was given (or setBodyMaterial set); throws std::invalid_argument on a stale
// id. A plane's, by its index in World::planes() (std::out_of_range past the last).
const Material& bodyMaterial(const World& world, BodyId body);
const Material& planeMaterial(const World& world, std::size_t plane);
// Per body: its solid for point queries (particles, soft-body nodes, surface samples).
const std::vector<BodySolid>& bodySolids(const World& world);
// The bodies that broke since the World began (stage BreakBodies), oldest first.
const std::vector<FractureEvent>& fractureEvents(const World& world);
const std::vector<ScriptedForce>& scriptedForces(const World& world);  // as World::addForce added them
// How many of World::contacts() the last narrow phase recycled (Settings::contactRecycleDistance).
std::size_t recycledContacts(const World& world);
// Changes whenever a body may have moved, appeared, gone or changed outside the scene queries'
// sight: step, addBody, destroyBodies, restore, setSettings, setBodyFilter and the non-const
// World::body(id). A new mutator of the bodies must bump it too. The queries rebuild their tree
// when it changed.
std::uint64_t geometryVersion(const World& world);

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

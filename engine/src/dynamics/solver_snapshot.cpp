// The contact solvers' part of a World snapshot (world/world_snapshot.h): what the next solve
// reads of the last one. A solve rebuilds its bodies, constraints and islands from the World, so
// what persists is the warm-start cache (Jolt's ContactConstraintManager::SaveState saves the
// same: the cached manifolds and their impulses), which bodies the last solve advanced, and the
// contact points it reported.
#include <algorithm>
#include <string>
#include <vector>

#include "dynamics/contact_solver.h"
#include "dynamics/pgs_solver.h"
#include "dynamics/soft_step_solver.h"
#include "math/byte_stream.h"

namespace rbsim {

namespace {

// The smallest a saved contact point can be [bytes]: its contact index, 12 doubles and a flag.
constexpr std::size_t kPointBytes = 8 + 12 * 8 + 1;

void savePoints(ByteWriter& out, const std::vector<SolvedContactPoint>& points) {
  out.count(points.size());
  for (const SolvedContactPoint& p : points) {
    out.u64(p.contact);
    out.vec3(p.position);
    out.vec3(p.normal);
    out.f64(p.depth);
    out.f64(p.normalImpulse);
    out.vec3(p.frictionImpulse);
    out.f64(p.approachVelocity);
    out.f64(p.normalVelocity);
    out.boolean(p.sticking);
  }
}

std::vector<SolvedContactPoint> loadPoints(ByteReader& in) {
  std::vector<SolvedContactPoint> points(in.count(kPointBytes, "contact points"));
  for (SolvedContactPoint& p : points) {
    p.contact = static_cast<std::size_t>(in.u64());
    p.position = in.vec3();
    p.normal = in.vec3();
    p.depth = in.f64();
    p.normalImpulse = in.f64();
    p.frictionImpulse = in.vec3();
    p.approachVelocity = in.f64();
    p.normalVelocity = in.f64();
    p.sticking = in.boolean();
  }
  return points;
}

int loadPointCount(ByteReader& in) {
  const std::uint32_t count = in.u32();
  if (count > static_cast<std::uint32_t>(kMaxManifoldPoints)) {
    in.fail("a cached manifold of " + std::to_string(count) + " points (expected at most " +
            std::to_string(kMaxManifoldPoints) + ")");
  }
  return static_cast<int>(count);
}

// The caches are looked up by key (binary search, a hash index): strictly ascending keys, whose
// body keys (contact_key.h pairKey: a plane's index or body A's key, then body B's) name living
// bodies, since a removal drops a body's warm starts by its key.
template <typename Cached>
void checkKeys(ByteReader& in, const std::vector<Cached>& cache, const std::vector<std::uint32_t>& bodyKeys) {
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 24) - 1;
  std::vector<char> living;
  for (const std::uint32_t key : bodyKeys) {
    if (key >= living.size()) living.resize(std::size_t{key} + 1, 0);
    living[key] = 1;
  }
  const auto lives = [&](std::uint64_t key) { return key < living.size() && living[key] != 0; };
  for (std::size_t i = 0; i < cache.size(); ++i) {
    if (i > 0 && !(cache[i - 1].key < cache[i].key)) in.fail("warm-start cache keys not strictly ascending");
    const bool plane = (cache[i].key >> 63) != 0;
    if (!lives(cache[i].key & kIndexMask) || (!plane && !lives((cache[i].key >> 24) & kIndexMask))) {
      in.fail("a warm-start cache key naming no body of the " + std::to_string(bodyKeys.size()));
    }
  }
}

// A snapshot before version 6 names a warm start's bodies by index: each becomes its body's key,
// the pair's order kept (as its contact names it), and the list is sorted by the new keys.
template <typename Cached>
void renameToKeys(ByteReader& in, std::vector<Cached>& cache, const std::vector<std::uint32_t>& bodyKeys) {
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 24) - 1;
  const auto keyOf = [&](std::uint64_t index) -> std::uint64_t {
    if (index >= bodyKeys.size()) in.fail("a warm-start cache key naming a body past the " + std::to_string(bodyKeys.size()));
    return bodyKeys[index];
  };
  for (Cached& c : cache) {
    const bool plane = (c.key >> 63) != 0;
    const std::uint64_t a = (c.key >> 24) & kIndexMask, b = c.key & kIndexMask;
    c.key = (c.key & ~((kIndexMask << 24) | kIndexMask)) | ((plane ? a : keyOf(a)) << 24) | keyOf(b);
  }
  std::sort(cache.begin(), cache.end(), [](const Cached& x, const Cached& y) { return x.key < y.key; });
}

}  // namespace

void ContactSolver::save(ByteWriter&) const {
  throw std::invalid_argument("World snapshot: this contact solver's warm starts have no saved form");
}

void ContactSolver::load(ByteReader& in, const std::vector<std::uint32_t>&, bool) { in.fail("this contact solver's warm starts have no saved form"); }

// A cached manifold's points past its count are never read, and the solvers leave them
// uninitialised: only the first `count` are written, so equal states give equal bytes.
void SoftStepSolver::save(ByteWriter& out) const {
  // The sleeping contacts' warm starts with the others, in one list sorted by key: read back into
  // cache_, contactsSlept keeps them apart again.
  std::vector<Cached> all = cache_;
  mergeAsleep(all);
  out.count(all.size());
  for (const Cached& c : all) {
    out.u64(c.key);
    out.u32(static_cast<std::uint32_t>(c.count));
    for (int k = 0; k < c.count; ++k) {
      out.vec3(c.localPoints[k]);
      out.f64(c.normalImpulses[k]);
      out.vec3(c.frictionImpulses[k]);
      out.boolean(c.sliding[k]);
    }
    out.boolean(c.sticking);
  }
  out.count(advancedList_.size());
  for (std::size_t body : advancedList_) out.u64(body);
  savePoints(out, points());
}

void SoftStepSolver::load(ByteReader& in, const std::vector<std::uint32_t>& bodyKeys, bool keyedByIndex) {
  const std::size_t bodies = bodyKeys.size();
  constexpr std::size_t kCachedBytes = 8 + 4 + 1;  // the least save writes for one: no points
  std::vector<Cached> cache(in.count(kCachedBytes, "cached manifolds"));
  for (Cached& c : cache) {
    c.key = in.u64();
    c.count = loadPointCount(in);
    for (int k = 0; k < c.count; ++k) {
      c.localPoints[k] = in.vec3();
      c.normalImpulses[k] = in.f64();
      c.frictionImpulses[k] = in.vec3();
      c.sliding[k] = in.boolean();
    }
    c.sticking = in.boolean();
  }
  if (keyedByIndex) renameToKeys(in, cache, bodyKeys);
  checkKeys(in, cache, bodyKeys);
  std::vector<std::size_t> advanced(in.count(8, "advanced bodies"));
  std::vector<char> flags(bodies, 0);
  for (std::size_t& body : advanced) {
    body = in.index(bodies, "advanced body");
    flags[body] = 1;
  }
  std::vector<SolvedContactPoint> points = loadPoints(in);
  forget();
  cache_ = std::move(cache);
  indexCache();
  advancedList_ = std::move(advanced);
  advanced_ = std::move(flags);
  solved_ = std::move(points);
  reported_ = true;
}

void PgsSolver::save(ByteWriter& out) const {
  out.count(cache_.size());
  for (const Cached& c : cache_) {
    out.u64(c.key);
    out.u32(static_cast<std::uint32_t>(c.count));
    for (int k = 0; k < c.count; ++k) {
      out.vec3(c.localPoints[k]);
      out.f64(c.normalImpulses[k]);
      out.vec3(c.pointFriction[k]);
      out.boolean(c.sliding[k]);
    }
    out.vec3(c.linearFriction);
    out.f64(c.twistFriction);
    out.boolean(c.sticking);
  }
  savePoints(out, solved_);
}

void PgsSolver::load(ByteReader& in, const std::vector<std::uint32_t>& bodyKeys, bool keyedByIndex) {
  constexpr std::size_t kCachedBytes = 8 + 4 + 4 * 8 + 1;  // the least save writes for one: no points
  std::vector<Cached> cache(in.count(kCachedBytes, "cached manifolds"));
  for (Cached& c : cache) {
    c.key = in.u64();
    c.count = loadPointCount(in);
    for (int k = 0; k < c.count; ++k) {
      c.localPoints[k] = in.vec3();
      c.normalImpulses[k] = in.f64();
      c.pointFriction[k] = in.vec3();
      c.sliding[k] = in.boolean();
    }
    c.linearFriction = in.vec3();
    c.twistFriction = in.f64();
    c.sticking = in.boolean();
  }
  if (keyedByIndex) renameToKeys(in, cache, bodyKeys);
  checkKeys(in, cache, bodyKeys);
  std::vector<SolvedContactPoint> points = loadPoints(in);
  forget();
  cache_ = std::move(cache);
  solved_ = std::move(points);
}

}  // namespace rbsim

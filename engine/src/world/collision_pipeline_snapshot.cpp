// The collision stages' part of a World snapshot (collision_pipeline.h save/load). Per-body
// measures (radius, thickness, grids, gaps) are the bodies' own and are rebuilt by addBody; what
// is saved is what the steps changed: the broad-phase ids and boxes, each body's reach and
// start, the contacts of the last narrow phase and the recycling frames kept for the next.
#include <string>
#include <utility>
#include <vector>

#include "math/byte_stream.h"
#include "world/collision_pipeline.h"

namespace rbsim {

namespace {

// The smallest saved forms [bytes], to bound counts by the bytes left (ByteReader::count).
constexpr std::size_t kContactBytes = 1 + 8 + 8 + 4 + 24 + 4 + 8;  // without points
constexpr std::size_t kFrameBytes = 8 + 24 + 4 + 24 + 64 + 1 + 4;  // without points
constexpr std::size_t kImpactBytes = 8 + 8 + 24 + 32;
constexpr std::size_t kBodyBytes = 4 + 8 + 48 + 104;

void saveBox(ByteWriter& out, const Aabb& box) {
  out.vec3(box.min);
  out.vec3(box.max);
}

Aabb loadBox(ByteReader& in) {
  Aabb box;
  box.min = in.vec3();
  box.max = in.vec3();
  if (!box.min.allFinite() || !box.max.allFinite() || (box.min.array() > box.max.array()).any()) {
    in.fail("a body's box not finite or empty");
  }
  return box;
}

void saveState(ByteWriter& out, const BodyState& s) {
  out.vec3(s.position);
  out.quat(s.orientation);
  out.vec3(s.linearMomentum);
  out.vec3(s.angularMomentum);
}

BodyState loadState(ByteReader& in) {
  BodyState s;
  s.position = in.vec3();
  s.orientation = in.quat();
  s.linearMomentum = in.vec3();
  s.angularMomentum = in.vec3();
  return s;
}

void saveContact(ByteWriter& out, const Contact& c) {
  out.u8(c.kind == Contact::Kind::PlaneBody ? 1 : 0);
  out.u64(c.a);
  out.u64(c.b);
  out.u32(c.part);
  out.vec3(c.manifold.normal);
  out.u32(static_cast<std::uint32_t>(c.manifold.count));
  for (int k = 0; k < c.manifold.count; ++k) {  // the points past the count are stale
    const ContactPoint& p = c.manifold.points[k];
    out.vec3(p.position);
    out.f64(p.depth);
    out.vec3(p.offset);
  }
  out.u32(c.childA);
  out.u32(c.childB);
}

std::uint16_t loadChild(ByteReader& in, const RigidBody* body) {
  const std::uint32_t child = in.u32();
  const std::size_t children = body && body->isCompound() ? body->children().size() : 1;
  if (child >= children) in.fail("a contact's child shape " + std::to_string(child) + " out of range");
  return static_cast<std::uint16_t>(child);
}

Contact loadContact(ByteReader& in, const std::vector<RigidBody>& bodies, std::size_t planes) {
  Contact c;
  const std::uint8_t kind = in.u8();
  if (kind > 1) in.fail("a contact of kind " + std::to_string(kind));
  c.kind = kind == 1 ? Contact::Kind::PlaneBody : Contact::Kind::BodyBody;
  c.a = in.index(c.kind == Contact::Kind::PlaneBody ? planes : bodies.size(), "contact side A");
  c.b = in.index(bodies.size(), "contact body B");
  const std::uint32_t part = in.u32();
  if (part > UINT16_MAX) in.fail("a contact part " + std::to_string(part));
  c.part = static_cast<std::uint16_t>(part);
  c.manifold.normal = in.vec3();
  const std::uint32_t count = in.u32();
  if (count > static_cast<std::uint32_t>(kMaxManifoldPoints)) in.fail("a manifold of " + std::to_string(count) + " points");
  c.manifold.count = static_cast<int>(count);
  for (int k = 0; k < c.manifold.count; ++k) {
    ContactPoint& p = c.manifold.points[k];
    p.position = in.vec3();
    p.depth = in.f64();
    p.offset = in.vec3();
  }
  c.childA = loadChild(in, c.kind == Contact::Kind::PlaneBody ? nullptr : &bodies[c.a]);
  c.childB = loadChild(in, &bodies[c.b]);
  return c;
}

void saveFrame(ByteWriter& out, const RecycleFrame& f) {
  out.u64(f.key);
  out.vec3(f.normal);
  out.u32(static_cast<std::uint32_t>(f.count));
  for (int k = 0; k < f.count; ++k) {  // those past the count are never read, and left uninitialised
    out.vec3(f.localA[k]);
    out.vec3(f.localB[k]);
    out.vec3(f.armA[k]);
    out.vec3(f.armB[k]);
    out.f64(f.base[k]);
  }
  out.vec3(f.relativePosition);
  out.quat(f.orientationA);
  out.quat(f.orientationB);
  out.boolean(f.touching);
  out.u32(f.age);
}

RecycleFrame loadFrame(ByteReader& in) {
  RecycleFrame f;
  f.key = in.u64();
  f.normal = in.vec3();
  const std::uint32_t count = in.u32();
  if (count > static_cast<std::uint32_t>(kMaxManifoldPoints)) in.fail("a recycling frame of " + std::to_string(count) + " points");
  f.count = static_cast<int>(count);
  for (int k = 0; k < f.count; ++k) {
    f.localA[k] = in.vec3();
    f.localB[k] = in.vec3();
    f.armA[k] = in.vec3();
    f.armB[k] = in.vec3();
    f.base[k] = in.f64();
  }
  f.relativePosition = in.vec3();
  f.orientationA = in.quat();
  f.orientationB = in.quat();
  f.touching = in.boolean();
  f.age = in.u32();
  return f;
}

void saveFrames(ByteWriter& out, const std::vector<RecycleFrame>& frames) {
  out.count(frames.size());
  for (const RecycleFrame& f : frames) saveFrame(out, f);
}

std::vector<RecycleFrame> loadFrames(ByteReader& in) {
  std::vector<RecycleFrame> frames(in.count(kFrameBytes, "recycling frames"));
  for (RecycleFrame& f : frames) f = loadFrame(in);
  return frames;
}

}  // namespace

void CollisionPipeline::save(ByteWriter& out) const {
  out.count(table_->proxies.size());
  for (std::size_t i = 0; i < table_->proxies.size(); ++i) {
    out.u32(table_->proxies[i]);
    out.f64(table_->reach[i]);
    saveBox(out, table_->boxes[i]);
    saveState(out, table_->start[i]);
  }
  out.count(bodyOfProxy_.size());  // one past the largest proxy id the broad phase handed out
  out.boolean(haveStart_);
  // This step's contacts, then the sleeping islands' (reported()): read back into contacts_, the
  // next narrow phase keeps the sleeping ones apart again (keepSleeping).
  const std::vector<Contact>& contacts = reported();
  out.count(contacts.size());
  for (const Contact& c : contacts) saveContact(out, c);
  saveFrames(out, keptPairFrames_);
  saveFrames(out, keptPlaneFrames_);
  recycle_.save(out);
  out.u64(recycledCount_);
  out.count(impacts_.size());
  for (const Impact& impact : impacts_) {
    out.u64(impact.body);
    out.f64(impact.fraction);
    out.vec3(impact.unstoppedPosition);
    out.quat(impact.unstoppedOrientation);
  }
}

void CollisionPipeline::load(ByteReader& in, std::size_t planes) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  const std::size_t n = in.count(kBodyBytes, "bodies in the collision stages");
  if (n != bodies.size() || n != table_->proxies.size()) {
    in.fail("collision stages of " + std::to_string(n) + " bodies for " + std::to_string(bodies.size()));
  }
  std::vector<ProxyId> proxies(n);
  std::vector<double> reach(n);
  std::vector<Aabb> boxes(n);
  std::vector<BodyState> start(n);
  for (std::size_t i = 0; i < n; ++i) {
    proxies[i] = in.u32();
    reach[i] = in.f64();
    boxes[i] = loadBox(in);
    start[i] = loadState(in);
  }
  // Every proxy belongs to one body: the ids are distinct and below the count handed out.
  const std::size_t capacity = in.count(0, "proxy ids");
  if (capacity > n + in.remaining()) in.fail("a broad phase of " + std::to_string(capacity) + " proxy ids");
  constexpr std::size_t kNoBody = SIZE_MAX;
  std::vector<std::size_t> bodyOfProxy(capacity, kNoBody);
  for (std::size_t i = 0; i < n; ++i) {
    if (proxies[i] >= capacity || bodyOfProxy[proxies[i]] != kNoBody) {
      in.fail("body " + std::to_string(i) + "'s proxy id " + std::to_string(proxies[i]) + " repeated or out of range");
    }
    bodyOfProxy[proxies[i]] = i;
  }
  const bool haveStart = in.boolean();
  std::vector<Contact> contacts(in.count(kContactBytes, "contacts"));
  for (Contact& c : contacts) c = loadContact(in, bodies, planes);
  std::vector<RecycleFrame> pairFrames = loadFrames(in);
  std::vector<RecycleFrame> planeFrames = loadFrames(in);
  KeyIndex recycle;
  recycle.load(in);
  if (recycle.maxIndex() >= static_cast<std::int64_t>(pairFrames.size() + planeFrames.size())) {
    in.fail("the recycling index names a frame past the " + std::to_string(pairFrames.size() + planeFrames.size()) + " kept");
  }
  const std::uint64_t recycledCount = in.u64();
  std::vector<Impact> impacts(in.count(kImpactBytes, "impacts"));
  for (Impact& impact : impacts) {
    impact.body = in.index(n, "impact body");
    impact.fraction = in.f64();
    impact.unstoppedPosition = in.vec3();
    impact.unstoppedOrientation = in.quat();
  }

  // The broad phase afresh with the same ids: a fresh pool hands out 0, 1, ... in order, and one
  // released frees its id for the next add, smallest first, as the saved pool's would.
  auto broad = std::make_unique<SplitBroadPhase>(settings_.broadPhase);
  const Aabb unused{Vec3::Zero(), Vec3::Zero()};
  for (std::size_t id = 0; id < capacity; ++id) {
    const std::size_t body = bodyOfProxy[id];
    broad->add(body == kNoBody ? unused : boxes[body]);
  }
  for (std::size_t id = 0; id < capacity; ++id) {
    if (bodyOfProxy[id] == kNoBody) broad->remove(static_cast<ProxyId>(id));
  }
  std::vector<ProxyId> awake;
  for (std::size_t i = 0; i < n; ++i) {
    if (bodies[i].awake()) awake.push_back(proxies[i]);
  }
  broad->update(awake);
  for (std::size_t& body : bodyOfProxy) body = body == kNoBody ? 0 : body;

  broad_ = std::move(broad);
  table_->proxies = std::move(proxies);
  bodyOfProxy_ = std::move(bodyOfProxy);
  table_->reach = std::move(reach);
  table_->boxes = std::move(boxes);
  table_->start = std::move(start);
  table_->fast.assign(n, 0);
  haveStart_ = haveStart;
  contacts_ = std::move(contacts);
  sleeping_.clear();
  sleptNow_.clear();
  fastList_.clear();
  reportedStale_ = true;
  keptPairFrames_ = std::move(pairFrames);
  keptPlaneFrames_ = std::move(planeFrames);
  recycle_ = std::move(recycle);
  recycledCount_ = static_cast<std::size_t>(recycledCount);
  impacts_ = std::move(impacts);
}

}  // namespace rbsim

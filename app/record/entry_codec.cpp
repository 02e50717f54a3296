#include "record/entry_codec.h"

#include <cmath>
#include <cstring>
#include <utility>

#include "rbsim/world/systems.h"

namespace rbsim::app {

namespace {

// Bytes of one body, particle, soft-body node and 2D body in an entry (entry_codec.h): x, q, P, L
// and the awake byte; x, v, 1/m, age, lifetime, colour (3 floats) and size; x and v; x, theta, P, L.
constexpr std::size_t kBodyEntryBytes = 13 * sizeof(double) + 1;
constexpr std::size_t kParticleEntryBytes = 9 * sizeof(double) + 4 * sizeof(float);
constexpr std::size_t kSoftNodeEntryBytes = 6 * sizeof(double);
constexpr std::size_t kPlanarBodyEntryBytes = 6 * sizeof(double);
constexpr std::size_t kRotationEntryBytes = 9 * sizeof(double);  // a body's R, with kOwnRotation

template <typename T>
void append(std::vector<std::uint8_t>& out, const T& value) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

void appendVec(std::vector<std::uint8_t>& out, const Vec3& v) {
  for (int i = 0; i < 3; ++i) append(out, v[i]);
}

// Reads an entry front to back; fail when it runs past its end.
struct Cursor {
  const std::vector<std::uint8_t>& entry;
  std::size_t at;
  const EntryFail& fail;
  template <typename T>
  void get(T& value) {
    if (sizeof value > entry.size() - at) fail("an entry runs past its end: the file is damaged");
    std::memcpy(&value, entry.data() + at, sizeof value);
    at += sizeof value;
  }
  void getVec(Vec3& v) {
    for (int i = 0; i < 3; ++i) get(v[i]);
  }
};

}  // namespace

void appendEntry(std::vector<std::uint8_t>& out, std::size_t world, const World& state,
                 const std::vector<std::uint8_t>* bodySet) {
  append(out, static_cast<std::uint16_t>(world | (bodySet ? kBodySetFlag : 0)));
  if (bodySet) {
    append(out, static_cast<std::uint64_t>(bodySet->size()));
    out.insert(out.end(), bodySet->begin(), bodySet->end());
  }
  append(out, state.stepCount());
  append(out, static_cast<std::uint32_t>(state.bodies().size()));
  for (const RigidBody& b : state.bodies()) {
    const BodyState& s = b.state();
    appendVec(out, s.position);
    for (const double c : {s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z()}) append(out, c);
    appendVec(out, s.linearMomentum);
    appendVec(out, s.angularMomentum);
    // R as a replay's setState would make it from q, or R itself (RigidBody::updateDerived).
    const Mat3 fromQ = s.orientation.toRotationMatrix();
    const bool own = std::memcmp(fromQ.data(), b.rotation().data(), sizeof(double) * 9) != 0;
    append(out, static_cast<std::uint8_t>((b.awake() ? kAwake : 0) | (own ? kOwnRotation : 0)));
    if (own) {
      for (int k = 0; k < 9; ++k) append(out, b.rotation().data()[k]);
    }
  }
  append(out, static_cast<std::uint32_t>(particleSystems(state).size()));
  for (const ParticleSystem& system : particleSystems(state)) {
    const ParticleStore& p = system.particles();
    append(out, static_cast<std::uint32_t>(p.count()));
    for (std::size_t i = 0; i < p.count(); ++i) {
      appendVec(out, p.position[i]);
      appendVec(out, p.velocity[i]);
      append(out, p.inverseMass[i]);
      append(out, p.age[i]);
      append(out, p.lifetime[i]);
      for (int c = 0; c < 3; ++c) append(out, p.color[i][c]);
      append(out, p.size[i]);
    }
  }
  append(out, static_cast<std::uint32_t>(softBodies(state).size()));
  for (const SoftBody& soft : softBodies(state)) {
    append(out, static_cast<std::uint32_t>(soft.positions().size()));
    for (const Vec3& x : soft.positions()) appendVec(out, x);
    for (const Vec3& v : soft.velocities()) appendVec(out, v);
  }
  const PlanarWorld* planar = planarWorld(state);
  append(out, static_cast<std::uint32_t>(planar ? planar->bodies().size() : 0));
  if (planar) {
    for (const PlanarBody& b : planar->bodies()) {
      const PlanarState& s = b.state();
      for (const double value : {s.position.x(), s.position.y(), s.angle, s.linearMomentum.x(), s.linearMomentum.y(),
                                 s.angularMomentum}) {
        append(out, value);
      }
    }
  }
}

std::size_t entryLength(const std::uint8_t* data, std::size_t size, const EntryFail& fail) {
  std::size_t at = 0;
  const auto skip = [&](std::uint64_t bytes) {
    if (bytes > size - at) fail("an entry runs past its block: the file is damaged");
    at += static_cast<std::size_t>(bytes);
  };
  const auto read = [&](auto& value) {
    skip(sizeof value);
    std::memcpy(&value, data + at - sizeof value, sizeof value);
  };
  const auto count = [&] {
    std::uint32_t n = 0;
    read(n);
    return std::uint64_t{n};
  };
  std::uint16_t world = 0;
  read(world);
  if ((world & kBodySetFlag) != 0) {
    std::uint64_t snapshot = 0;
    read(snapshot);
    skip(snapshot);
  }
  skip(sizeof(std::uint64_t));  // step
  for (std::uint64_t bodies = count(), i = 0; i < bodies; ++i) {
    skip(kBodyEntryBytes);
    if ((data[at - 1] & kOwnRotation) != 0) skip(kRotationEntryBytes);
  }
  for (std::uint64_t systems = count(), i = 0; i < systems; ++i) skip(count() * kParticleEntryBytes);
  for (std::uint64_t softBodies = count(), i = 0; i < softBodies; ++i) skip(count() * kSoftNodeEntryBytes);
  skip(count() * kPlanarBodyEntryBytes);
  return at;
}

EntryParts entryParts(const std::vector<std::uint8_t>& entry, const EntryFail& fail) {
  Cursor in{entry, 0, fail};
  EntryParts parts;
  in.get(parts.world);
  const bool bodySet = (parts.world & kBodySetFlag) != 0;
  parts.world = static_cast<std::uint16_t>(parts.world & ~kBodySetFlag);
  if (bodySet) {
    std::uint64_t bytes = 0;
    in.get(bytes);
    if (bytes > entry.size() - in.at) fail("an entry's World snapshot runs past its end: the file is damaged");
    parts.snapshot = entry.data() + in.at;
    parts.snapshotBytes = static_cast<std::size_t>(bytes);
    in.at += parts.snapshotBytes;
  }
  parts.stateOffset = in.at;
  return parts;
}

void restoreState(const std::vector<std::uint8_t>& entry, const EntryParts& parts, std::uint64_t number,
                  bool nextStep, World& world, const EntryFail& fail) {
  Cursor in{entry, parts.stateOffset, fail};
  const std::string which = "entry " + std::to_string(number);
  std::uint64_t step = 0;
  std::uint32_t bodies = 0;
  in.get(step);
  in.get(bodies);
  if ((nextStep && step != world.stepCount() + 1) || bodies != world.bodies().size()) {
    fail(which + " is step " + std::to_string(step) + " of world " + std::to_string(parts.world) + " with " +
         std::to_string(bodies) + " bodies; the scene expects step " + std::to_string(world.stepCount() + 1) +
         " with " + std::to_string(world.bodies().size()) + ": the recording does not belong to these scenes");
  }
  // Scratch kept between entries: a replay restores one every step.
  thread_local std::vector<BodyState> states;
  thread_local std::vector<char> awakeFlags;
  thread_local std::vector<std::pair<std::uint32_t, Mat3>> rotations;  // bodies with their own R
  states.resize(bodies);
  awakeFlags.resize(bodies);
  rotations.clear();
  for (std::uint32_t i = 0; i < bodies; ++i) {
    BodyState& s = states[i];
    in.getVec(s.position);
    double q[4];
    for (double& c : q) in.get(c);
    s.orientation = Quat(q[0], q[1], q[2], q[3]);
    in.getVec(s.linearMomentum);
    in.getVec(s.angularMomentum);
    std::uint8_t flags = 0;
    in.get(flags);
    awakeFlags[i] = static_cast<char>(flags & kAwake);
    if ((flags & kOwnRotation) != 0) {
      Mat3 rotation;
      for (int k = 0; k < 9; ++k) in.get(rotation.data()[k]);
      if (!rotation.allFinite()) fail(which + ": body " + std::to_string(i) + "'s rotation matrix is not finite");
      rotations.emplace_back(i, rotation);
    }
    // Validated as a scene's values are: a damaged or forged entry must not reach the World.
    if (!s.position.allFinite() || !s.linearMomentum.allFinite() || !s.angularMomentum.allFinite() ||
        !s.orientation.coeffs().allFinite()) {
      fail(which + ": body " + std::to_string(i) + "'s state is not finite");
    }
    if (std::abs(s.orientation.norm() - 1.0) > kRotationTolerance) {
      fail(which + ": body " + std::to_string(i) + "'s orientation is not a unit quaternion (|q| = " +
           std::to_string(s.orientation.norm()) + ")");
    }
    if ((flags & ~(kAwake | kOwnRotation)) != 0) fail(which + ": body " + std::to_string(i) + "'s flags are " + std::to_string(flags));
  }
  world.restore(step, states, awakeFlags);
  for (const auto& [i, rotation] : rotations) world.body(world.idAt(i)).setState(states[i], rotation);
  std::uint32_t systems = 0;
  in.get(systems);
  if (systems != particleSystems(static_cast<const World&>(world)).size()) {
    fail(which + ": its particle systems do not match the scene's");
  }
  for (std::size_t k = 0; k < systems; ++k) {
    ParticleStore& p = particleSystems(world)[k].particles();
    std::uint32_t count = 0;
    in.get(count);
    if (count > p.capacity()) fail(which + " holds more particles than the scene's system can");
    p.setCount(count);
    for (std::size_t i = 0; i < count; ++i) {
      in.getVec(p.position[i]);
      in.getVec(p.velocity[i]);
      in.get(p.inverseMass[i]);
      in.get(p.age[i]);
      in.get(p.lifetime[i]);
      for (int c = 0; c < 3; ++c) in.get(p.color[i][c]);
      in.get(p.size[i]);
      // A lifetime may be infinite (ParticleStore's kImmortal), never NaN.
      if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !std::isfinite(p.inverseMass[i]) ||
          !std::isfinite(p.age[i]) || std::isnan(p.lifetime[i]) || !std::isfinite(p.size[i])) {
        fail(which + ": particle " + std::to_string(i) + " is not finite");
      }
    }
  }
  std::uint32_t softCount = 0;
  in.get(softCount);
  if (softCount != softBodies(static_cast<const World&>(world)).size()) fail(which + ": its soft bodies do not match the scene's");
  for (std::size_t k = 0; k < softCount; ++k) {
    SoftBody& soft = softBodies(world)[k];
    std::uint32_t nodes = 0;
    in.get(nodes);
    if (nodes != soft.positions().size()) fail(which + ": its soft body nodes do not match the scene's");
    for (Vec3& x : soft.positions()) in.getVec(x);
    for (Vec3& v : soft.velocities()) in.getVec(v);
    for (std::size_t n = 0; n < nodes; ++n) {
      if (!soft.positions()[n].allFinite() || !soft.velocities()[n].allFinite()) {
        fail(which + ": soft body node " + std::to_string(n) + " is not finite");
      }
    }
  }
  std::uint32_t planarCount = 0;
  in.get(planarCount);
  PlanarWorld* planar = planarWorld(world);
  if (planarCount != (planar ? planar->bodies().size() : 0)) fail(which + ": its 2D bodies do not match the scene's");
  for (std::uint32_t i = 0; i < planarCount; ++i) {
    PlanarState s;
    in.get(s.position.x());
    in.get(s.position.y());
    in.get(s.angle);
    in.get(s.linearMomentum.x());
    in.get(s.linearMomentum.y());
    in.get(s.angularMomentum);
    if (!s.position.allFinite() || !std::isfinite(s.angle) || !s.linearMomentum.allFinite() || !std::isfinite(s.angularMomentum)) {
      fail(which + ": 2D body " + std::to_string(i) + "'s state is not finite");
    }
    planar->bodies()[i].state() = s;
  }
  if (in.at != entry.size()) fail(which + " has " + std::to_string(entry.size() - in.at) + " bytes after its state: the file is damaged");
}

}  // namespace rbsim::app

#pragma once
// The plain records of a World snapshot (world/world_snapshot.h), written and read field by
// field (snapshot_parts.cpp): settings, ids, materials, planes, scripts, springs, joints, pose
// events, kinematic motions. Readers check enums and counts; ids are checked by the World reader
// once its id table is read.
#include <cstdint>

#include "math/byte_stream.h"
#include "rbsim/body/material.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/settings/settings.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/shapes/plane.h"
#include "rbsim/world/kinematic_motion.h"
#include "rbsim/world/scripts.h"
#include "rbsim/world/spring.h"

namespace rbsim::snapshot {

void write(ByteWriter& out, const Settings& s);
Settings readSettings(ByteReader& in);
void write(ByteWriter& out, const BodyId& id);
BodyId readId(ByteReader& in);
void write(ByteWriter& out, const Material& m);
Material readMaterial(ByteReader& in);
void write(ByteWriter& out, const CollisionFilter& f);
CollisionFilter readFilter(ByteReader& in);
void write(ByteWriter& out, const Aabb& box);
Aabb readAabb(ByteReader& in);
void write(ByteWriter& out, const ScriptedForce& f);
ScriptedForce readForce(ByteReader& in);
void write(ByteWriter& out, const Spring& s);
Spring readSpring(ByteReader& in);
// A joint with its bodies' indices (the file keeps them beside the ids, as when Joint held both;
// kWorldInFile for the world's side).
inline constexpr std::uint64_t kWorldInFile = UINT64_MAX;
void write(ByteWriter& out, const Joint& j, std::uint64_t indexA, std::uint64_t indexB);
Joint readJoint(ByteReader& in, std::uint64_t& indexA, std::uint64_t& indexB);
void write(ByteWriter& out, const PoseEvent& e);
PoseEvent readPoseEvent(ByteReader& in);
void write(ByteWriter& out, const KinematicMotion& m);
KinematicMotion readMotion(ByteReader& in);

// An enum stored as a u32, checked against its number of values.
template <typename E>
E readEnum(ByteReader& in, std::uint32_t values, const char* what) {
  const std::uint32_t v = in.u32();
  if (v >= values) in.fail(std::string(what) + " " + std::to_string(v) + " (expected < " + std::to_string(values) + ")");
  return static_cast<E>(v);
}
template <typename E>
void writeEnum(ByteWriter& out, E value) {
  out.u32(static_cast<std::uint32_t>(value));
}

}  // namespace rbsim::snapshot

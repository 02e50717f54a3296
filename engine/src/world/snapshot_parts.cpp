// Field by field, in declaration order (snapshot_parts.h). A field added to one of these structs
// must be added here and kWorldSnapshotVersion raised.
#include "world/snapshot_parts.h"

#include <optional>
#include <string>

#include "rbsim/integrate/integrator.h"

namespace rbsim::snapshot {

namespace {

template <typename T, typename Write>
void writeOptional(ByteWriter& out, const std::optional<T>& value, Write write) {
  out.boolean(value.has_value());
  if (value) write(*value);
}

}  // namespace

void write(ByteWriter& out, const Settings& s) {
  out.vec3(s.gravity);
  out.f64(s.timeStep);
  writeEnum(out, s.integrator);
  writeEnum(out, s.inertia);
  out.boolean(s.driftCorrection);
  out.boolean(s.allowSleep);
  out.f64(s.sleepLinearSpeed);
  out.f64(s.sleepAngularSpeed);
  out.f64(s.timeToSleep);
  out.boolean(s.detectCollisions);
  writeEnum(out, s.broadPhase);
  out.f64(s.contactMargin);
  out.f64(s.contactRecycleDistance);
  out.boolean(s.continuousCollision);
  out.f64(s.ccdMotionFraction);
  out.boolean(s.logQueries);
  out.u64(s.queryLogCapacity);
  out.boolean(s.respondToContacts);
  writeEnum(out, s.solver);
  out.i64(s.substeps);
  out.f64(s.contactHertz);
  out.f64(s.contactDampingRatio);
  out.f64(s.contactPushSpeed);
  writeEnum(out, s.friction);
  writeEnum(out, s.meshContact);
  out.i64(s.velocityIterations);
  out.i64(s.positionIterations);
  out.f64(s.restitutionThreshold);
  out.f64(s.contactSlop);
  out.f64(s.positionCorrection);
  out.boolean(s.warmStarting);
  out.f64(s.warmStartDistance);
  out.i64(s.threads);
  out.boolean(s.skipIdleStages);
}

Settings readSettings(ByteReader& in) {
  // An int read back from 64 bits; checkSettings then checks its range.
  const auto readInt = [&](const char* what) {
    const std::int64_t v = in.i64();
    if (v < INT32_MIN || v > INT32_MAX) in.fail(std::string("settings ") + what + " " + std::to_string(v));
    return static_cast<int>(v);
  };
  Settings s;
  s.gravity = in.vec3();
  s.timeStep = in.f64();
  s.integrator = readEnum<Integrator>(in, static_cast<std::uint32_t>(integratorNames().size()), "integrator");
  s.inertia = readEnum<InertiaMethod>(in, 2, "inertia method");
  s.driftCorrection = in.boolean();
  s.allowSleep = in.boolean();
  s.sleepLinearSpeed = in.f64();
  s.sleepAngularSpeed = in.f64();
  s.timeToSleep = in.f64();
  s.detectCollisions = in.boolean();
  s.broadPhase = readEnum<Settings::BroadPhaseMethod>(in, 2, "broad phase");
  s.contactMargin = in.f64();
  s.contactRecycleDistance = in.f64();
  s.continuousCollision = in.boolean();
  s.ccdMotionFraction = in.f64();
  s.logQueries = in.boolean();
  s.queryLogCapacity = static_cast<std::size_t>(in.u64());
  s.respondToContacts = in.boolean();
  s.solver = readEnum<Settings::ContactSolverMethod>(in, 3, "solver");
  s.substeps = readInt("substeps");
  s.contactHertz = in.f64();
  s.contactDampingRatio = in.f64();
  s.contactPushSpeed = in.f64();
  s.friction = readEnum<Settings::FrictionModel>(in, 2, "friction model");
  s.meshContact = readEnum<Settings::MeshContact>(in, 2, "mesh contact");
  s.velocityIterations = readInt("velocity iterations");
  s.positionIterations = readInt("position iterations");
  s.restitutionThreshold = in.f64();
  s.contactSlop = in.f64();
  s.positionCorrection = in.f64();
  s.warmStarting = in.boolean();
  s.warmStartDistance = in.f64();
  s.threads = readInt("threads");
  s.skipIdleStages = in.boolean();
  if (const SettingsProblem problem = checkSettings(s)) in.fail("settings: " + problem.message());
  return s;
}

void write(ByteWriter& out, const BodyId& id) {
  out.u32(id.slot);
  out.u32(id.generation);
}

BodyId readId(ByteReader& in) {
  BodyId id;
  id.slot = in.u32();
  id.generation = in.u32();
  return id;
}

void write(ByteWriter& out, const Material& m) {
  out.f64(m.restitution);
  out.f64(m.staticFriction);
  out.f64(m.kineticFriction);
}

Material readMaterial(ByteReader& in) {
  Material m;
  m.restitution = in.f64();
  m.staticFriction = in.f64();
  m.kineticFriction = in.f64();
  const std::string problem = checkMaterial(m);
  if (!problem.empty()) in.fail("material: " + problem);
  return m;
}

void write(ByteWriter& out, const CollisionFilter& f) {
  out.u64(f.category);
  out.u64(f.mask);
  out.u32(static_cast<std::uint32_t>(f.group));
}

CollisionFilter readFilter(ByteReader& in) {
  CollisionFilter f;
  f.category = in.u64();
  f.mask = in.u64();
  f.group = static_cast<std::int32_t>(in.u32());
  return f;
}

void write(ByteWriter& out, const Aabb& box) {
  out.vec3(box.min);
  out.vec3(box.max);
}

Aabb readAabb(ByteReader& in) {
  Aabb box;
  box.min = in.vec3();
  box.max = in.vec3();
  return box;
}

void write(ByteWriter& out, const ScriptedForce& f) {
  write(out, f.body);
  out.vec3(f.force);
  out.vec3(f.point);
  writeEnum(out, f.forceFrame);
  writeEnum(out, f.pointFrame);
  out.f64(f.start);
  out.f64(f.end);
}

ScriptedForce readForce(ByteReader& in) {
  ScriptedForce f;
  f.body = readId(in);
  f.force = in.vec3();
  f.point = in.vec3();
  f.forceFrame = readEnum<Frame>(in, 2, "force frame");
  f.pointFrame = readEnum<Frame>(in, 2, "point frame");
  f.start = in.f64();
  f.end = in.f64();
  return f;
}

void write(ByteWriter& out, const Spring& s) {
  write(out, s.body);
  out.vec3(s.anchor);
  out.vec3(s.point);
  out.f64(s.stiffness);
  out.f64(s.restLength);
  out.f64(s.damping);
}

Spring readSpring(ByteReader& in) {
  Spring s;
  s.body = readId(in);
  s.anchor = in.vec3();
  s.point = in.vec3();
  s.stiffness = in.f64();
  s.restLength = in.f64();
  s.damping = in.f64();
  return s;
}

void write(ByteWriter& out, const Joint& j, std::uint64_t indexA, std::uint64_t indexB) {
  const JointDef& d = j.def;
  writeEnum(out, d.type);
  out.text(d.name);
  write(out, d.bodyA);
  write(out, d.bodyB);
  out.vec3(d.anchor);
  out.vec3(d.axis);
  out.boolean(d.motor);
  for (double v : {d.motorSpeed, d.maxMotorTorque, d.maxMotorForce}) out.f64(v);
  out.boolean(d.limits);
  for (double v : {d.lowerAngle, d.upperAngle, d.lowerTranslation, d.upperTranslation}) out.f64(v);
  out.boolean(d.coneLimit);
  out.f64(d.coneAngle);
  out.boolean(d.spring);
  for (double v : {d.springHertz, d.springDampingRatio, d.friction, d.linearHertz, d.linearDampingRatio, d.angularHertz,
                   d.angularDampingRatio}) {
    out.f64(v);
  }
  out.boolean(d.collideConnected);
  out.u64(indexA);
  out.u64(indexB);
  out.vec3(j.localAnchorBase);
  out.vec3(j.localAnchorMoving);
  out.vec3(j.localAxisBase);
  out.vec3(j.localAxisMoving);
  out.quat(j.referenceRotation);
  out.vec3(j.linearImpulse);
  out.vec3(j.angularImpulse);
  for (double v : {j.motorImpulse, j.lowerImpulse, j.upperImpulse, j.swingImpulse}) out.f64(v);
  out.vec3(j.springImpulse);
  out.vec3(j.frictionImpulse);
}

Joint readJoint(ByteReader& in, std::uint64_t& indexA, std::uint64_t& indexB) {
  Joint j;
  JointDef& d = j.def;
  d.type = readEnum<JointDef::Type>(in, 4, "joint type");
  d.name = in.text();
  d.bodyA = readId(in);
  d.bodyB = readId(in);
  d.anchor = in.vec3();
  d.axis = in.vec3();
  d.motor = in.boolean();
  for (double* v : {&d.motorSpeed, &d.maxMotorTorque, &d.maxMotorForce}) *v = in.f64();
  d.limits = in.boolean();
  for (double* v : {&d.lowerAngle, &d.upperAngle, &d.lowerTranslation, &d.upperTranslation}) *v = in.f64();
  d.coneLimit = in.boolean();
  d.coneAngle = in.f64();
  d.spring = in.boolean();
  for (double* v : {&d.springHertz, &d.springDampingRatio, &d.friction, &d.linearHertz, &d.linearDampingRatio,
                    &d.angularHertz, &d.angularDampingRatio}) {
    *v = in.f64();
  }
  d.collideConnected = in.boolean();
  indexA = in.u64();
  indexB = in.u64();
  j.localAnchorBase = in.vec3();
  j.localAnchorMoving = in.vec3();
  j.localAxisBase = in.vec3();
  j.localAxisMoving = in.vec3();
  j.referenceRotation = in.quat();
  j.linearImpulse = in.vec3();
  j.angularImpulse = in.vec3();
  for (double* v : {&j.motorImpulse, &j.lowerImpulse, &j.upperImpulse, &j.swingImpulse}) *v = in.f64();
  j.springImpulse = in.vec3();
  j.frictionImpulse = in.vec3();
  return j;
}

void write(ByteWriter& out, const PoseEvent& e) {
  write(out, e.body);
  out.f64(e.time);
  writeOptional(out, e.position, [&](const Vec3& v) { out.vec3(v); });
  writeOptional(out, e.orientation, [&](const Quat& q) { out.quat(q); });
  writeOptional(out, e.velocity, [&](const Vec3& v) { out.vec3(v); });
  writeOptional(out, e.angularVelocity, [&](const Vec3& v) { out.vec3(v); });
}

PoseEvent readPoseEvent(ByteReader& in) {
  PoseEvent e;
  e.body = readId(in);
  e.time = in.f64();
  if (in.boolean()) e.position = in.vec3();
  if (in.boolean()) e.orientation = in.quat();
  if (in.boolean()) e.velocity = in.vec3();
  if (in.boolean()) e.angularVelocity = in.vec3();
  return e;
}

void write(ByteWriter& out, const KinematicMotion& m) {
  write(out, m.body);
  writeEnum(out, m.kind);
  out.vec3(m.pivot);
  out.vec3(m.angularVelocity);
  out.count(m.keys.size());
  for (const Keyframe& k : m.keys) {
    out.f64(k.time);
    out.vec3(k.position);
    out.quat(k.orientation);
  }
  out.boolean(m.loop);
}

KinematicMotion readMotion(ByteReader& in) {
  constexpr std::size_t kKeyBytes = 8 * 8;  // time, position, orientation
  KinematicMotion m;
  m.body = readId(in);
  m.kind = readEnum<KinematicMotion::Kind>(in, 2, "kinematic motion kind");
  m.pivot = in.vec3();
  m.angularVelocity = in.vec3();
  m.keys.resize(in.count(kKeyBytes, "keyframes"));
  for (Keyframe& k : m.keys) {
    k.time = in.f64();
    k.position = in.vec3();
    k.orientation = in.quat();
  }
  m.loop = in.boolean();
  const std::string problem = checkKinematicMotion(m);
  if (!problem.empty()) in.fail("kinematic motion: " + problem);
  return m;
}

}  // namespace rbsim::snapshot

// The bodies of a World snapshot (world_snapshot_access.h). A body's constant parts are not
// saved (Jolt's SaveState saves no shapes either): the reader takes them from the base World's
// bodies, spawner prototypes and their fracture pieces, matched by shapeFingerprint, and the
// record supplies what may differ between bodies of one shape (name, colour, material, filter,
// kind) and everything a step changes.
#include <string>
#include <unordered_map>
#include <vector>

#include "math/fnv.h"
#include "rbsim/fracture/fracture.h"
#include "rbsim/integrate/free_rigid_body.h"
#include "rbsim/world/ragdoll.h"
#include "rbsim/world/world_snapshot.h"
#include "world/snapshot_parts.h"
#include "world/world_snapshot_access.h"

namespace rbsim {

namespace {

std::uint64_t mix(std::uint64_t h, double v) { return fnvMix(h, v); }
std::uint64_t mix(std::uint64_t h, const Vec3& v) { return mix(mix(mix(h, v.x()), v.y()), v.z()); }
std::uint64_t mix(std::uint64_t h, const Mat3& m) {
  for (int k = 0; k < 9; ++k) h = mix(h, m.data()[k]);
  return h;
}
std::uint64_t mixCount(std::uint64_t h, std::size_t n) { return mix(h, static_cast<double>(n)); }
std::uint64_t mixShape(std::uint64_t h, const Shape& s) {
  h = mixCount(h, static_cast<std::size_t>(s.type));
  h = mix(mix(h, s.radius), s.halfLength);
  return mix(h, s.halfExtents);
}
std::uint64_t mixMesh(std::uint64_t h, const Mesh* mesh) {
  if (!mesh) return mixCount(h, SIZE_MAX);
  h = mixCount(mixCount(h, mesh->vertices.size()), mesh->triangles.size());
  for (const Vec3& v : mesh->vertices) h = mix(h, v);
  return h;
}

// A BodyDef giving `body` again: its constants, and its solid's grids, as they are.
BodyDef defOf(const RigidBody& body, const BodySolid& solid, const std::shared_ptr<const FracturePattern>& pattern,
              const Material& material) {
  BodyDef def;
  def.name = body.name();
  def.mesh = body.sharedMesh();
  def.fileFrame = body.fileFrame();
  def.mass = body.mass();
  def.inertiaBody = body.inertiaBody();
  def.position = body.position();
  def.orientation = body.orientation();
  def.material = material;
  def.isStatic = body.isStatic();
  def.isKinematic = body.isKinematic();
  def.shape = body.shape();
  def.filter = body.filter();
  def.children = body.children();
  def.fracture = pattern;
  def.sdf = solid.sdf;
  def.surfaceSamples = solid.samples;
  def.implicit = solid.implicit;
  def.triangles = solid.triangles;
  return def;
}

using Catalogue = std::unordered_map<std::uint64_t, BodyDef>;

bool sameMesh(const Mesh& a, const Mesh& b) { return a.vertices == b.vertices && a.triangles == b.triangles; }

// A definition, and the pieces it breaks into, by fingerprint (the first of equal ones).
void catalogue(Catalogue& out, const BodyDef& def) {
  const RigidBody body(def);
  out.emplace(shapeFingerprint(body, bodySolidOf(def)), def);
  if (!def.fracture) return;
  for (const BodyDef& piece : fracturePieces(body, *def.fracture, def.material)) {
    out.emplace(shapeFingerprint(RigidBody(piece), bodySolidOf(piece)), piece);
  }
}

void saveMemo(ByteWriter& out, const FreeFlowMemo* memo) {
  out.boolean(memo != nullptr);
  if (!memo) return;
  out.boolean(memo->flow.has_value());
  if (memo->flow) {
    out.quat(memo->flow->givenOrientation());
    out.vec3(memo->flow->angularMomentum());
    out.vec3(memo->flow->principalMoments());
  }
  out.f64(memo->dt);
  out.i64(memo->steps);
  out.quat(memo->lastOrientation);
  out.quat(memo->bodyToPrincipal);
}

void loadMemo(ByteReader& in, RigidBody& body) {
  if (!in.boolean()) return;
  FreeFlowMemo memo;
  if (in.boolean()) {
    const Quat given = in.quat();
    const Vec3 momentum = in.vec3();
    const Vec3 moments = in.vec3();
    if (!given.coeffs().allFinite() || given.norm() == 0.0 || !momentum.allFinite() || !(moments.array() > 0.0).all()) {
      in.fail("body '" + body.name() + "': a free-flow memo that is no flow");
    }
    memo.flow.emplace(given, momentum, moments);
  }
  memo.dt = in.f64();
  memo.steps = static_cast<long>(in.i64());
  memo.lastOrientation = in.quat();
  memo.bodyToPrincipal = in.quat();
  body.freeFlowMemo() = memo;
}

}  // namespace

std::uint64_t shapeFingerprint(const RigidBody& body, const BodySolid& solid) {
  std::uint64_t h = kFnvOffsetBasis;
  h = mixMesh(h, &body.mesh());
  h = mixShape(h, body.shape());
  h = mixCount(h, body.children().size());
  for (const ChildShape& c : body.children()) {
    h = mix(mixShape(h, c.shape), c.position);
    h = mix(mix(mix(mix(h, c.orientation.x()), c.orientation.y()), c.orientation.z()), c.orientation.w());
    h = mixMesh(h, c.mesh.get());
  }
  h = mix(mix(h, body.mass()), body.inertiaBody());
  h = mix(mix(h, body.fileFrame().axes), body.fileFrame().centre);
  h = mixMesh(h, body.fileFrame().mesh.get());
  h = mixCount(h, (solid.sdf ? 1 : 0) + (solid.implicit ? 2 : 0) + (solid.triangles ? 4 : 0));
  return mixCount(h, solid.samples ? solid.samples->size() : 0);
}

void WorldSnapshotAccess::saveBodies(const World& world, ByteWriter& out) {
  out.count(world.table_->bodies.size());
  // Which bodies share one mesh object (a spawned figure's bones share their figure's, a scene's
  // copies their block's): the renderer draws the bodies of one mesh as instances of it, in
  // batches of first appearance, so a World read back draws the same batches only when its
  // bodies share as these did (a replay of a recording is drawn bit for bit).
  std::unordered_map<const Mesh*, std::size_t> firstWithMesh;
  for (std::size_t i = 0; i < world.table_->bodies.size(); ++i) {
    const RigidBody& b = world.table_->bodies[i];
    out.u64(shapeFingerprint(b, world.table_->solids[i]));
    out.u64(firstWithMesh.emplace(b.sharedMesh().get(), i).first->second);
    const BodyId id = world.idAt(i);
    out.u32(id.slot);
    out.u32(id.generation);
    out.text(b.name());
    snapshot::write(out, world.table_->materials[i]);
    snapshot::write(out, b.filter());
    out.boolean(b.isStatic());
    out.boolean(b.isKinematic());
    out.boolean(world.table_->fracturePatterns[i] != nullptr);
    const BodyState& s = b.state();
    out.vec3(s.position);
    out.quat(s.orientation);
    out.vec3(s.linearMomentum);
    out.vec3(s.angularMomentum);
    out.mat3(b.rotation());
    out.boolean(b.awake());
    out.f64(b.restingTime());
    out.vec3(b.force());
    out.vec3(b.torque());
    out.vec3(b.bodyTorque());
    saveMemo(out, b.freeFlowMemoIfMade());
  }
}

void WorldSnapshotAccess::loadBodies(ByteReader& in, const World& base, World& world) {
  Catalogue shapes;
  for (std::size_t i = 0; i < base.table_->bodies.size(); ++i) {
    catalogue(shapes, defOf(base.table_->bodies[i], base.table_->solids[i], base.table_->fracturePatterns[i], base.table_->materials[i]));
  }
  // A spawner's copies share its prototype's mesh object, and so do those it makes after the read.
  std::unordered_map<std::uint64_t, std::shared_ptr<const Mesh>> prototypeMeshes;
  for (const Spawner& spawner : base.spawners_) {
    if (!spawner.def.ragdoll) {
      catalogue(shapes, spawner.def.prototype);
      const BodyDef& prototype = spawner.def.prototype;
      prototypeMeshes.emplace(shapeFingerprint(RigidBody(prototype), bodySolidOf(prototype)), prototype.mesh);
      continue;
    }
    // A figure's bones, as a burst makes them: the drawn pose moves them, their shapes stay.
    World figure(base.settings_);
    static_cast<void>(addRagdoll(figure, *spawner.def.ragdoll));
    for (std::size_t i = 0; i < figure.table_->bodies.size(); ++i) {
      catalogue(shapes, defOf(figure.table_->bodies[i], figure.table_->solids[i], nullptr, figure.table_->materials[i]));
    }
  }
  // The fewest bytes a body record takes: fingerprint, mesh group, id, an empty name, 32 doubles,
  // 6 flags.
  constexpr std::size_t kBodyBytes = 8 + 8 + 8 + 8 + 32 * 8 + 6;
  const std::size_t count = in.count(kBodyBytes, "bodies");
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint64_t fingerprint = in.u64();
    const std::uint64_t group = in.u64();
    BodyId id;
    id.slot = in.u32();
    id.generation = in.u32();
    const std::string name = in.text();
    const auto found = shapes.find(fingerprint);
    if (found == shapes.end()) {
      in.fail("body " + std::to_string(i) + " '" + name +
              "': no body, spawner prototype, spawned figure's bone or fracture piece of the World read into has its "
              "shape (a World built from another scene)");
    }
    BodyDef def = found->second;
    if (group > i || (group < i && !sameMesh(*world.table_->bodies[group].sharedMesh(), *def.mesh))) {
      in.fail("body " + std::to_string(i) + " '" + name + "': shares the mesh of body " + std::to_string(group) +
              ", which is not an earlier body with its mesh");
    }
    // The first of a group keeps the mesh object its body has in the base World (read into the
    // World it was saved from, nothing is uploaded to the renderer again), or takes its spawner's
    // prototype's, or has a copy of its own; the later ones of the group share it.
    const auto prototype = prototypeMeshes.find(fingerprint);
    if (group < i) {
      def.mesh = world.table_->bodies[group].sharedMesh();
    } else if (base.isValid(id) && sameMesh(base.body(id).mesh(), *def.mesh)) {
      def.mesh = base.body(id).sharedMesh();
    } else if (prototype != prototypeMeshes.end() && sameMesh(*prototype->second, *def.mesh)) {
      def.mesh = prototype->second;
    } else {
      def.mesh = std::make_shared<const Mesh>(*def.mesh);
    }
    def.name = name;
    def.material = snapshot::readMaterial(in);
    def.filter = snapshot::readFilter(in);
    def.isStatic = in.boolean();
    def.isKinematic = in.boolean();
    if (def.isStatic && def.isKinematic) in.fail("body '" + name + "': both static and kinematic");
    const bool breakable = in.boolean();
    if (breakable && !def.fracture) in.fail("body '" + name + "': breakable, but its shape has no fracture pattern here");
    if (!breakable) def.fracture = nullptr;
    BodyState state;
    state.position = in.vec3();
    state.orientation = in.quat();
    state.linearMomentum = in.vec3();
    state.angularMomentum = in.vec3();
    const Mat3 rotation = in.mat3();
    if (!isFinite(state) || !rotation.allFinite()) in.fail("body '" + name + "': a state that is not finite");
    const bool awake = in.boolean();
    world.addBody(def);
    RigidBody& body = world.table_->bodies.back();
    if (awake) {
      body.wake();
    } else if (!body.isStatic()) {
      body.sleep();
    }
    if (body.awake() != awake) in.fail("body '" + name + "': a static body awake");
    body.setState(state, rotation);
    body.setRestingTime(in.f64());
    body.clearAccumulators();
    body.applyForce(in.vec3());
    body.applyTorque(in.vec3());
    body.applyBodyTorque(in.vec3());
    loadMemo(in, body);
  }
}

}  // namespace rbsim

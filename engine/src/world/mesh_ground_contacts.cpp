#include "world/mesh_ground_contacts.h"

#include "collision/narrowphase/shape_triangle.h"
#include "geometry/triangle_bvh.h"
#include "rbsim/shapes/collision_filter.h"

namespace rbsim {

namespace {

constexpr std::uint32_t kPartCount = 1u << 15;  // Contact::part is below this

// The box `world` (world frame) in the ground's body frame: the box of its eight corners there.
Aabb inGroundFrame(const Aabb& world, const Mat3& R, const Vec3& x) {
  Aabb local;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? world.max.x() : world.min.x(), (i & 2) ? world.max.y() : world.min.y(),
                      (i & 4) ? world.max.z() : world.min.z());
    local.grow(R.transpose() * (corner - x));
  }
  return local;
}

// One shape of the other body (child `child`) against the ground's triangles near it.
void collideShape(const RigidBody& ground, std::size_t ig, const TriangleBvh& bvh, const PosedShape& shape,
                  std::size_t child, std::size_t io, bool groundFirst, double margin, std::vector<Contact>& out) {
  // Per thread: the narrow phase runs pairs on any thread, and these are reused pair after pair.
  thread_local std::vector<std::uint32_t> near;
  thread_local ShapePoints points;
  const auto [lo, hi] = shape.shape->worldBounds(shape.rotation, shape.position);
  const Mat3& R = ground.rotation();
  const Vec3& x = ground.position();
  near.clear();
  bvh.overlapping(inGroundFrame(Aabb{lo, hi}.inflated(margin), R, x), near);
  if (near.empty()) return;
  shapePointsOf(shape, points);
  for (const std::uint32_t t : near) {
    const Triangle& tri = bvh.triangles()[t];
    WorldTriangle w;
    for (int k = 0; k < 3; ++k) w.vertices[k] = R * bvh.vertices()[tri[k]] + x;
    const Vec3 n = (w.vertices[1] - w.vertices[0]).cross(w.vertices[2] - w.vertices[0]);
    if (!(n.norm() > 0.0)) continue;  // a degenerate triangle has no side to rest on
    w.normal = n.normalized();
    w.activeEdges = bvh.activeEdges(t);
    ContactManifold m = collideShapeTriangle(shape, points, w, margin);
    if (m.count == 0) continue;
    if (!groundFirst) m.normal = -m.normal;
    const auto c = static_cast<std::uint16_t>(child);
    out.push_back({Contact::Kind::BodyBody, groundFirst ? ig : io, groundFirst ? io : ig, meshGroundPart(t, child), m,
                   groundFirst ? std::uint16_t{0} : c, groundFirst ? c : std::uint16_t{0}});
  }
}

}  // namespace

std::uint16_t meshGroundPart(std::uint32_t triangle, std::size_t child) {
  return static_cast<std::uint16_t>((triangle + kMeshGroundChildStride * static_cast<std::uint32_t>(child)) % kPartCount);
}

bool isMeshGround(const RigidBody& body, const BodySolid& solid) {
  return body.isStatic() && !body.isCompound() && body.shape().type == ShapeType::Mesh && solid.triangles && !solid.sdf;
}

void collideMeshGround(const RigidBody& ground, std::size_t ig, const TriangleBvh& triangles, const RigidBody& other,
                       std::size_t io, bool groundFirst, double margin, std::vector<Contact>& out) {
  if (!other.isCompound()) {
    if (!shouldCollide(ground.filter(), other.filter())) return;
    collideShape(ground, ig, triangles, {&other.shape(), other.rotation(), other.position()}, 0, io, groundFirst, margin,
                 out);
    return;
  }
  const Mat3& R = other.rotation();
  const std::vector<ChildShape>& children = other.children();
  for (std::size_t c = 0; c < children.size(); ++c) {
    if (!shouldCollide(ground.filter(), children[c].filter)) continue;
    const PosedShape posed{&children[c].shape, R * children[c].orientation.toRotationMatrix(),
                           other.bodyToWorld(children[c].position)};
    collideShape(ground, ig, triangles, posed, c, io, groundFirst, margin, out);
  }
}

}  // namespace rbsim

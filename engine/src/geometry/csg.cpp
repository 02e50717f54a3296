#include "geometry/csg.h"

#include <algorithm>

namespace rbsim {

namespace {

// Each primitive's half extents about its centre in its own frame [m].
struct HalfExtents {
  Vec3 operator()(const SphereSurface& s) const { return Vec3::Constant(s.radius); }
  Vec3 operator()(const EllipsoidSurface& s) const { return s.radii; }
  Vec3 operator()(const TorusSurface& s) const {
    const double reach = s.majorRadius + s.minorRadius;
    return Vec3(reach, s.minorRadius, reach);
  }
  Vec3 operator()(const BoxSurface& s) const { return s.halfExtents; }
  Vec3 operator()(const CapsuleSurface& s) const { return Vec3(s.radius, s.halfLength + s.radius, s.radius); }
  Vec3 operator()(const CylinderSurface& s) const { return Vec3(s.radius, s.halfHeight, s.radius); }
};

}  // namespace

const char* csgOpName(CsgOp op) {
  switch (op) {
    case CsgOp::Union: return "union";
    case CsgOp::Intersection: return "intersection";
    case CsgOp::Difference: return "difference";
  }
  return "?";
}

ImplicitFunction ImplicitFunction::primitive(ImplicitPrimitive surface, const Vec3& position, const Quat& orientation) {
  ImplicitFunction f;
  f.node_ = std::move(surface);
  f.rotation_ = orientation.normalized().toRotationMatrix();
  f.translation_ = position;
  return f;
}

ImplicitFunction ImplicitFunction::combine(CsgOp op, ImplicitFunction a, ImplicitFunction b, const Vec3& position,
                                           const Quat& orientation) {
  ImplicitFunction f;
  f.node_ = Operation{op, std::make_shared<const ImplicitFunction>(std::move(a)),
                      std::make_shared<const ImplicitFunction>(std::move(b))};
  f.rotation_ = orientation.normalized().toRotationMatrix();
  f.translation_ = position;
  return f;
}

double ImplicitFunction::phi(const Vec3& x) const { return localPhi(rotation_.transpose() * (x - translation_)); }

double ImplicitFunction::localPhi(const Vec3& local) const {
  if (const auto* surface = std::get_if<ImplicitPrimitive>(&node_)) {
    return std::visit([&](const auto& s) { return s.phi(local); }, *surface);
  }
  const Operation& o = std::get<Operation>(node_);
  const double a = o.a->phi(local), b = o.b->phi(local);
  switch (o.op) {
    case CsgOp::Union: return std::min(a, b);
    case CsgOp::Intersection: return std::max(a, b);
    case CsgOp::Difference: return std::max(a, -b);
  }
  return a;
}

ImplicitBounds ImplicitFunction::localBounds() const {
  if (const auto* surface = std::get_if<ImplicitPrimitive>(&node_)) {
    const Vec3 h = std::visit(HalfExtents{}, *surface);
    return {-h, h};
  }
  const Operation& o = std::get<Operation>(node_);
  const ImplicitBounds a = o.a->bounds(), b = o.b->bounds();
  switch (o.op) {
    case CsgOp::Union:
      if (a.empty()) return b;
      if (b.empty()) return a;
      return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)};
    case CsgOp::Intersection: return {a.lo.cwiseMax(b.lo), a.hi.cwiseMin(b.hi)};
    case CsgOp::Difference: return a;
  }
  return a;
}

ImplicitBounds ImplicitFunction::bounds() const {
  const ImplicitBounds local = localBounds();
  if (local.empty()) return local;
  // A box's extent along each parent axis is |R| h about its moved centre (Ericson 2005, 4.2.6).
  const Vec3 centre = rotation_ * (0.5 * (local.lo + local.hi)) + translation_;
  const Vec3 half = rotation_.cwiseAbs() * (0.5 * (local.hi - local.lo));
  return {centre - half, centre + half};
}

int ImplicitFunction::depth() const {
  if (std::holds_alternative<ImplicitPrimitive>(node_)) return 0;
  const Operation& o = std::get<Operation>(node_);
  return 1 + std::max(o.a->depth(), o.b->depth());
}

int ImplicitFunction::primitiveCount() const {
  if (std::holds_alternative<ImplicitPrimitive>(node_)) return 1;
  const Operation& o = std::get<Operation>(node_);
  return o.a->primitiveCount() + o.b->primitiveCount();
}

}  // namespace rbsim

#pragma once
// Constructive solid geometry on implicit surfaces (seed 000 "Recall: Implicit Surfaces":
// "efficient boolean operations: union, difference, intersection"). On the operands' signed
// distances a and b: union min(a, b), intersection max(a, b), difference a - b = max(a, -b)
// (Ricci 1973, "A constructive geometry for computer graphics", The Computer Journal 16(2)).
// The result has the right sign everywhere and is the exact distance wherever the nearest surface
// point is one an operand contributes unclipped; elsewhere (inside a union, near a difference's
// cut edges) |phi| is a lower bound on the distance.
#include <memory>
#include <utility>
#include <variant>

#include "geometry/implicit_primitives.h"
#include "geometry/implicit_surface.h"
#include "rbsim/math/types.h"

namespace rbsim {

using ImplicitPrimitive =
    std::variant<SphereSurface, EllipsoidSurface, TorusSurface, BoxSurface, CapsuleSurface, CylinderSurface>;

enum class CsgOp { Union, Intersection, Difference };
const char* csgOpName(CsgOp op);

// An axis-aligned box [m]; empty when lo > hi on some axis.
struct ImplicitBounds {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  bool empty() const { return (lo.array() > hi.array()).any(); }
};

// A node of a CSG tree: a primitive or an operation on two nodes, placed by a rigid motion
// (rotation R, translation t) in its parent's frame, so phi_node(x) = f(R^T (x - t)).
class ImplicitFunction {
 public:
  static ImplicitFunction primitive(ImplicitPrimitive surface, const Vec3& position = Vec3::Zero(),
                                    const Quat& orientation = Quat::Identity());
  static ImplicitFunction combine(CsgOp op, ImplicitFunction a, ImplicitFunction b,
                                  const Vec3& position = Vec3::Zero(), const Quat& orientation = Quat::Identity());

  // phi [m] at x in this node's parent frame (for the root: the shape's file frame).
  double phi(const Vec3& x) const;
  // A box holding the solid (phi < 0): each primitive's extent moved by its pose, union of the
  // operands' boxes for a union, their overlap for an intersection, the first's for a difference.
  ImplicitBounds bounds() const;
  // Levels of operations above the deepest primitive (a primitive: 0) and primitives in all.
  int depth() const;
  int primitiveCount() const;

 private:
  struct Operation {
    CsgOp op;
    std::shared_ptr<const ImplicitFunction> a, b;
  };
  double localPhi(const Vec3& local) const;
  ImplicitBounds localBounds() const;

  std::variant<ImplicitPrimitive, Operation> node_;
  Mat3 rotation_ = Mat3::Identity();
  Vec3 translation_ = Vec3::Zero();
};

}  // namespace rbsim

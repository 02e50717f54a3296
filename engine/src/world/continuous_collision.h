#pragma once
// Continuous collision detection by conservative advancement (Mirtich 1996, "Impulse-based
// Dynamic Simulation of Rigid Body Systems", §2.3.2; Ericson, Real-Time Collision Detection,
// §9.5.5): seed 004's answer to the fixed-time-step weakness, a thin fast body passing through a
// wall between two samples. The motion over a step is taken as x(s) = x0 + s (x1 - x0) and
// q(s) = slerp(q0, q1, s), s in [0, 1]; no point of a body moves more than
//   bound = |x1 - x0| + angle(q0, q1) r_max
// per unit s (r_max: the farthest point of its shape from the centre of mass), so advancing s by
// distance / (sum of the bounds) never steps past the first contact.
//
// What is swept is the collision shape (shapes/shape.h), the geometry the narrow phase collides:
// a sphere, capsule or rounded box as its core grown by its radius, a box or hull as itself, a
// compound as its children. The display mesh is not: a sphere's is inscribed in it, and a mesh
// larger than its shape stopped the body above the surface its shape rests on, every step, while
// gravity went on adding to its momentum (issue 56).
#include <optional>
#include <vector>

#include "rbsim/body/child_shape.h"
#include "rbsim/collision/contact.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/integrate/body_state.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

// Advancement stops when the bodies are closer than this [m]; also the gap they are left at.
inline constexpr double kImpactSeparation = 1e-3;
// Each iteration at least halves the remaining gap in practice; this caps pathological spins.
inline constexpr int kMaxAdvancementIterations = 64;

// One body's motion over a step.
struct SweptBody {
  const Shape* shape = nullptr;  // body frame, origin at the centre of mass
  // A compound's children (body/child_shape.h), swept in place of `shape` when not empty.
  const std::vector<ChildShape>* children = nullptr;
  BodyState start, end;
  double radius = 0.0;  // r_max [m]
};

// The pose of the sweep at s in [0, 1].
BodyState poseAt(const SweptBody& body, double s);
// The largest distance any point of the body moves per unit s [m].
double motionBound(const SweptBody& body);
// The world box of the swept shape at s in [0, 1] (exact for each part, Shape::worldBounds).
Aabb boundsAt(const SweptBody& body, double s);

// The first s at which the body comes within kImpactSeparation of the plane, or nothing when it
// stays apart, or starts already penetrating (that is the narrow phase's job), or starts within
// the separation and its first kImpactSeparation of motion does not bring it closer.
std::optional<double> timeOfImpact(const SweptBody& body, const Plane& plane);
// The same for two bodies, both moving (GJK distance between their shapes' cores, less the radii).
std::optional<double> timeOfImpact(const SweptBody& a, const SweptBody& b);

}  // namespace rbsim

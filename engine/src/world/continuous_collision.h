#pragma once
// Continuous collision detection by conservative advancement (Mirtich 1996, "Impulse-based
// Dynamic Simulation of Rigid Body Systems", §2.3.2; Ericson, Real-Time Collision Detection,
// §9.5.5): seed 004's answer to the fixed-time-step weakness, a thin fast body passing through a
// wall between two samples. The motion over a step is taken as x(s) = x0 + s (x1 - x0) and
// q(s) = slerp(q0, q1, s), s in [0, 1]; no point of a body moves more than
//   bound = |x1 - x0| + angle(q0, q1) r_max
// per unit s (r_max: the farthest vertex from the centre of mass), so advancing s by
// distance / (sum of the bounds) never steps past the first contact.
#include <optional>
#include <vector>

#include "rbsim/integrate/body_state.h"
#include "rbsim/collision/contact.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Advancement stops when the bodies are closer than this [m]; also the gap they are left at.
inline constexpr double kImpactSeparation = 1e-3;
// Each iteration at least halves the remaining gap in practice; this caps pathological spins.
inline constexpr int kMaxAdvancementIterations = 64;

// One body's motion over a step.
struct SweptBody {
  const std::vector<Vec3>* bodyVertices = nullptr;  // body frame, origin at the centre of mass
  BodyState start, end;
  double radius = 0.0;  // r_max [m]
};

// The pose of the sweep at s in [0, 1].
BodyState poseAt(const SweptBody& body, double s);
// The largest distance any point of the body moves per unit s [m].
double motionBound(const SweptBody& body);
std::vector<Vec3> worldVerticesAt(const SweptBody& body, double s);

// The first s at which the body comes within kImpactSeparation of the plane, or nothing when it
// stays apart, or starts already penetrating (that is the narrow phase's job), or starts within
// the separation and its first kImpactSeparation of motion does not bring it closer.
std::optional<double> timeOfImpact(const SweptBody& body, const Plane& plane);
// The same for two bodies, both moving (GJK distance between the convex hulls).
std::optional<double> timeOfImpact(const SweptBody& a, const SweptBody& b);

}  // namespace rbsim

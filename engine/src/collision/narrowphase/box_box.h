#pragma once
// Oriented box vs oriented box by the separating axis theorem (Gottschalk, Lin, Manocha, "OBBTree",
// SIGGRAPH 1996: 15 axes, the 3 + 3 face normals and the 9 edge cross products), with the contact
// manifold of ODE's dBoxBox and Bullet's btBoxBoxDetector: for a face axis, the incident face is
// clipped against the reference face's side planes (Sutherland-Hodgman) and the points below the
// reference face kept; for an edge axis, one point from the closest points of the two edges.
#include <optional>

#include "rbsim/collision/contact.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct OrientedBox {
  Vec3 centre = Vec3::Zero();             // world frame [m]
  Mat3 rotation = Mat3::Identity();       // columns are the box axes in world frame
  Vec3 halfExtents = Vec3::Constant(0.5);  // [m]
};

// Axis preference (after Box2D's b2CollidePolygons and ODE's dBoxBox fudge factor): a face of B
// replaces the best face of A only when its separation s (negative = penetration) is larger by
// relative * |s_A| + absolute, and an edge pair replaces the chosen face only when larger by
// relative * |s_face| + absolute. Faces give stable 4-point manifolds for resting boxes; ties and
// near-ties between A and B go to A, so the reference face does not flicker between frames.
inline constexpr double kSatFaceRelTolerance = 0.02;  // [1]
inline constexpr double kSatFaceAbsTolerance = 1e-5;  // [m]
inline constexpr double kSatEdgeRelTolerance = 0.05;  // [1]
inline constexpr double kSatEdgeAbsTolerance = 1e-5;  // [m]
// Edge pairs with |a_i x b_j| below this [1] (sine of their angle) are parallel: their cross
// product is no axis, and the face axes already cover that direction.
inline constexpr double kSatParallelEdgeSine = 1e-6;

enum class SatAxisKind { FaceA, FaceB, EdgeEdge };

struct BoxBoxResult {
  // Normal from A to B; count 0 when some axis separates the boxes by more than the margin.
  ContactManifold manifold;
  // [m] Along the chosen axis (or the separating one): > 0 apart (a lower bound on the distance),
  // < 0 overlapping by -separation.
  double separation = 0.0;
  SatAxisKind axis = SatAxisKind::FaceA;
  int indexA = 0, indexB = 0;  // box axes of the chosen face (FaceA/FaceB) or edges (EdgeEdge)
};

// `margin` [m] >= 0: boxes apart by up to this still get (speculative) contacts, depth < 0.
BoxBoxResult collideBoxes(const OrientedBox& a, const OrientedBox& b, double margin = 0.0);

// The box a body is, when its body-space mesh has exactly the 8 corners of its bounds; x and R
// are the body's position and rotation. Used to dispatch box pairs to collideBoxes.
std::optional<OrientedBox> orientedBoxOf(const Mesh& mesh, const Vec3& position, const Mat3& rotation);

}  // namespace rbsim

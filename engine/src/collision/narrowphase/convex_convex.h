#pragma once
// The narrow phase for a pair of convex vertex sets (each standing for its convex hull, as in
// GJK): GJK separation, EPA penetration normal and depth, then a manifold from the two support
// features (the vertices of A within a tolerance of A's extreme along n, those of B within it of
// B's extreme along -n) clipped against each other in the contact plane (Sutherland-Hodgman), the
// points midway between the two surfaces, reduced to at most 4. Box pairs may go to the SAT of
// box_box.h instead. Also the plain GJK distance, for demos and continuous collision detection.
#include <vector>

#include "rbsim/collision/contact.h"
#include "collision/narrowphase/box_box.h"
#include "collision/narrowphase/gjk.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/face_planes.h"

namespace rbsim {

// Vertices this close [m] to their set's extreme along the normal belong to the support feature
// (face, edge or vertex). It absorbs EPA's normal error and decides how tilted a resting face
// may be and still give a face contact; the depths are computed from the geometry, not from it.
inline constexpr double kSupportFeatureTolerance = 1e-3;

struct ConvexContact {
  ContactManifold manifold;  // normal from A to B; count 0 when apart by more than the margin
  bool overlap = false;      // the hulls touch or intersect
  // [m] when apart, GJK's distance; for box pairs (usedBoxSat) the SAT separation, the largest
  // gap along the 15 axes: exact when the closest features are a face or two edges, a lower
  // bound when they are vertices. 0 when overlapping.
  double distance = 0.0;
  double depth = 0.0;        // [m] penetration depth (EPA, or SAT for boxes) when overlapping
  // Closest points when apart (GJK only), deepest points (pointA - pointB = depth n) when
  // overlapping [m].
  Vec3 pointA = Vec3::Zero();
  Vec3 pointB = Vec3::Zero();
  bool usedBoxSat = false;  // both boxes were given, so collideBoxes made the manifold
};

// `margin` [m] >= 0: pairs apart by up to this get speculative contacts (depth < 0). When both
// boxes are given (their poses must match the vertex sets) the SAT of collideBoxes is used.
ConvexContact collideConvex(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double margin = 0.0,
                            const OrientedBox* boxA = nullptr, const OrientedBox* boxB = nullptr,
                            double featureTolerance = kSupportFeatureTolerance);

// The same with GJK and EPA on the sets' own support mappings (a hill climb over a large hull's
// vertex graph instead of a scan); a and b are still the vertex sets, for the feature manifold.
ConvexContact collideConvex(const SupportMap& supportA, const std::vector<Vec3>& a, const SupportMap& supportB,
                            const std::vector<Vec3>& b, double margin = 0.0,
                            double featureTolerance = kSupportFeatureTolerance);

// A face axis within this [m] of EPA's separation is taken in its place, so that a face meets the
// other hull (a manifold of several points) rather than two edges at one point: Box3D keeps its
// face contact unless the edge axis separates more by B3_LINEAR_SLOP, 5 mm (convex_manifold.c,
// b3CollideHulls, edgeTol), as Box2D's polygon manifold prefers a face (b2_linearSlop).
inline constexpr double kFaceAxisPreference = 5e-3;
// And for hulls pressed into each other, this fraction [1] of the depth besides: a face's
// manifold of several points, its deepest within a tenth of EPA's depth, pushes a deep pair out
// along a normal nearly as short, where two edges' one point let it turn about that point deeper
// in (Box3D's convex pile, issue 56: each step's deepest overlap over steps 250-499, mean and
// worst, 0.31 and 1.18 m with the slop alone; 0.23 and 0.47 at 0.05, 0.22 and 0.55 at 0.1, 0.22
// and 0.46 at 0.25; Box3D 0.39 and 0.84; bench/box3d_scenes --scenes convex_pile --threads 1).
// Box3D's pairs never get as deep: its edge slop alone is tuned for resting contact.
inline constexpr double kDeepFaceAxisPreference = 0.1;

// A hull's face planes (shapes/face_planes.h) where its body is: rotation R and position x.
struct PosedFaces {
  const FacePlanes* planes = nullptr;
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();  // [m]
};

// collideConvex for two hulls that know their faces (either may be null): when EPA's normal is
// not a face's (two edges, or a vertex on an edge), the face of A most along it or of B most
// against it is taken instead when its separation is within kFaceAxisPreference (plus
// kDeepFaceAxisPreference of the depth) of EPA's; against a reference face the other hull's
// incident face is clipped to it (Box3D's b3BuildFaceAContact).
ConvexContact collideHulls(const SupportMap& supportA, const std::vector<Vec3>& a, const PosedFaces& facesA,
                           const SupportMap& supportB, const std::vector<Vec3>& b, const PosedFaces& facesB,
                           double margin = 0.0);

struct ConvexDistance {
  bool overlap = false;
  double distance = 0.0;       // [m], 0 when overlapping
  Vec3 pointA = Vec3::Zero();  // closest point of hull A [m]
  Vec3 pointB = Vec3::Zero();  // closest point of hull B [m]
};

// The distance between the convex hulls of a and b and their closest points (GJK).
ConvexDistance convexDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace rbsim

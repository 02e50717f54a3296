#pragma once
// Closed, consistently oriented (outward, counter-clockwise seen from outside) mesh generators for
// tests and demos, in body space centred on the origin. Every argument out of range throws
// std::invalid_argument naming it.
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

using Vec2 = Eigen::Vector2d;

// Latitude-longitude sphere: `segments` (>= 3) around the y axis, `rings` (>= 2) bands from pole
// to pole; vertices on the sphere of `radius` [m], so the mesh is inscribed in it.
Mesh makeUvSphere(double radius, int segments, int rings);

// Capsule along the y axis: a cylinder of `radius` [m] and `length` [m] (>= 0) capped by two
// hemispheres, tessellated as makeUvSphere with `rings` even (the equator laid at both rims);
// vertices on the exact capsule, so the mesh is inscribed in it.
Mesh makeCapsule(double radius, double length, int segments, int rings);

// Rounded box: the points within `radius` [m] of a core box of `coreHalfExtents` [m] (each >= 0).
// Each face of the outer box is a grid whose points are sent to the nearest point of the rounded
// surface, with `bandSegments` (>= 1) steps of equal angle over each 45-degree half of an edge's
// quarter-round; vertices on the exact surface, so the mesh is inscribed in it.
Mesh makeRoundedBox(const Vec3& coreHalfExtents, double radius, int bandSegments);

// Torus around the y axis: tube centre circle of `majorRadius` [m] in the xz plane, tube radius
// `minorRadius` [m] < majorRadius; vertices on the exact torus.
Mesh makeTorus(double majorRadius, double minorRadius, int majorSegments, int minorSegments);

// Hemispherical shell opening up +y: outer hemisphere of `outerRadius` [m] below the plane y = 0,
// inner hemisphere of outerRadius - wallThickness, joined by a flat rim ring at y = 0.
// `segments` (>= 3) around y, `rings` (>= 1) from the bottom pole to the rim.
Mesh makeBowl(double outerRadius, double wallThickness, int segments, int rings);

// The simple polygon `outline` (counter-clockwise in the xy plane, >= 3 corners, non-zero area)
// extruded along z from -depth/2 to +depth/2 [m]; the caps are triangulated by ear clipping
// (geometry/polygon_triangulation.h), so the polygon may be non-convex.
Mesh makeExtrudedPolygon(const std::vector<Vec2>& outline, double depth);

// A letter "U" (non-convex prism): `width` x `height` [m] outline with arms and base `stroke` [m]
// thick, extruded by `depth` [m], centred on the origin.
Mesh makeLetterU(double width, double height, double stroke, double depth);

}  // namespace rbsim

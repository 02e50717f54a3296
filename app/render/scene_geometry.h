#pragma once
// CPU side of a frame: turns FrameData into flat vertex arrays the GL renderer uploads as they are.
// Kept free of GL so the geometry rules (flat normals, feature edges, arrow shapes) are plain C++.
#include <vector>

#include <glm/glm.hpp>

#include "frame_data.h"

namespace rbsim::render {

struct MeshVertex {
  glm::vec3 position;
  glm::vec3 normal;  // the triangle's own normal on its 3 vertices (flat shading), or the
                     // vertex's averaged normal on a smooth body
  glm::vec3 color;   // linear RGB
};

struct LineVertex {
  glm::vec3 position;
  glm::vec4 color;  // linear RGB + alpha
};

// One see-through body's triangles inside SceneGeometry::ghosts.
struct GhostRange {
  int first = 0;  // vertex offset into ghosts, a multiple of 3
  int count = 0;  // vertices, a multiple of 3
  float opacity = 1.0f;
};

struct SceneGeometry {
  std::vector<MeshVertex> bodies;      // every opaque body's triangles, 3 vertices each
  std::vector<MeshVertex> ghosts;      // bodies with opacity < 1, farthest from the eye first
  std::vector<GhostRange> ghostRanges; // one per ghost, in drawing (back-to-front) order
  std::vector<MeshVertex> arrowHeads;  // cones at the tips of the force arrows
  std::vector<LineVertex> edges;       // feature edges (creases, open borders) of opaque bodies
  std::vector<LineVertex> highlight;   // the selected body's feature edges, drawn brighter
  std::vector<LineVertex> ghostEdges;  // ghosts' feature edges, alpha = the ghost's opacity
  std::vector<LineVertex> axes;        // body axes: red x, green y, blue z (columns of R)
  std::vector<LineVertex> forceShafts; // force arrows from the application point to the head
  void clear();
};

// Whether a body is drawn as an instance of its mesh (instanced_bodies.h) rather than from its
// world vertices here: an opaque rigid body with a mesh, not smooth, not selected (the highlight
// of the selected one is drawn with its own edges here). Ghosts and cloths stay on this path.
bool drawnAsInstance(const BodyView& body);

// Fills `out` (reusing its capacity) from one frame, leaving out the surfaces and outlines of
// bodies drawnAsInstance (their axes stay). Triangle indices outside a body's vertex list are
// skipped rather than trusted, since they come from a mesh file.
void buildSceneGeometry(const FrameData& frame, SceneGeometry& out);

// The body's shape in its own frame, p = R^T (p' - x), as buildSceneGeometry would draw it: 3
// vertices per triangle with its flat normal (colour white), and its feature edges as segments.
void buildBodyShape(const BodyView& body, std::vector<MeshVertex>& triangles,
                    std::vector<LineVertex>& edges);

// The ground square (y = 0, centred under the eye) has this half size over the camera's far
// distance: its corners at 0.92 of the far distance are inside the far plane for any sensible eye
// height, and the ground has faded into the horizon colour long before, so its edge never shows.
// Shared by the colour pass and the segmentation pass, which must cover the same pixels.
inline constexpr float kGroundHalfSizeOfFar = 0.65f;

// Colours shared by the geometry and the tests (linear RGB).
inline constexpr glm::vec3 kAxisColors[3] = {
    {0.90f, 0.10f, 0.08f}, {0.15f, 0.75f, 0.12f}, {0.10f, 0.30f, 1.00f}};
inline constexpr glm::vec3 kForceColor{1.00f, 0.78f, 0.05f};
inline constexpr glm::vec3 kHighlightColor{1.00f, 1.00f, 1.00f};
// Outlines are this fraction of the body's colour, so edges read as shading, not a second colour.
inline constexpr float kEdgeShade = 0.25f;

}  // namespace rbsim::render

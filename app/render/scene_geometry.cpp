#include "scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace rbsim::render {

namespace {

// Two faces meeting at more than this angle make a visible crease; flatter ones (the diagonal of
// a box face, a finely tessellated curved surface) are left out so outlines stay clean.
constexpr float kCreaseCosine = 0.94f;  // cos(20 degrees)

glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

struct EdgeFaces {
  glm::vec3 firstNormal{0.0f};
  int faces = 0;
  bool crease = false;
};

// Where one body's triangles and outlines go: opaque bodies and ghosts have separate lists.
struct BodyTarget {
  std::vector<MeshVertex>& triangles;
  std::vector<LineVertex>& edges;
  std::vector<LineVertex>& highlight;
  float alpha;  // of the outlines
};

// Per-vertex normals of a smooth body: the sum of its triangles' area-weighted normals.
void vertexNormals(const BodyView& body, std::vector<glm::vec3>& normals) {
  const std::size_t count = body.worldVertices.size();
  normals.assign(count, glm::vec3(0.0f));
  for (const auto& tri : *body.triangles) {
    if (tri[0] >= count || tri[1] >= count || tri[2] >= count) continue;
    const glm::vec3& a = body.worldVertices[tri[0]];
    const glm::vec3 n = glm::cross(body.worldVertices[tri[1]] - a, body.worldVertices[tri[2]] - a);
    for (int k = 0; k < 3; ++k) normals[tri[k]] += n;
  }
  for (glm::vec3& n : normals) {
    const float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

// Appends the body's triangles and its feature edges (crease or border) to `out`.
void addBody(const BodyView& body, const BodyTarget& out,
             std::unordered_map<std::uint64_t, EdgeFaces>& edgeMap, std::vector<glm::vec3>& normals) {
  if (body.triangles == nullptr) return;
  const auto& vertices = body.worldVertices;
  const std::size_t count = vertices.size();
  edgeMap.clear();
  if (body.smooth) vertexNormals(body, normals);
  for (const auto& tri : *body.triangles) {
    if (tri[0] >= count || tri[1] >= count || tri[2] >= count) continue;
    const glm::vec3& a = vertices[tri[0]];
    const glm::vec3& b = vertices[tri[1]];
    const glm::vec3& c = vertices[tri[2]];
    const glm::vec3 n = faceNormal(a, b, c);
    out.triangles.push_back({a, body.smooth ? normals[tri[0]] : n, body.color});
    out.triangles.push_back({b, body.smooth ? normals[tri[1]] : n, body.color});
    out.triangles.push_back({c, body.smooth ? normals[tri[2]] : n, body.color});
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = std::min(tri[k], tri[(k + 1) % 3]);
      const std::uint32_t j = std::max(tri[k], tri[(k + 1) % 3]);
      EdgeFaces& edge = edgeMap[(static_cast<std::uint64_t>(i) << 32) | j];
      if (edge.faces == 0) edge.firstNormal = n;
      else if (glm::dot(edge.firstNormal, n) < kCreaseCosine) edge.crease = true;
      ++edge.faces;
    }
  }
  const glm::vec4 edgeColor(body.color * kEdgeShade, out.alpha);
  const glm::vec4 highlightColor(kHighlightColor, out.alpha);
  for (const auto& [key, edge] : edgeMap) {
    if (edge.faces != 1 && (!edge.crease || body.smooth)) continue;
    const glm::vec3& p = vertices[key >> 32];
    const glm::vec3& q = vertices[key & 0xffffffffu];
    out.edges.push_back({p, edgeColor});
    out.edges.push_back({q, edgeColor});
    if (body.selected) {
      out.highlight.push_back({p, highlightColor});
      out.highlight.push_back({q, highlightColor});
    }
  }
}

bool isGhost(const BodyView& body) { return body.opacity < 1.0f; }  // NaN counts as opaque
bool isDrawn(const BodyView& body) { return body.opacity > 0.0f; }

void addAxes(const BodyView& body, SceneGeometry& out) {
  for (int axis = 0; axis < 3; ++axis) {
    const glm::vec4 color(kAxisColors[axis], 1.0f);
    out.axes.push_back({body.position, color});
    out.axes.push_back({body.position + body.axisLength * body.rotation[axis], color});
  }
}

// A cone (flat-shaded side and base) with its tip at `tip`, pointing along unit vector `dir`.
void addCone(const glm::vec3& tip, const glm::vec3& dir, float length, float radius,
             const glm::vec3& color, std::vector<MeshVertex>& out) {
  constexpr int kSegments = 14;
  // Any vector not parallel to dir gives a basis of the base plane.
  const glm::vec3 helper = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(dir, helper));
  const glm::vec3 w = glm::cross(dir, u);
  const glm::vec3 baseCentre = tip - dir * length;
  for (int s = 0; s < kSegments; ++s) {
    const float a0 = 2.0f * 3.14159265f * static_cast<float>(s) / kSegments;
    const float a1 = 2.0f * 3.14159265f * static_cast<float>(s + 1) / kSegments;
    const glm::vec3 p0 = baseCentre + radius * (std::cos(a0) * u + std::sin(a0) * w);
    const glm::vec3 p1 = baseCentre + radius * (std::cos(a1) * u + std::sin(a1) * w);
    const glm::vec3 side = faceNormal(p0, p1, tip);
    out.push_back({p0, side, color});
    out.push_back({p1, side, color});
    out.push_back({tip, side, color});
    out.push_back({baseCentre, -dir, color});
    out.push_back({p1, -dir, color});
    out.push_back({p0, -dir, color});
  }
}

void addForce(const ForceArrow& arrow, float scale, SceneGeometry& out) {
  const glm::vec3 vector = arrow.force * scale;
  const float length = glm::length(vector);
  if (!(length > 1e-4f)) return;  // also rejects NaN
  const glm::vec3 dir = vector / length;
  // The head grows with the arrow up to a cap, so long arrows do not get huge cones.
  const float headLength = std::min(0.3f * length, 0.18f);
  const float headRadius = 0.38f * headLength;
  const glm::vec3 tip = arrow.point + vector;
  const glm::vec4 color(kForceColor, 1.0f);
  out.forceShafts.push_back({arrow.point, color});
  out.forceShafts.push_back({tip - dir * headLength, color});
  addCone(tip, dir, headLength, headRadius, kForceColor, out.arrowHeads);
}

}  // namespace

bool drawnAsInstance(const BodyView& body) {
  return body.mesh != nullptr && body.triangles != nullptr && !body.smooth && !body.selected &&
         isDrawn(body) && !isGhost(body);
}

void buildBodyShape(const BodyView& body, std::vector<MeshVertex>& triangles,
                    std::vector<LineVertex>& edges) {
  BodyView local;
  local.triangles = body.triangles;
  local.color = glm::vec3(1.0f);
  local.worldVertices.reserve(body.worldVertices.size());
  const glm::mat3 toBody = glm::transpose(body.rotation);  // R^-1 of a rotation
  for (const glm::vec3& p : body.worldVertices) {
    local.worldVertices.push_back(toBody * (p - body.position));
  }
  std::vector<LineVertex> unusedHighlight;
  std::unordered_map<std::uint64_t, EdgeFaces> edgeMap;
  std::vector<glm::vec3> unusedNormals;
  triangles.clear();
  edges.clear();
  addBody(local, {triangles, edges, unusedHighlight, 1.0f}, edgeMap, unusedNormals);
}

void SceneGeometry::clear() {
  bodies.clear();
  arrowHeads.clear();
  ghosts.clear();
  ghostRanges.clear();
  edges.clear();
  highlight.clear();
  ghostEdges.clear();
  axes.clear();
  forceShafts.clear();
}

void buildSceneGeometry(const FrameData& frame, SceneGeometry& out) {
  out.clear();
  std::unordered_map<std::uint64_t, EdgeFaces> edgeMap;
  std::vector<glm::vec3> normals;  // of smooth bodies
  std::vector<const BodyView*> ghosts;
  const BodyTarget opaque{out.bodies, out.edges, out.highlight, 1.0f};
  for (const BodyView& body : frame.bodies) {
    if (!isDrawn(body)) continue;
    if (isGhost(body)) ghosts.push_back(&body);
    else if (!drawnAsInstance(body)) addBody(body, opaque, edgeMap, normals);
    if (frame.options.axes && body.axisLength > 0.0f) addAxes(body, out);
  }
  // Blending is order-dependent: the farthest ghost goes first so nearer ones tint it. Stable,
  // so ghosts at equal distance keep the app's order from frame to frame (no flicker).
  const glm::vec3 eye = frame.camera.eye;
  std::stable_sort(ghosts.begin(), ghosts.end(), [&eye](const BodyView* p, const BodyView* q) {
    return glm::distance(p->position, eye) > glm::distance(q->position, eye);
  });
  for (const BodyView* ghost : ghosts) {
    const int first = static_cast<int>(out.ghosts.size());
    // A ghost's highlight goes with its edges: both must be drawn after the ghost's surface.
    addBody(*ghost, {out.ghosts, out.ghostEdges, out.ghostEdges, ghost->opacity}, edgeMap, normals);
    const int count = static_cast<int>(out.ghosts.size()) - first;
    if (count > 0) out.ghostRanges.push_back({first, count, ghost->opacity});
  }
  for (const ForceArrow& arrow : frame.forces) addForce(arrow, frame.options.forceScale, out);
}

}  // namespace rbsim::render

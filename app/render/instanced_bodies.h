#pragma once
// Bodies that share a rigid mesh, drawn as instances: each distinct mesh is uploaded once (its
// body-space triangles and feature edges), and per frame one buffer of per-body (R, x, colour)
// goes up, so a frame of 1000 boxes costs one draw call per mesh instead of rebuilding 36 000
// world-space vertices and their outlines on the CPU. The caller binds the shader program and
// sets its uniforms; this class owns the buffers and issues the draws.
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "frame_data.h"
#include "gl_api.h"
#include "scene_geometry.h"

namespace rbsim::render {

// One body's per-instance attributes (shader locations 3 to 7), as uploaded.
struct BodyInstance {
  glm::vec3 position;  // x, world frame [m]
  glm::vec3 axes[3];   // columns of R
  glm::vec3 color;     // linear RGB
};

class InstancedBodies {
 public:
  InstancedBodies();
  ~InstancedBodies();
  InstancedBodies(const InstancedBodies&) = delete;
  InstancedBodies& operator=(const InstancedBodies&) = delete;

  // Groups the frame's bodies that are drawnAsInstance by mesh, uploads meshes not seen last
  // frame, the instance buffer, and drops meshes no body used this frame.
  void upload(const FrameData& frame);
  // With mesh_instanced.vert bound: every instance's triangles.
  void drawSurfaces() const;
  // With shadow_instanced.vert bound: the same triangles (position only).
  void drawShadows() const { drawSurfaces(); }
  // With line_instanced.vert bound: every instance's feature edges.
  void drawEdges() const;
  bool empty() const { return batches_.empty(); }

 private:
  struct MeshBuffers {
    std::shared_ptr<const void> owner;  // pins the address used as the key
    GLuint triangleVao = 0, triangleVbo = 0, edgeVao = 0, edgeVbo = 0;
    GLsizei triangleVertices = 0, edgeVertices = 0;
    std::uint64_t lastFrame = 0;
  };
  struct Batch {
    const MeshBuffers* mesh;
    GLuint firstInstance;
    GLsizei count;
  };

  MeshBuffers& meshFor(const BodyView& body);
  void release(MeshBuffers& mesh);

  GLuint instanceVbo_ = 0;
  std::uint64_t frame_ = 0;
  std::unordered_map<const void*, MeshBuffers> meshes_;
  std::vector<Batch> batches_;
  // Reused every frame.
  std::vector<BodyInstance> instances_;
  std::vector<const BodyView*> bodies_;
  std::vector<MeshVertex> shapeTriangles_;
  std::vector<LineVertex> shapeEdges_;
};

}  // namespace rbsim::render

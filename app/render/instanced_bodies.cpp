#include "instanced_bodies.h"

#include <algorithm>
#include <cstddef>

namespace rbsim::render {

namespace {

// Per-vertex attribute 0 (position) and, for triangles, 1 (normal) from the bound mesh buffer;
// per-instance attributes 3 to 7 from the instance buffer, advancing once per instance.
void setInstanceAttributes(GLuint instanceVbo) {
  glBindBuffer(GL_ARRAY_BUFFER, instanceVbo);
  const auto stride = static_cast<GLsizei>(sizeof(BodyInstance));
  const std::size_t offsets[5] = {offsetof(BodyInstance, position), offsetof(BodyInstance, axes),
                                  offsetof(BodyInstance, axes) + sizeof(glm::vec3),
                                  offsetof(BodyInstance, axes) + 2 * sizeof(glm::vec3),
                                  offsetof(BodyInstance, color)};
  for (GLuint k = 0; k < 5; ++k) {
    glEnableVertexAttribArray(3 + k);
    glVertexAttribPointer(3 + k, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsets[k]));
    glVertexAttribDivisor(3 + k, 1);
  }
}

template <typename Vertex>
GLuint uploadStatic(const std::vector<Vertex>& vertices) {
  GLuint vbo = 0;
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  return vbo;
}

}  // namespace

InstancedBodies::InstancedBodies() { glGenBuffers(1, &instanceVbo_); }

InstancedBodies::~InstancedBodies() {
  for (auto& [key, mesh] : meshes_) release(mesh);
  glDeleteBuffers(1, &instanceVbo_);
}

void InstancedBodies::release(MeshBuffers& mesh) {
  glDeleteVertexArrays(1, &mesh.triangleVao);
  glDeleteVertexArrays(1, &mesh.edgeVao);
  glDeleteBuffers(1, &mesh.triangleVbo);
  glDeleteBuffers(1, &mesh.edgeVbo);
}

InstancedBodies::MeshBuffers& InstancedBodies::meshFor(const BodyView& body) {
  MeshBuffers& mesh = meshes_[body.mesh.get()];
  mesh.lastFrame = frame_;
  if (mesh.owner) return mesh;
  // First sight of this mesh: its shape in body space, from this body's world vertices.
  mesh.owner = body.mesh;
  buildBodyShape(body, shapeTriangles_, shapeEdges_);
  mesh.triangleVertices = static_cast<GLsizei>(shapeTriangles_.size());
  mesh.edgeVertices = static_cast<GLsizei>(shapeEdges_.size());
  glGenVertexArrays(1, &mesh.triangleVao);
  glBindVertexArray(mesh.triangleVao);
  mesh.triangleVbo = uploadStatic(shapeTriangles_);
  const auto meshStride = static_cast<GLsizei>(sizeof(MeshVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, meshStride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, meshStride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
  setInstanceAttributes(instanceVbo_);
  glGenVertexArrays(1, &mesh.edgeVao);
  glBindVertexArray(mesh.edgeVao);
  mesh.edgeVbo = uploadStatic(shapeEdges_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(sizeof(LineVertex)),
                        reinterpret_cast<void*>(offsetof(LineVertex, position)));
  setInstanceAttributes(instanceVbo_);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return mesh;
}

void InstancedBodies::upload(const FrameData& frame) {
  ++frame_;
  batches_.clear();
  instances_.clear();
  bodies_.clear();
  for (const BodyView& body : frame.bodies) {
    if (drawnAsInstance(body)) bodies_.push_back(&body);
  }
  // Bodies of one mesh next to each other, meshes in order of first appearance (stable), so each
  // mesh is one contiguous run of instances.
  std::unordered_map<const void*, std::size_t> firstSeen;
  for (const BodyView* body : bodies_) firstSeen.emplace(body->mesh.get(), firstSeen.size());
  std::stable_sort(bodies_.begin(), bodies_.end(), [&firstSeen](const BodyView* p, const BodyView* q) {
    return firstSeen.at(p->mesh.get()) < firstSeen.at(q->mesh.get());
  });
  for (const BodyView* body : bodies_) {
    if (batches_.empty() || batches_.back().mesh->owner != body->mesh) {
      batches_.push_back({&meshFor(*body), static_cast<GLuint>(instances_.size()), 0});
    }
    ++batches_.back().count;
    instances_.push_back(
        {body->position, {body->rotation[0], body->rotation[1], body->rotation[2]}, body->color});
  }
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    if (it->second.lastFrame == frame_) {
      ++it;
    } else {
      release(it->second);
      it = meshes_.erase(it);
    }
  }
  // A fresh glBufferData each frame lets the driver orphan last frame's storage.
  glBindBuffer(GL_ARRAY_BUFFER, instanceVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances_.size() * sizeof(BodyInstance)),
               instances_.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void InstancedBodies::drawSurfaces() const {
  for (const Batch& batch : batches_) {
    glBindVertexArray(batch.mesh->triangleVao);
    glDrawArraysInstancedBaseInstance(GL_TRIANGLES, 0, batch.mesh->triangleVertices, batch.count,
                                      batch.firstInstance);
  }
}

void InstancedBodies::drawEdges() const {
  for (const Batch& batch : batches_) {
    if (batch.mesh->edgeVertices == 0) continue;
    glBindVertexArray(batch.mesh->edgeVao);
    glDrawArraysInstancedBaseInstance(GL_LINES, 0, batch.mesh->edgeVertices, batch.count,
                                      batch.firstInstance);
  }
}

}  // namespace rbsim::render

#pragma once
// Cooking a scene: the second half of loading one. The parser (scene.h's describeScene) reads the
// JSON into a plain description, meshes and mass properties included, and lists in
// Scene::cooking what each distinct shape still needs built for collision: a signed distance grid
// with its surface samples (seed 000 "Constructing Signed Distance Functions"), an implicit
// shape's exact solid, or a static mesh ground's triangle hierarchy. cookScene builds each once
// and hands the bodies that share the shape the same pointers; a SceneCache kept across loads
// (a compared phase's worlds, app/run/phase.h) builds each distinct shape once for all of them.
#include <cstddef>
#include <memory>
#include <string>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct ImplicitShape;  // shapes/implicit_shape.h (private)
struct Scene;          // scene/scene.h

// What the bodies of one shape (those whose BodyDef::mesh is `mesh`) need cooked.
struct CookRequest {
  enum class Kind {
    Grid,       // a grid over the mesh and surface samples, and the triangles' hierarchy
    Implicit,   // the exact function's grid, solid and samples
    Triangles,  // a static mesh ground: the triangles' hierarchy only
  };
  Kind kind = Kind::Grid;
  std::shared_ptr<const Mesh> mesh;  // body space, shared by the bodies of this shape
  int resolution = 32;               // the grid's cells along the mesh's longest side [1]
  // Grid: the samples' spacing, as resolved (0: the vertices). Implicit: the spacing of the mesh's
  // samples moved onto the exact surface beside the sharp ones (0: none).
  double sampleSpacing = 0.0;  // [m]
  std::shared_ptr<const ImplicitShape> implicit;  // Implicit only
  Mat3 axes = Mat3::Identity();  // Implicit only: the body frame in the file's (FileFrame)
  Vec3 centre = Vec3::Zero();    // [m]
  std::string shapeJson;         // Implicit only: the "shape" block as text, which the cache keys on
  // Where a failure is reported: the file and the JSON paths of the body's "shape" and, for an
  // implicit shape's evaluation budget, its "shape.resolution".
  std::string file, shapeField, resolutionField;
};

// The grids, samples, solids and triangle hierarchies cooked so far, keyed by the mesh (by its
// content, so two loads of one file share them) and the request's parameters; and the shapes
// described so far (mesh, mass properties, hull), keyed by the JSON they were read from. Keep one
// for loads of one document that differ in a few keys; a new one reads mesh files again.
class SceneCache {
 public:
  SceneCache();
  ~SceneCache();
  SceneCache(const SceneCache&) = delete;
  SceneCache& operator=(const SceneCache&) = delete;
  std::size_t shapesCooked() const;     // distinct requests built (each a grid or a hierarchy)
  std::size_t shapesDescribed() const;  // distinct shape keys read and built

  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// Builds what scene.cooking asks for (through `cache` when given) and sets it on every body and
// spawner prototype of that shape, then empties scene.cooking. A scene with nothing to cook is
// left as it was. Throws InputError naming the body's field when a grid cannot be built.
void cookScene(Scene& scene, SceneCache* cache = nullptr);

}  // namespace rbsim

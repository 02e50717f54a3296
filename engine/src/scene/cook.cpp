#include "rbsim/scene/cook.h"

#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include "geometry/feature_points.h"
#include "geometry/surface_samples.h"
#include "geometry/triangle_bvh.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "scene/scene_cache.h"
#include "shapes/implicit_shape.h"

namespace rbsim {

namespace scene_detail {

namespace {

// FNV-1a, 64 bits (Fowler, Noll and Vo; the IETF draft "The FNV Non-Cryptographic Hash
// Algorithm"): a hash of the mesh's bytes that picks the bucket; equal contents decide a hit.
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;  // [1]
constexpr std::uint64_t kFnvPrime = 1099511628211ull;          // [1]

void hashBytes(std::uint64_t& h, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * kFnvPrime;
}

template <class T>
void hashValue(std::uint64_t& h, const T& value) {
  hashBytes(h, &value, sizeof value);
}

std::uint64_t meshHash(const Mesh& mesh) {
  std::uint64_t h = kFnvOffset;
  for (const Vec3& v : mesh.vertices) hashBytes(h, v.data(), 3 * sizeof(double));
  if (!mesh.triangles.empty()) hashBytes(h, mesh.triangles.data(), mesh.triangles.size() * sizeof(Triangle));
  return h;
}

// The request's parameters, bit for bit, and its mesh's hash: what the cache buckets by.
std::string keyOf(const CookRequest& r) {
  std::uint64_t h = kFnvOffset;
  hashValue(h, r.kind);
  hashValue(h, r.resolution);
  hashValue(h, r.sampleSpacing);
  if (r.kind == CookRequest::Kind::Implicit) {
    hashBytes(h, r.axes.data(), 9 * sizeof(double));
    hashBytes(h, r.centre.data(), 3 * sizeof(double));
  }
  const std::uint64_t parameters = h, mesh = meshHash(*r.mesh);
  std::string key(2 * sizeof(std::uint64_t), '\0');
  std::memcpy(key.data(), &parameters, sizeof parameters);
  std::memcpy(key.data() + sizeof parameters, &mesh, sizeof mesh);
  return r.kind == CookRequest::Kind::Implicit ? key + r.shapeJson : key;
}

bool sameMesh(const Mesh& a, const Mesh& b) {
  return &a == &b || (a.vertices == b.vertices && a.triangles == b.triangles);
}

Cooked build(const CookRequest& r) {
  Cooked c;
  const Mesh& mesh = *r.mesh;
  try {
    if (r.kind == CookRequest::Kind::Triangles) {
      c.triangles = std::make_shared<const TriangleBvh>(mesh);
      return c;
    }
    SdfGridOptions options;
    options.resolution = r.resolution;
    if (r.kind == CookRequest::Kind::Grid) {
      c.sdf = std::make_shared<const SignedDistanceGrid>(SignedDistanceGrid::build(mesh, options));
      c.surfaceSamples = std::make_shared<const std::vector<Vec3>>(surfaceSamples(mesh, r.sampleSpacing));
      c.triangles = std::make_shared<const TriangleBvh>(mesh);
      return c;
    }
    // An implicit body collides through its exact function: one sharp sample per surface cell of
    // its grid, and the mesh's samples at the asked spacing moved onto the exact surface.
    ImplicitBudget* budget = r.implicit->budget.get();
    c.sdf = std::make_shared<const SignedDistanceGrid>(implicitBodyGrid(*r.implicit, mesh, r.axes, r.centre));
    auto solid = std::make_shared<const ImplicitSolid>(implicitSolidOf(*r.implicit, r.axes, r.centre));
    std::vector<Vec3> samples = implicitSurfaceSamples(*solid, *c.sdf, budget);
    if (r.sampleSpacing > 0.0) {
      const ExactField field = implicitField(*solid, budget);
      for (const Vec3& p : surfaceSamples(mesh, r.sampleSpacing)) {
        samples.push_back(projectOntoSurface(p, field, kCrossingTolerance * c.sdf->cellSize()));
      }
    }
    c.surfaceSamples = std::make_shared<const std::vector<Vec3>>(std::move(samples));
    c.implicit = std::move(solid);
  } catch (const ImplicitBudgetExceeded& e) {  // the shape's resolution and its tree's size set the cost
    throw InputError(r.file, r.resolutionField, std::string(e.what()) + "; use a lower resolution or fewer primitives");
  } catch (const std::invalid_argument& e) {
    throw InputError(r.file, r.shapeField, std::string("no signed distance grid for this shape: ") + e.what());
  }
  return c;
}

}  // namespace

Cooked CookCache::cook(const CookRequest& request) {
  std::vector<Entry>& bucket = entries_[keyOf(request)];
  for (const Entry& e : bucket) {
    if (sameMesh(*e.mesh, *request.mesh)) return e.cooked;
  }
  bucket.push_back({request.mesh, build(request)});
  ++count_;
  return bucket.back().cooked;
}

}  // namespace scene_detail

SceneCache::SceneCache() : impl_(std::make_unique<Impl>()) {}
SceneCache::~SceneCache() = default;
std::size_t SceneCache::shapesCooked() const { return impl_->cooked.size(); }
std::size_t SceneCache::shapesDescribed() const { return impl_->shapes.size(); }

void cookScene(Scene& scene, SceneCache* cache) {
  if (scene.cooking.empty()) return;
  SceneCache own;
  scene_detail::CookCache& cooker = (cache != nullptr ? cache : &own)->impl().cooked;
  // By mesh object: the bodies of one described shape share it (and spawned copies their
  // prototype's), so one lookup a body finds what its shape cooked to.
  std::unordered_map<const Mesh*, scene_detail::Cooked> byMesh;
  for (const CookRequest& request : scene.cooking) byMesh.emplace(request.mesh.get(), cooker.cook(request));
  const auto apply = [&](BodyDef& def) {
    const auto it = byMesh.find(def.mesh.get());
    if (it == byMesh.end()) return;
    def.sdf = it->second.sdf;
    def.surfaceSamples = it->second.surfaceSamples;
    def.implicit = it->second.implicit;
    def.triangles = it->second.triangles;
  };
  for (BodyDef& def : scene.bodies) apply(def);
  for (SpawnerDef& spawner : scene.spawners) apply(spawner.prototype);
  scene.cooking.clear();
}

}  // namespace rbsim

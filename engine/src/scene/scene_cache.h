#pragma once
// What a SceneCache (rbsim/scene/cook.h) holds: the shapes the parser described and the grids and
// hierarchies cookScene built. Internal to scene/.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "rbsim/scene/cook.h"
#include "scene/body_parser.h"

namespace rbsim {

class SignedDistanceGrid;
struct ImplicitSolid;
class TriangleBvh;

namespace scene_detail {

// What one request cooked: the pointers every body of its shape shares.
struct Cooked {
  std::shared_ptr<const SignedDistanceGrid> sdf;
  std::shared_ptr<const std::vector<Vec3>> surfaceSamples;
  std::shared_ptr<const ImplicitSolid> implicit;
  std::shared_ptr<const TriangleBvh> triangles;
};

// Requests cooked so far, by their parameters and their mesh's content: a request whose mesh is
// another object with the same vertices and triangles (the same file described again for another
// compared value) finds what the first one built.
class CookCache {
 public:
  // What `request` cooks to, built on its first call.
  Cooked cook(const CookRequest& request);
  std::size_t size() const { return count_; }

 private:
  struct Entry {
    std::shared_ptr<const Mesh> mesh;
    Cooked cooked;
  };
  std::unordered_map<std::string, std::vector<Entry>> entries_;  // by parameters and a hash of the mesh
  std::size_t count_ = 0;
};

}  // namespace scene_detail

struct SceneCache::Impl {
  scene_detail::ShapeCache shapes;
  scene_detail::CookCache cooked;
};

}  // namespace rbsim

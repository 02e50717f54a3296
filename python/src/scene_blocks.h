#pragma once
// What World.save_scene writes (issue 57): the blocks a World built in Python was given, as the
// scene format's JSON (add_body's keys are those of an entry of "bodies", and so on), kept beside
// the World, so a scene file holding them loads back into the same World through the same parser.
// A block is kept as given, each double as its bits (nlohmann::json dumps the shortest text that
// reads back as the same double), and written with the state its body has now.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbsim/integrate/body_state.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::python {

class SceneBlocks {
 public:
  // A World loaded from a scene file keeps no blocks: save_scene names `file` and refuses.
  void loadedFrom(const std::string& file) { loadedFrom_ = file; }
  // `block` named, as the body `body` (id `id`) was made from it, in its state as made.
  void addBody(BodyId id, nlohmann::json block, const RigidBody& body);
  void addForce(BodyId id, nlohmann::json force);  // onto the body's "forces"
  void addPlane(nlohmann::json block) { planes_.push_back(std::move(block)); }
  void addSpawner(nlohmann::json block) { spawners_.push_back(std::move(block)); }
  void addJoint(nlohmann::json block, const Joint& made);

  // The scene file of `world` now, with `scene`'s title and `world`'s settings. InputError
  // naming `call` when the World holds what a scene file cannot say: a body it was not given (a
  // spawned one, a broken piece), or, once time has run, anything timed from the start (joints,
  // whose anchors and limits are read at the bodies' poses when made; spawners; set_pose blocks;
  // kinematic motions; forces with a start or an end), since a scene's clock starts at 0.
  nlohmann::json document(const World& world, const Scene& scene, const char* call) const;

 private:
  using Key = std::pair<std::uint32_t, std::uint32_t>;  // BodyId's slot, generation
  struct Body {
    nlohmann::json block;
    BodyState made;  // its state when added: a body still in it is written as given
  };
  struct JointBlock {
    nlohmann::json block;
    Key a, b;
    std::string name;
  };
  nlohmann::json bodyBlock(const RigidBody& body, const Body& kept) const;

  std::string loadedFrom_;
  std::map<Key, Body> bodies_;  // never erased: World.set_state may bring a removed body back
  std::vector<nlohmann::json> planes_, spawners_;
  std::vector<JointBlock> joints_;
};

// `document` into `path`, whole or not at all (render/checked_file.h: a temporary file renamed
// into place); InputError naming the file, `call` and the OS's reason.
void writeTextFile(const std::string& path, const std::string& text, const char* call);

}  // namespace rbsim::python

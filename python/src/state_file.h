#pragma once
// A State as bytes (issue 57): the pickle of rbsim.State and the file State.save writes are the
// same CBOR document (nlohmann::json::to_cbor): {"format": "rbsim-state", "version", "scene" (the
// scene file the World was built from, or "World()"), "world" (the number of the World that gave
// it), "time", "step_count", "bodies", "inertia" (the bodies' inertia methods, as the Scene keeps them), "snapshot" (binary: the World's
// snapshot, engine/include/rbsim/world/world_snapshot.h)}.
#include <memory>
#include <string>

#include "py_world.h"

namespace rbsim::python {

// InputError naming `call` for a state whose World cannot be saved (step listeners, LCP).
std::string stateBytes(const PyWorld::Saved& state, const char* call);
// InputError naming `source` (a file, "State.__setstate__()") for bytes that are not a state.
std::shared_ptr<PyWorld::Saved> stateFromBytes(const std::string& bytes, const std::string& source);
// Written whole or not at all: a temporary file beside `path`, renamed over it.
void saveStateFile(const PyWorld::Saved& state, const std::string& path);
std::shared_ptr<PyWorld::Saved> loadStateFile(const std::string& path);

}  // namespace rbsim::python

// A State as bytes: pickled, or saved to a file (state_file.h).
#include "state_file.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "rbsim/io/input_error.h"
#include "rbsim/world/world_snapshot.h"

namespace rbsim::python {

namespace {

constexpr const char* kFormat = "rbsim-state";
constexpr int kStateVersion = 1;

// The value of `key`, of the JSON type `is` accepts, or InputError naming the source and the key.
template <typename Is>
const nlohmann::json& field(const nlohmann::json& doc, const char* key, Is is, const std::string& source,
                            const char* expected) {
  if (!doc.contains(key) || !is(doc.at(key))) throw InputError(source, key, std::string("expected ") + expected);
  return doc.at(key);
}

}  // namespace

std::string stateBytes(const PyWorld::Saved& state, const char* call) {
  nlohmann::json doc;
  doc["format"] = kFormat;
  doc["version"] = kStateVersion;
  doc["world"] = state.serial;
  doc["time"] = state.time;
  doc["step_count"] = state.stepCount;
  doc["bodies"] = state.bodyCount;
  if (state.world) {
    std::vector<std::uint8_t> snapshot;
    try {
      snapshot = saveWorldSnapshot(*state.world);
    } catch (const std::invalid_argument& e) {
      throw InputError(call, "state", e.what());
    }
    doc["scene"] = state.scene.file;
    doc["inertia"] = state.scene.inertiaMethods;
    doc["snapshot"] = nlohmann::json::binary(std::move(snapshot));
  } else {
    doc["scene"] = state.scene.file;
    doc["inertia"] = state.inertiaMethods;
    doc["snapshot"] = nlohmann::json::binary(state.snapshot);
  }
  const std::vector<std::uint8_t> cbor = nlohmann::json::to_cbor(doc);
  return std::string(cbor.begin(), cbor.end());
}

std::shared_ptr<PyWorld::Saved> stateFromBytes(const std::string& bytes, const std::string& source) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::from_cbor(bytes);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source, "", std::string("not an rbsim state (expected what State.save writes): ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("format") || doc.at("format") != kFormat) {
    throw InputError(source, "format", "expected \"rbsim-state\" (what State.save writes)");
  }
  const auto isInt = [](const nlohmann::json& j) { return j.is_number_unsigned(); };
  if (field(doc, "version", isInt, source, "a version number") != kStateVersion) {
    throw InputError(source, "version", "expected " + std::to_string(kStateVersion) + " (this build's), found " +
                                            doc.at("version").dump());
  }
  auto state = std::make_shared<PyWorld::Saved>();
  state->scene.file = field(doc, "scene", [](const nlohmann::json& j) { return j.is_string(); }, source, "a scene file").get<std::string>();
  state->serial = field(doc, "world", isInt, source, "a World number").get<std::uint64_t>();
  state->time = field(doc, "time", [](const nlohmann::json& j) { return j.is_number(); }, source, "a time [s]").get<double>();
  state->stepCount = field(doc, "step_count", isInt, source, "a step count").get<std::uint64_t>();
  state->bodyCount = field(doc, "bodies", isInt, source, "a body count").get<std::size_t>();
  const nlohmann::json& inertia = field(doc, "inertia", [](const nlohmann::json& j) { return j.is_array(); }, source,
                                        "a list of inertia methods");
  for (const nlohmann::json& method : inertia) {
    if (!method.is_string()) throw InputError(source, "inertia", "expected a list of inertia methods");
    state->inertiaMethods.push_back(method.get<std::string>());
  }
  state->snapshot = field(doc, "snapshot", [](const nlohmann::json& j) { return j.is_binary(); }, source,
                          "the World's snapshot (binary)").get_binary();
  try {
    checkWorldSnapshot(state->snapshot.data(), state->snapshot.size(), source);
  } catch (const std::invalid_argument& e) {
    throw InputError(source, "snapshot", e.what());
  }
  return state;
}

void saveStateFile(const PyWorld::Saved& state, const std::string& path) {
  const std::string bytes = stateBytes(state, "State.save()");
  // Beside the target, so the rename stays on one file system and replaces it in one step.
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::remove(temporary.c_str());
      throw InputError(path, "", "cannot write the state (" + std::string(std::strerror(errno)) + ")");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw InputError(path, "", "cannot write the state (" + reason + ")");
  }
}

std::shared_ptr<PyWorld::Saved> loadStateFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the state file (" + std::string(std::strerror(errno)) + ")");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::shared_ptr<PyWorld::Saved> state = stateFromBytes(bytes.str(), path);
  state->source = path;
  return state;
}

}  // namespace rbsim::python

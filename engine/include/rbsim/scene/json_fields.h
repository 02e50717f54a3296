#pragma once
// Strict reading of one JSON object of a scene: every field is checked for type, range and
// finiteness, unknown keys are rejected with the nearest known key suggested, and every error
// names the file and the JSON path (e.g. "bodies[1].shape.extents").
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbsim/math/format_number.h"  // formatNumber, for the parsers' messages
#include "rbsim/math/types.h"
#include "rbsim/scene/scene_keys.h"

namespace rbsim {

// The keys an object allows: a table of scene_keys.h or a list written in place.
class KeyNames {
 public:
  // Held for the call it is passed to, within the full expression that made the list.
  KeyNames(std::initializer_list<const char*> names) : names_(names), count_(names.size()) {}  // NOLINT: implicit
  KeyNames(const KeyTable& table) : keys_(table.data), count_(table.size()) {}  // NOLINT: implicit
  std::size_t size() const { return count_; }
  const char* operator[](std::size_t i) const { return keys_ != nullptr ? keys_[i].name : names_.begin()[i]; }

 private:
  std::initializer_list<const char*> names_;
  const SceneKey* keys_ = nullptr;
  std::size_t count_ = 0;
};

class JsonObject {
 public:
  // Throws InputError if `value` is not an object or has a key outside `allowed`.
  JsonObject(const nlohmann::json& value, std::string file, std::string path, KeyNames allowed);

  bool has(const char* key) const { return value_.contains(key); }
  std::string pathOf(const char* key) const;
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  const nlohmann::json& raw(const char* key) const { return value_.at(key); }

  double number(const char* key, double fallback) const;
  double requiredNumber(const char* key) const;
  double positiveNumber(const char* key, double fallback) const;  // > 0
  std::optional<double> optionalPositive(const char* key) const;
  int positiveInt(const char* key, int fallback) const;  // in [1, kMaxCount]
  // Keys that belong to another variant of this object (a sphere's "extents") are an error
  // naming `owner`, e.g. "a \"sphere\" shape", and listing the keys that apply.
  void allowOnly(KeyNames keys, const std::string& owner) const;
  bool boolean(const char* key, bool fallback) const;
  std::string string(const char* key, const std::string& fallback) const;
  std::string requiredString(const char* key) const;
  Vec3 vec3(const char* key, const Vec3& fallback) const;
  std::optional<Vec3> optionalVec3(const char* key) const;
  // A vector whose length may be at most `limit` (scene/input_ranges.h); `what` names the
  // limit in the message, e.g. "the speed of light".
  Vec3 boundedVec3(const char* key, const Vec3& fallback, double limit, const char* unit, const char* what) const;
  Vec3 positiveVec3(const char* key) const;  // required, every component > 0
  // Orientation: {"quaternion": [w,x,y,z]} | {"matrix": [[r11,r12,r13],...]} |
  // {"axis_angle_deg": [ax, ay, az, degrees]}; must be a rotation, never silently normalised:
  // only with "normalize": true is a quaternion normalised and a matrix replaced by the nearest
  // rotation (a matrix of determinant <= 0 is refused even then).
  std::optional<Quat> optionalOrientation(const char* key) const;
  JsonObject object(const char* key, KeyNames allowed) const;
  std::vector<JsonObject> objectArray(const char* key, KeyNames allowed) const;

  [[noreturn]] void fail(const char* key, const std::string& problem) const;

 private:
  std::vector<double> numbers(const char* key, std::size_t count) const;

  const nlohmann::json& value_;
  std::string file_;
  std::string path_;
};

// The known key nearest to `key` by edit distance, or "" when none is close.
std::string nearestKey(const std::string& key, const std::vector<std::string>& known);

}  // namespace rbsim

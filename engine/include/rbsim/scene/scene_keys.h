#pragma once
// The keys of a scene file's blocks as tables: each key's name, JSON type, range and a one-line
// description. The parser takes the names from these tables for its unknown-key checks
// (JsonObject, json_fields.h); the schema generator (scene_schema.h) takes everything, so
// docs/scene.schema.json and the parser read one list. Ranges name the parser's own constants
// (settings.h, scene/input_ranges.h); tests/python/test_scene_schema.py holds the parser to them.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace rbsim {

// The largest count any integer key accepts; each key's own budget is usually lower.
inline constexpr long long kMaxCount = 1'000'000'000;

// A key's JSON value. Vec3 is [x, y, z]; NumberArray and IntegerArray an array of `length`
// numbers (any length when 0); Vec3Array an array of [x, y, z]; Orientation the orientation object of json_fields.h;
// NumberOrChoice a number or one of `choices` ("auto"); Any a value the table leaves to its parser.
enum class KeyType {
  Number, Integer, Boolean, String, Vec3, NumberArray, IntegerArray, Vec3Array, Matrix3, StringArray, Orientation, Object, ObjectArray,
  NumberOrChoice, Any
};

struct KeyTable;
struct KeyVariant;

// A list of names, constant: an enum's choices.
struct NameList {
  const char* const* names = nullptr;
  std::size_t count = 0;
  template <std::size_t N>
  constexpr NameList(const char* const (&list)[N]) : names(list), count(N) {}  // NOLINT: implicit by design
  constexpr NameList() = default;
};

struct SceneKey {
  const char* name = "";
  KeyType type = KeyType::Any;
  const char* description = "";
  // Numbers, and each component of a vector: within [minimum, maximum], each end open or not.
  double minimum = -std::numeric_limits<double>::infinity();
  double maximum = std::numeric_limits<double>::infinity();
  bool exclusiveMinimum = false;
  bool exclusiveMaximum = false;
  bool required = false;
  std::size_t length = 0;                    // NumberArray: its length (0: any)
  std::size_t minItems = 0;                  // arrays: the fewest elements
  NameList choices;                          // String (an enum) and NumberOrChoice
  std::vector<std::string> (*choicesOf)() = nullptr;  // an enum whose names the engine lists at run time
  const KeyTable* keys = nullptr;            // Object and ObjectArray: the keys of the object
  const KeyVariant* variants = nullptr;      // the object's keys by its "type" (shapes, joints)
  std::size_t variantCount = 0;

  // A table iterates as names, as the plain lists it replaced did.
  constexpr operator const char*() const { return name; }  // NOLINT: implicit by design

  constexpr SceneKey atLeast(double v) const { SceneKey k = *this; k.minimum = v; k.exclusiveMinimum = false; return k; }
  constexpr SceneKey above(double v) const { SceneKey k = *this; k.minimum = v; k.exclusiveMinimum = true; return k; }
  constexpr SceneKey atMost(double v) const { SceneKey k = *this; k.maximum = v; k.exclusiveMaximum = false; return k; }
  constexpr SceneKey below(double v) const { SceneKey k = *this; k.maximum = v; k.exclusiveMaximum = true; return k; }
  constexpr SceneKey within(double lo, double hi) const { return atLeast(lo).atMost(hi); }
  // Each component within +-limit: what a bound on a vector's length implies of its components.
  constexpr SceneKey magnitude(double limit) const { return within(-limit, limit); }
  constexpr SceneKey oneOf(NameList names) const { SceneKey k = *this; k.choices = names; return k; }
  constexpr SceneKey oneOf(std::vector<std::string> (*names)()) const { SceneKey k = *this; k.choicesOf = names; return k; }
  constexpr SceneKey of(const KeyTable& table) const { SceneKey k = *this; k.keys = &table; return k; }
  template <std::size_t N>
  constexpr SceneKey byType(const KeyVariant (&list)[N]) const {
    SceneKey k = *this;
    k.variants = list;
    k.variantCount = N;
    return k;
  }
  constexpr SceneKey sized(std::size_t n) const { SceneKey k = *this; k.length = n; return k; }
  constexpr SceneKey nonEmpty() const { SceneKey k = *this; k.minItems = 1; return k; }
  constexpr SceneKey needed() const { SceneKey k = *this; k.required = true; return k; }
};

constexpr SceneKey key(const char* name, KeyType type, const char* description) {
  SceneKey k;
  k.name = name;
  k.type = type;
  k.description = description;
  return k;
}

// The keys of one JSON object of a scene; iterates as SceneKey (and so as names).
struct KeyTable {
  const SceneKey* data = nullptr;
  std::size_t count = 0;
  const char* description = "";
  template <std::size_t N>
  constexpr KeyTable(const SceneKey (&table)[N], const char* what = "") : data(table), count(N), description(what) {}

  constexpr const SceneKey* begin() const { return data; }
  constexpr const SceneKey* end() const { return data + count; }
  constexpr std::size_t size() const { return count; }
};

// The entry of `table` named `name`, for a table that takes some of another's keys (a spawn
// block's body template); a name the table lacks does not compile.
template <std::size_t N>
constexpr SceneKey pick(const SceneKey (&table)[N], const char* name) {
  for (std::size_t i = 0; i < N; ++i) {
    const char* a = table[i].name;
    const char* b = name;
    while (*a != '\0' && *a == *b) ++a, ++b;
    if (*a == *b) return table[i];
  }
  throw "pick: no such key";  // in a constant expression: a compile error
}

// The keys an object takes when its "type" is `value` (a box shape, a hinge joint).
struct KeyVariant {
  const char* value;
  const KeyTable* keys;
  const char* description;
};

// An orientation (JsonObject::optionalOrientation): exactly one of the first four, and "normalize".
inline constexpr SceneKey kOrientationKeyTable[] = {
    key("quaternion", KeyType::NumberArray, "unit quaternion [w, x, y, z]").sized(4),
    key("matrix", KeyType::Matrix3, "rotation matrix, rows [[r11, r12, r13], ...]"),
    key("axis_angle_deg", KeyType::NumberArray, "[ax, ay, az, degrees], a non-zero axis").sized(4),
    key("euler_zyx_deg", KeyType::NumberArray, "[yaw, pitch, roll] in degrees: z, then the new y, then the newest x").sized(3),
    key("normalize", KeyType::Boolean, "normalise a quaternion, or take the rotation nearest a matrix"),
};
inline constexpr KeyTable kOrientationKeys{kOrientationKeyTable, "an orientation: exactly one of quaternion, matrix, axis_angle_deg, euler_zyx_deg"};

}  // namespace rbsim

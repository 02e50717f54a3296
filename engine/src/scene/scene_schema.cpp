// The schema is the key tables written out (scene_keys.h): each table an object whose keys are
// the only ones allowed (the parser refuses any other), each key its type and range. Keywords are
// JSON Schema 2020-12's (https://json-schema.org/draft/2020-12/json-schema-validation).
#include "rbsim/scene/scene_schema.h"

#include <cmath>
#include <string>
#include <vector>

#include "scene/scene_file_keys.h"

namespace rbsim {

namespace {

using json = nlohmann::json;

// A bound as JSON: a whole number as an integer (1000000, not 1000000.0) while a double holds it
// exactly.
json number(double x) {
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
  if (x == std::floor(x) && std::abs(x) <= kExactIntegers) return static_cast<long long>(x);
  return x;
}

// The range of a number (or of each component of a vector).
json ranged(const char* type, const SceneKey& k) {
  json s = {{"type", type}};
  if (std::isfinite(k.minimum)) s[k.exclusiveMinimum ? "exclusiveMinimum" : "minimum"] = number(k.minimum);
  if (std::isfinite(k.maximum)) s[k.exclusiveMaximum ? "exclusiveMaximum" : "maximum"] = number(k.maximum);
  return s;
}

std::vector<std::string> choicesOf(const SceneKey& k) {
  if (k.choicesOf != nullptr) return k.choicesOf();
  return std::vector<std::string>(k.choices.names, k.choices.names + k.choices.count);
}

json arrayOf(json items, std::size_t length, std::size_t minItems) {
  json s = {{"type", "array"}, {"items", std::move(items)}};
  if (length > 0) {
    s["minItems"] = length;
    s["maxItems"] = length;
  } else if (minItems > 0) {
    s["minItems"] = minItems;
  }
  return s;
}

json objectSchema(const KeyTable& table, const KeyVariant* variants, std::size_t variantCount);

json keySchema(const SceneKey& k) {
  json s;
  switch (k.type) {
    case KeyType::Number: s = ranged("number", k); break;
    case KeyType::Integer: s = ranged("integer", k); break;
    case KeyType::Boolean: s = {{"type", "boolean"}}; break;
    case KeyType::String:
      s = {{"type", "string"}};
      if (k.choices.count > 0 || k.choicesOf != nullptr) s["enum"] = choicesOf(k);
      break;
    case KeyType::Vec3: s = arrayOf(ranged("number", k), 3, 0); break;
    case KeyType::NumberArray: s = arrayOf(ranged("number", k), k.length, k.minItems); break;
    case KeyType::IntegerArray: s = arrayOf(ranged("integer", k), k.length, k.minItems); break;
    case KeyType::Vec3Array: s = arrayOf(arrayOf(ranged("number", k), 3, 0), 0, k.minItems); break;
    case KeyType::Matrix3: s = arrayOf(arrayOf({{"type", "number"}}, 3, 0), 3, 0); break;
    case KeyType::StringArray:
      s = arrayOf({{"type", "string"}}, 0, k.minItems);
      if (k.choices.count > 0 || k.choicesOf != nullptr) {
        s["items"]["enum"] = choicesOf(k);
        s["uniqueItems"] = true;
      }
      break;
    case KeyType::Orientation: s = {{"$ref", "#/$defs/orientation"}}; break;
    case KeyType::Object:
      s = k.keys != nullptr ? objectSchema(*k.keys, k.variants, k.variantCount) : json{{"type", "object"}};
      break;
    case KeyType::ObjectArray:
      s = arrayOf(k.keys != nullptr ? objectSchema(*k.keys, k.variants, k.variantCount) : json{{"type", "object"}}, 0, k.minItems);
      break;
    case KeyType::NumberOrChoice: s = {{"anyOf", {ranged("number", k), {{"enum", choicesOf(k)}}}}}; break;
    case KeyType::Any: break;
  }
  s["description"] = k.description;
  return s;
}

// An object of exactly the table's keys. With variants, the keys also depend on its "type": each
// variant adds an if/then whose "then" allows only that type's keys, with that type's ranges.
json objectSchema(const KeyTable& table, const KeyVariant* variants, std::size_t variantCount) {
  json s = {{"type", "object"}, {"additionalProperties", false}, {"properties", json::object()}};
  if (table.description[0] != '\0') s["description"] = table.description;
  json required = json::array();
  for (const SceneKey& k : table) {
    s["properties"][k.name] = keySchema(k);
    if (k.required) required.push_back(k.name);
  }
  if (!required.empty()) s["required"] = required;
  if (variantCount == 0) return s;
  json types = json::array(), cases = json::array();
  for (std::size_t i = 0; i < variantCount; ++i) {
    const KeyVariant& v = variants[i];
    types.push_back(v.value);
    json then = objectSchema(*v.keys, nullptr, 0);
    then["properties"]["type"] = {{"const", v.value}, {"description", v.description}};
    cases.push_back({{"if", {{"properties", {{"type", {{"const", v.value}}}}}, {"required", json::array({"type"})}}}, {"then", then}});
  }
  s["properties"]["type"]["enum"] = types;
  s["allOf"] = cases;
  return s;
}

}  // namespace

json sceneSchema() {
  json root = objectSchema(scene_detail::kSceneKeys, nullptr, 0);
  root["properties"]["compare"] = keySchema(key("compare", KeyType::Object, "worlds that differ in one key, side by side (rbsim run)").of(kCompareKeys));
  json orientation = objectSchema(kOrientationKeys, nullptr, 0);
  json exactlyOne = json::array();
  for (const char* form : {"quaternion", "matrix", "axis_angle_deg", "euler_zyx_deg"}) exactlyOne.push_back({{"required", json::array({form})}});
  orientation["oneOf"] = exactlyOne;
  json document = {{"$schema", "https://json-schema.org/draft/2020-12/schema"}, {"title", "rbsim scene"}};
  document.update(root);
  document["$defs"] = {{"orientation", orientation}};
  return document;
}

}  // namespace rbsim

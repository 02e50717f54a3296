// The --set flag: "path=value" assignments applied to a scene document before it is checked,
// so an override is validated exactly like the same key written in the file.
#include <string>
#include <vector>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"
#include "rbsim/scene/strict_json.h"

namespace rbsim {

namespace {

bool isIndex(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

std::vector<std::string> splitScenePath(const std::string& path) {
  std::vector<std::string> parts;
  std::string current;
  for (char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!current.empty()) parts.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) parts.push_back(current);
  return parts;
}

void applyOverride(nlohmann::json& document, const std::string& assignment) {
  // Keys and bare-word values go into the document as they are; a scene file's text is checked for
  // UTF-8 by the JSON parser, and so must these be, or the document could not be written out again
  // (nlohmann's dump throws on the first invalid byte; found by tests/fuzz's set fuzzer).
  try {
    static_cast<void>(nlohmann::json(assignment).dump());
  } catch (const nlohmann::json::type_error&) {
    throw InputError("", "--set", "expected UTF-8 text; the assignment has a byte that is not");
  }
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("", "--set", "expected key=value (e.g. world.dt=0.001), got \"" + assignment + "\"");
  }
  const std::vector<std::string> parts = splitScenePath(assignment.substr(0, eq));
  if (parts.empty()) {
    throw InputError("", "--set", "expected a key before '=' (e.g. world.dt=0.001), got \"" + assignment + "\"");
  }
  const std::string text = assignment.substr(eq + 1);
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) {
    value = text;  // a bare word such as rk4 or cube is a string
  } else {
    try {
      value = parseStrictJson(text, "");  // duplicate keys are refused in a value too
    } catch (const InputError& e) {
      throw InputError("", "--set", "in the value, " + e.field() + ": " + e.problem());
    }
  }

  nlohmann::json* node = &document;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (node->is_array()) {
      std::size_t index = node->size();
      if (isIndex(part)) {
        // Digits beyond any array's length (and beyond what stoul takes) name no element.
        index = part.size() <= 9 ? std::stoul(part) : node->size();
      } else {  // an element by its "name"
        for (std::size_t k = 0; k < node->size(); ++k) {
          const nlohmann::json& element = (*node)[k];
          if (element.is_object() && element.contains("name") && element["name"] == part) index = k;
        }
      }
      if (index >= node->size()) {
        std::vector<std::string> names;
        for (const nlohmann::json& element : *node) {
          if (element.is_object() && element.contains("name") && element["name"].is_string()) {
            names.push_back(element["name"].get<std::string>());
          }
        }
        const std::string near = isIndex(part) ? "" : nearestKey(part, names);
        throw InputError("", "--set", "\"" + part + "\" names no element of the array (it has " +
                                          std::to_string(node->size()) + ", indexed from 0 or by name)" +
                                          (near.empty() ? "" : "; did you mean \"" + near + "\"?"));
      }
      node = &(*node)[index];
    } else {
      if (node->is_null()) *node = nlohmann::json::object();
      if (!node->is_object()) throw InputError("", "--set", "\"" + part + "\" is inside a value that is not an object");
      node = &(*node)[part];
    }
  }
  *node = value;
}

}  // namespace rbsim

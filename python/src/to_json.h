#pragma once
// Python values as the JSON of a scene file, so keyword arguments go through the scene loader's
// checks and messages (engine/include/rbsim/scene/scene_parts.h) instead of a second set of rules.
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace rbsim::python {

// dict -> object (string keys), list, tuple and NumPy array -> array, bool, int, float (NaN and
// infinities kept, for the loader to refuse by field), str, None -> null. Throws InputError
// naming `path` for anything else (an object the scene format has no word for).
nlohmann::json toJson(const pybind11::handle& value, const std::string& file, const std::string& path);

// Keyword arguments as one JSON object.
nlohmann::json toJson(const pybind11::kwargs& kwargs, const std::string& file, const std::string& path);

}  // namespace rbsim::python

#include "to_json.h"

#include <string>

#include "rbsim/io/input_error.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// Nesting deeper than any scene block (a body's forces hold vectors: four levels) is a mistake,
// and a self-containing list would otherwise recurse until the stack ran out.
constexpr int kMaxDepth = 32;

nlohmann::json convert(const py::handle& value, const std::string& file, const std::string& path, int depth) {
  if (depth > kMaxDepth) throw InputError(file, path, "nested deeper than " + std::to_string(kMaxDepth) + " levels");
  if (value.is_none()) return nullptr;
  // bool before int: True is an int in Python.
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    // As a scene file's integers parse (nlohmann::json): one >= 0 unsigned, so that hull indices
    // and filter masks with bit 63 read as they do from a file; a negative one signed.
    try {
      return value.cast<unsigned long long>();
    } catch (const py::cast_error&) {
    }
    try {
      return value.cast<long long>();
    } catch (const py::cast_error&) {
      return value.cast<double>();  // beyond 64 bits: the loader's ranges refuse it by field
    }
  }
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) throw InputError(file, path, "expected string keys, got " + std::string(py::repr(key)));
      const std::string name = key.cast<std::string>();
      object[name] = convert(item, file, path.empty() ? name : path + "." + name, depth + 1);
    }
    return object;
  }
  // NumPy arrays and scalars: through tolist()/item(), which give plain Python numbers.
  if (py::hasattr(value, "tolist") && !py::isinstance<py::list>(value)) {
    return convert(value.attr("tolist")(), file, path, depth + 1);
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json array = nlohmann::json::array();
    std::size_t i = 0;
    for (const py::handle item : value) {
      array.push_back(convert(item, file, path + "[" + std::to_string(i) + "]", depth + 1));
      ++i;
    }
    return array;
  }
  throw InputError(file, path, "expected a number, string, bool, list or dict, got a " +
                                   std::string(py::str(value.get_type().attr("__name__"))));
}

}  // namespace

nlohmann::json toJson(const py::handle& value, const std::string& file, const std::string& path) {
  return convert(value, file, path, 0);
}

nlohmann::json toJson(const py::kwargs& kwargs, const std::string& file, const std::string& path) {
  return convert(kwargs, file, path, 0);
}

}  // namespace rbsim::python

#include "arguments.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

std::string typeName(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__"));
}

}  // namespace

void wrongType(const char* call, const char* parameter, const std::string& expected, const py::handle& value) {
  throw py::type_error(std::string(call) + ": " + parameter + ": expected " + expected + ", got " + typeName(value));
}

long long intArgument(const py::handle& value, const char* call, const char* parameter) {
  // bool is an int subclass, but World.step(True) is a mistake, not one step; NumPy's integers
  // pass through __index__.
  if (py::isinstance<py::bool_>(value) || !PyIndex_Check(value.ptr())) wrongType(call, parameter, "an int", value);
  try {
    return py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr())).cast<long long>();
  } catch (const py::cast_error&) {
    throw py::value_error(std::string(call) + ": " + parameter + ": " + std::string(py::repr(value)) +
                          " does not fit in 64 bits");
  }
}

std::string stringArgument(const py::handle& value, const char* call, const char* parameter) {
  if (!py::isinstance<py::str>(value)) wrongType(call, parameter, "a str", value);
  return value.cast<std::string>();
}

std::string pathArgument(const py::handle& value, const char* call, const char* parameter) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    const py::object path = value.attr("__fspath__")();
    if (py::isinstance<py::str>(path)) return path.cast<std::string>();
  }
  wrongType(call, parameter, "a path (str or pathlib.Path)", value);
}

std::vector<std::string> stringListArgument(const py::handle& value, const char* call, const char* parameter) {
  if (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value)) {
    wrongType(call, parameter, "a list of str such as [\"world.dt=0.01\"]", value);
  }
  std::vector<std::string> out;
  std::size_t i = 0;
  for (const py::handle item : value) {
    const std::string name = std::string(parameter) + "[" + std::to_string(i++) + "]";
    out.push_back(stringArgument(item, call, name.c_str()));
  }
  return out;
}

const PyBodyId& bodyArgument(const py::handle& value, const char* call, const char* parameter) {
  if (!py::isinstance<PyBodyId>(value)) wrongType(call, parameter, "a BodyId (from add_body or id_at)", value);
  return *value.cast<const PyBodyId*>();
}

PyWorld& worldArgument(const py::handle& value, const char* call, const char* parameter) {
  if (!py::isinstance<PyWorld>(value)) wrongType(call, parameter, "a World", value);
  return *value.cast<PyWorld*>();
}

py::array_t<double, py::array::c_style | py::array::forcecast> doubleArrayArgument(const py::handle& value,
                                                                                  const char* call,
                                                                                  const char* parameter) {
  auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array) wrongType(call, parameter, "numbers (a float, a sequence or an array of them)", value);
  return array;
}

py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> byteArrayArgument(const py::handle& value,
                                                                                      const char* call,
                                                                                      const char* parameter) {
  auto array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array) wrongType(call, parameter, "a uint8 array", value);
  return array;
}

py::kwargs givenKeywords(const py::kwargs& kwargs) {
  py::dict given;
  for (const auto& [key, value] : kwargs) {
    if (!value.is_none()) given[key] = value;
  }
  return py::reinterpret_borrow<py::kwargs>(given);
}

void requireKeywordsOnly(const py::args& args, const char* call, const char* block) {
  if (args.empty()) return;
  throw py::type_error(std::string(call) + " takes keyword arguments only (the keys of " + block + "), got " +
                       std::to_string(args.size()) + " positional argument" + (args.size() == 1 ? "" : "s") +
                       " (" + typeName(args[0]) + ")");
}

}  // namespace rbsim::python

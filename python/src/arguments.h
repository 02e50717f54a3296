#pragma once
// Positional and named arguments of the module's calls, converted by hand so that a value of the
// wrong type is a TypeError that names the call, the parameter and the type it expects
// ("World.step(): steps: expected an int, got str"), where pybind11 would only list the call's
// signatures or say "Unable to cast Python instance to C++ type" (issue 37).
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "py_world.h"

namespace rbsim::python {

// Raises TypeError: "<call>: <parameter>: expected <expected>, got <type of value>".
[[noreturn]] void wrongType(const char* call, const char* parameter, const std::string& expected,
                            const pybind11::handle& value);

long long intArgument(const pybind11::handle& value, const char* call, const char* parameter);  // no bool, no float
std::string stringArgument(const pybind11::handle& value, const char* call, const char* parameter);
// A str or an os.PathLike (pathlib.Path), as open() takes.
std::string pathArgument(const pybind11::handle& value, const char* call, const char* parameter);
// A list or tuple of str; a single str is refused (it is not one override per character).
std::vector<std::string> stringListArgument(const pybind11::handle& value, const char* call, const char* parameter);
const PyBodyId& bodyArgument(const pybind11::handle& value, const char* call, const char* parameter = "body");
PyWorld& worldArgument(const pybind11::handle& value, const char* call, const char* parameter = "world");
// Anything NumPy can read as an array of doubles (a number, a sequence, an array).
pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast> doubleArrayArgument(
    const pybind11::handle& value, const char* call, const char* parameter);
pybind11::array_t<std::uint8_t, pybind11::array::c_style | pybind11::array::forcecast> byteArrayArgument(
    const pybind11::handle& value, const char* call, const char* parameter);
// The keyword arguments given as anything but None: in a signature, None stands for the scene
// format's default (the key left out), so passing it is leaving the key out.
pybind11::kwargs givenKeywords(const pybind11::kwargs& kwargs);
// A call that takes keyword arguments only (the keys of a scene block) refuses positional ones.
void requireKeywordsOnly(const pybind11::args& args, const char* call, const char* block);

}  // namespace rbsim::python

// Parameters from Python: numbers, integers, strings and vectors of numbers, their types
// and ranges checked, or an InvalidArgument (a ValueError) naming the parameter, as for the
// library's own checks. The bindings take py::handle and convert here, where a typed
// parameter would answer a wrong type with pybind11's dump of the signature.
#pragma once

#include <ddb/core/errors.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <limits>
#include <string>

namespace ddb::python {

/// `object` (a Python or NumPy real number, or anything with __float__) as a double.
inline double realArgument(const std::string& name, pybind11::handle object) {
  const double value = PyFloat_AsDouble(object.ptr());
  if (value == -1.0 && PyErr_Occurred() != nullptr) {
    PyErr_Clear();
    throwInvalid(name, std::string(pybind11::repr(object)), "must be a real number");
  }
  return value;
}

/// `object` (a Python or NumPy integer: not a float, whose fraction would be dropped) as an
/// Int in [lowest, highest].
template <class Int>
Int integerArgument(const std::string& name, pybind11::handle object,
                    Int lowest = std::numeric_limits<Int>::lowest(),
                    Int highest = std::numeric_limits<Int>::max()) {
  namespace py = pybind11;
  const std::string what = std::string(py::repr(object));
  const auto range = "[" + std::to_string(lowest) + ", " + std::to_string(highest) + "]";
  PyObject* index = PyNumber_Index(object.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    throwInvalid(name, what, "must be an integer in " + range);
  }
  const auto value = py::reinterpret_steal<py::int_>(index);
  if (value < py::int_(lowest) || value > py::int_(highest)) {
    throwInvalid(name, what, "must be an integer in " + range);
  }
  return value.cast<Int>();
}

/// `object` (a str) as a string.
inline std::string textArgument(const std::string& name, pybind11::handle object) {
  if (!pybind11::isinstance<pybind11::str>(object)) {
    throwInvalid(name, std::string(pybind11::repr(object)), "must be a str");
  }
  return object.cast<std::string>();
}

/// `object` (a sequence or array of `size` real numbers; any number of them if size < 0) as an
/// Eigen vector (a copy). A refusal says what it must be: `size` numbers, or `requirement`
/// where given (e.g. "a 1-D array of N numbers J_i > 0, 2 <= N <= 4096").
template <int Rows = Eigen::Dynamic>
Eigen::Matrix<double, Rows, 1> vectorArgument(const std::string& name, pybind11::handle object,
                                              Eigen::Index size = Rows,
                                              const std::string& requirement = "") {
  namespace py = pybind11;
  const py::array array = py::array::ensure(object);
  const std::string what = std::string(py::repr(object));
  if (!array || !(array.dtype().kind() == 'f' || array.dtype().kind() == 'i' ||
                  array.dtype().kind() == 'u')) {
    throwInvalid(name, what, "must be a sequence of real numbers");
  }
  if (array.ndim() != 1 || (size >= 0 && array.shape(0) != size)) {
    const std::string shape = array.ndim() == 1
                                  ? std::to_string(array.shape(0)) + " numbers"
                                  : "an array of " + std::to_string(array.ndim()) + " dimensions";
    throwInvalid(name, what,
                 "must be " +
                     (!requirement.empty() ? requirement
                      : size >= 0          ? "a 1-D array of " + std::to_string(size) + " numbers"
                                           : std::string("a 1-D array of numbers")) +
                     ", not " + shape);
  }
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  return Eigen::Map<const Eigen::Matrix<double, Rows, 1>>(values.data(), values.shape(0));
}

}  // namespace ddb::python

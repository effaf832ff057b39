// Parameters from Python: a vector of numbers, its length and dtype checked, or an
// InvalidArgument (a ValueError) naming the parameter, as for the library's own checks.
#pragma once

#include <ddb/core/errors.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>

namespace ddb::python {

/// `object` (a sequence or array of `size` real numbers) as an Eigen vector (a copy).
template <int Rows = Eigen::Dynamic>
Eigen::Matrix<double, Rows, 1> vectorArgument(const std::string& name, pybind11::handle object,
                                              Eigen::Index size = Rows) {
  namespace py = pybind11;
  const py::array array = py::array::ensure(object);
  const std::string what = std::string(py::repr(object));
  if (!array || !(array.dtype().kind() == 'f' || array.dtype().kind() == 'i' ||
                  array.dtype().kind() == 'u')) {
    throwInvalid(name, what, "must be a sequence of real numbers");
  }
  if (array.ndim() != 1 || (size >= 0 && array.shape(0) != size)) {
    throwInvalid(name, what, "must be " + std::to_string(size) + " numbers");
  }
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  return Eigen::Map<const Eigen::Matrix<double, Rows, 1>>(values.data(), values.shape(0));
}

}  // namespace ddb::python

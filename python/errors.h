// The library's errors as Python exceptions: InvalidArgument is a ValueError (its message
// names the parameter), SolveFailure is ddb.SolveFailure, a RuntimeError carrying the
// failure's fields and, from integrate(), the states computed before it.
#pragma once

#include <ddb/core/errors.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace ddb::python {

/// What a SolveFailure says, copied so that it outlives the C++ exception (integrate()
/// catches it with the GIL released and raises once it holds the GIL again).
struct FailureRecord {
  std::string message, kind, what_failed;
  long step = -1;
  double t = 0.0, h = 0.0, residual = 0.0, tolerance = 0.0;

  static FailureRecord of(const SolveFailure& failure);
};

/// Raises ddb.SolveFailure with the record's fields and `times`, `states` (the valid prefix;
/// None when there is none).
[[noreturn]] void raiseSolveFailure(const FailureRecord& record, pybind11::object times,
                                    pybind11::object states);

}  // namespace ddb::python

#include "errors.h"

#include <exception>

#include "bindings.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

/// ddb.SolveFailure, created by bindErrors.
py::handle solveFailureType;

}  // namespace

FailureRecord FailureRecord::of(const SolveFailure& failure) {
  FailureRecord r;
  r.message = failure.what();
  if (dynamic_cast<const NonFiniteState*>(&failure) != nullptr) {
    r.kind = "NonFiniteState";
  } else if (dynamic_cast<const BudgetExhausted*>(&failure) != nullptr) {
    r.kind = "BudgetExhausted";
  } else if (dynamic_cast<const InjectivityLimit*>(&failure) != nullptr) {
    r.kind = "InjectivityLimit";
  } else {
    r.kind = "SolveFailure";
  }
  r.what_failed = failure.whatFailed();
  r.step = failure.step();
  r.t = failure.time();
  r.h = failure.h();
  r.residual = failure.residual();
  r.tolerance = failure.tolerance();
  return r;
}

namespace {

py::object solveFailureObject(const FailureRecord& record, py::object times, py::object states) {
  py::object error = solveFailureType(record.message);
  error.attr("kind") = record.kind;
  error.attr("what_failed") = record.what_failed;
  error.attr("step") = record.step;
  error.attr("t") = record.t;
  error.attr("h") = record.h;
  error.attr("residual") = record.residual;
  error.attr("tolerance") = record.tolerance;
  error.attr("times") = std::move(times);
  error.attr("states") = std::move(states);
  return error;
}

}  // namespace

void raiseSolveFailure(const FailureRecord& record, py::object times, py::object states) {
  PyErr_SetObject(solveFailureType.ptr(),
                  solveFailureObject(record, std::move(times), std::move(states)).ptr());
  throw py::error_already_set();
}

void bindErrors(py::module_& m) {
  static py::exception<SolveFailure> type(m, "SolveFailure", PyExc_RuntimeError);
  type.doc() =
      "A step whose implicit solve (or series, or state) failed: a RuntimeError with "
      "kind (SolveFailure, NonFiniteState, BudgetExhausted or InjectivityLimit), what_failed, "
      "step (index k of the step from t_k), t, h, residual, tolerance and, when raised by "
      "integrate(), times and states: the states kept before the failure (the last one "
      "computed included, whatever `every`).";
  solveFailureType = type;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SolveFailure& failure) {
      // InvalidArgument is a std::invalid_argument: pybind11 makes it a ValueError itself.
      PyErr_SetObject(solveFailureType.ptr(),
                      solveFailureObject(FailureRecord::of(failure), py::none(), py::none()).ptr());
    }
  });
}

}  // namespace ddb::python

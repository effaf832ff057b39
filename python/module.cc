// The `ddb` Python module: the library's systems, the method table and integrate() on
// NumPy arrays (docs/guide/python.md).
#include <ddb/core/openblas_kernels.h>
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.h"

PYBIND11_MODULE(ddb, m) {
  m.doc() =
      "Lie-Poisson systems with double-bracket dissipation, integrated by the DDB methods "
      "(energy decays, Casimirs kept) and their peers, at C++ speed. Build a system "
      "(rigid_body, heavy_top, kirchhoff, manakov, zeitlin, zeitlin_mhd, user_system), pick a "
      "method by "
      "its name (methods()) and call integrate(). See docs/guide/python.md.";
  m.attr("__version__") = DDB_VERSION;
  ddb::python::bindErrors(m);
  ddb::python::bindSystem(m);
  ddb::python::bindSystems(m);
  ddb::python::bindScenarios(m);
  ddb::python::bindZeitlin(m);
  ddb::python::bindZeitlinMhd(m);
  ddb::python::bindUserSystem(m);
  ddb::python::bindMethods(m);
  ddb::python::bindIntegrate(m);
  // Said once, at import, as the apps say it when a run starts (core/openblas_kernels.h).
  if (const std::string advice = ddb::openblasKernelAdvice(); !advice.empty()) {
    if (PyErr_WarnEx(PyExc_RuntimeWarning, advice.c_str(), 1) != 0)
      throw pybind11::error_already_set();
  }
}

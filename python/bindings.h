// The parts of the `ddb` Python module (docs/guide/python.md), each bound by
// its own file and called in this order by module.cc.
#pragma once

#include <pybind11/pybind11.h>

namespace ddb::python {

void bindErrors(pybind11::module_& m);      // errors.cc
void bindSystem(pybind11::module_& m);      // system.cc
void bindSystems(pybind11::module_& m);     // systems.cc
void bindScenarios(pybind11::module_& m);   // scenarios.cc
void bindZeitlin(pybind11::module_& m);     // zeitlin.cc
void bindZeitlinMhd(pybind11::module_& m);  // zeitlin_mhd.cc
void bindUserSystem(pybind11::module_& m);  // user_system.cc
void bindMethods(pybind11::module_& m);     // methods.cc
void bindIntegrate(pybind11::module_& m);   // integrate.cc

}  // namespace ddb::python

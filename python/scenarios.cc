// The paper's scenarios and the default heavy top and Kirchhoff body
// (systems/paper_scenarios.h; docs/reference/conventions.md §3): their data, system() and mu0.
#include <ddb/systems/paper_scenarios.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "arguments.h"
#include "bindings.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

void bindScenarios(py::module_& m) {
  py::class_<RigidBodyScenario>(m, "RigidBodyScenario",
                                "A rigid-body scenario of the paper (Section 5): k# = alpha I, "
                                "started from M0 = I Omega0, over [0, t_end].")
      .def_readonly("name", &RigidBodyScenario::name)
      .def_readonly("description", &RigidBodyScenario::description)
      .def_readonly("inertia", &RigidBodyScenario::inertia)
      .def_readonly("alpha", &RigidBodyScenario::alpha)
      .def_readonly("omega0", &RigidBodyScenario::omega0)
      .def_readonly("t_end", &RigidBodyScenario::t_end)
      .def_property_readonly("mu0", &RigidBodyScenario::mu0, "M0 = inertia * omega0")
      .def(
          "system", [](const RigidBodyScenario& s) { return std::make_shared<System>(s.system()); },
          "The scenario's rigid body.")
      .def("__repr__", [](const RigidBodyScenario& s) {
        return "<ddb.RigidBodyScenario " + s.name + ": " + s.description + ">";
      });
  m.def("scenarios", &rigidBodyScenarios, "Scenarios A, B and C of the paper, in its order.");
  m.def(
      "scenario",
      [](py::handle name_object) {
        // The library's rigidBodyScenario() names its parameter `scenario`; this one is `name`.
        const std::string name = textArgument("name", name_object);
        std::string valid;
        for (const RigidBodyScenario& s : rigidBodyScenarios()) {
          if (s.name == name) return s;
          valid += (valid.empty() ? "" : ", ") + s.name;
        }
        throwInvalid("name", name, "expected one of " + valid);
      },
      py::arg("name"), "The scenario called `name` (A, B or C); ValueError for another name.");
  py::class_<HeavyTopSetup>(m, "HeavyTopSetup",
                            "The apps' default heavy top: its parameters (each may be changed), "
                            "mu0 (gamma tilted by 0.3 rad from e3) and t_end.")
      .def(py::init<>())
      .def_readwrite("inertia", &HeavyTopSetup::inertia)
      .def_readwrite("mgl", &HeavyTopSetup::mgl)
      .def_readwrite("chi", &HeavyTopSetup::chi)
      .def_readwrite("mu0", &HeavyTopSetup::mu0)
      .def_readwrite("metric", &HeavyTopSetup::metric)
      .def_readwrite("alpha", &HeavyTopSetup::alpha)
      .def_readwrite("t_end", &HeavyTopSetup::t_end)
      .def(
          "system", [](const HeavyTopSetup& s) { return std::make_shared<System>(s.system()); },
          "The heavy top of these parameters.");
  py::class_<KirchhoffSetup>(m, "KirchhoffSetup",
                             "The apps' default Kirchhoff body: its parameters (each may be "
                             "changed), mu0 and t_end.")
      .def(py::init<>())
      .def_readwrite("inertia", &KirchhoffSetup::inertia)
      .def_readwrite("mass", &KirchhoffSetup::mass)
      .def_readwrite("mu0", &KirchhoffSetup::mu0)
      .def_readwrite("metric", &KirchhoffSetup::metric)
      .def_readwrite("alpha", &KirchhoffSetup::alpha)
      .def_readwrite("t_end", &KirchhoffSetup::t_end)
      .def(
          "system", [](const KirchhoffSetup& s) { return std::make_shared<System>(s.system()); },
          "The Kirchhoff body of these parameters.");
  py::class_<PlanarKirchhoffSetup>(m, "PlanarKirchhoffSetup",
                                   "The apps' default planar Kirchhoff body: its parameters (each "
                                   "may be changed), mu0 and t_end.")
      .def(py::init<>())
      .def_readwrite("inertia", &PlanarKirchhoffSetup::inertia)
      .def_readwrite("mass", &PlanarKirchhoffSetup::mass)
      .def_readwrite("mu0", &PlanarKirchhoffSetup::mu0)
      .def_readwrite("metric", &PlanarKirchhoffSetup::metric)
      .def_readwrite("alpha", &PlanarKirchhoffSetup::alpha)
      .def_readwrite("t_end", &PlanarKirchhoffSetup::t_end)
      .def(
          "system",
          [](const PlanarKirchhoffSetup& s) { return std::make_shared<System>(s.system()); },
          "The planar Kirchhoff body of these parameters.");
}

}  // namespace ddb::python

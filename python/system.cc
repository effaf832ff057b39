// ddb.System: name, group, N, the energy H and the Casimirs of states, and the methods of
// the table that apply.
#include "system.h"

#include <ddb/integrators/methods/method_table.h>
#include <pybind11/stl.h>

#include <vector>

#include "bindings.h"
#include "states.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

/// f(system, state) of one state or of each of a stack (mapStates), on the system's group.
template <class F>
py::object perState(const System& s, py::handle states, bool scalar, F&& f) {
  return s.visit([&](const auto& p) {
    using G = GroupOf<decltype(p)>;
    return mapStates<G>(states, s.n(), scalar, [&](const Dual<G>& mu) { return f(*p, mu); });
  });
}

}  // namespace

void bindSystem(py::module_& m) {
  py::class_<System, std::shared_ptr<System>>(
      m, "System",
      "A Lie-Poisson system with double-bracket dissipation on SO3, SE2, SE3, SO(N), SU(N) or "
      "SU(N) x| su(N)*. Built by rigid_body, heavy_top, kirchhoff, planar_kirchhoff, manakov, "
      "zeitlin, zeitlin_mhd, "
      "user_system or a scenario's system().")
      .def_property_readonly("name", &System::name)
      .def_property_readonly("group", &System::group,
                             "SO3, SE2, SE3, SO(N), SU(N) or SU(N) x| su(N)*")
      .def_property_readonly(
          "n", &System::n,
          "N of SO(N), SU(N), SU(N) x| su(N)* (states N x N, or 2 x N x N); 0 on SO3, SE2 and SE3")
      .def_property_readonly(
          "state_shape",
          [](const System& s) {
            return s.visit([&](const auto& p) {
              return py::tuple(py::cast(stateShape<GroupOf<decltype(p)>>(s.n())));
            });
          },
          "the shape of one state: (3,) (SO3, SE2), (6,) (SE3), (N, N) or (2, N, N) (zeitlin_mhd)")
      .def(
          "energy",
          [](const System& s, py::handle states) {
            return perState(s, states, true, [](const auto& system, const auto& mu) {
              return Eigen::VectorXd::Constant(1, system.energy(mu));
            });
          },
          py::arg("states"),
          "The Hamiltonian H of one state (a float) or of each of a stack of states, shape "
          "(k, ...) (an array of k floats).")
      .def(
          "casimirs",
          [](const System& s, py::handle states) {
            return perState(s, states, false, [](const auto& system, const auto& mu) {
              return Eigen::VectorXd(system.casimirs(mu));
            });
          },
          py::arg("states"),
          "The Casimirs of one state or of each of a stack: |m| on SO3; (|gamma|^2, pi.gamma) "
          "on SE3; on SO(N), SU(N) the spectrum, the eigenvalues of -i mu, ascending; on "
          "zeitlin_mhd's group tr H^k (k = 2..N) then tr(H^k K) (k = 0..N-1), H = -i Theta, "
          "K = -i W. One state: an array (c,); a stack of k: an array (k, c).")
      .def(
          "methods",
          [](const System& s) {
            return s.visit([](const auto& p) {
              std::vector<std::string> names;
              for (const MethodInfo& method : kMethods) {
                if (methodApplies(method, *p)) names.emplace_back(method.name);
              }
              return names;
            });
          },
          "The names of the methods of ddb.methods() that apply to this system.")
      .def("__repr__", [](const System& s) {
        return "<ddb.System '" + s.name() + "' on " + s.group() +
               (s.n() > 0 ? ", N = " + std::to_string(s.n()) : std::string()) + ">";
      });
}

}  // namespace ddb::python

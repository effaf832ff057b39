// The library's systems by their factories (systems/): rigid body, heavy top, Kirchhoff body and
// planar Kirchhoff body with the defaults of systems/paper_scenarios.h, and the Manakov body on
// SO(N).
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <pybind11/eigen.h>

#include <memory>

#include "arguments.h"
#include "bindings.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

void bindSystems(py::module_& m) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  m.def(
      "rigid_body",
      [](py::handle inertia, py::handle alpha) {
        return std::make_shared<System>(
            makeRigidBody(vectorArgument<3>("inertia", inertia), realArgument("alpha", alpha)));
      },
      py::arg("inertia") = a.inertia, py::arg("alpha") = a.alpha,
      "The free rigid body on SO3 (paper, Sections 3 and 5): principal moments `inertia` "
      "(3 numbers > 0), k# = alpha I. States m in R^3; Casimir |m|. Has a Lagrangian, so "
      "every fixed-size method applies. Defaults: Scenario A.");
  const HeavyTopSetup top;
  m.def(
      "heavy_top",
      [](py::handle inertia, py::handle mgl, py::handle chi, py::handle alpha, py::handle metric) {
        return std::make_shared<System>(
            makeHeavyTop(vectorArgument<3>("inertia", inertia), realArgument("mgl", mgl),
                         vectorArgument<3>("chi", chi), realArgument("alpha", alpha),
                         vectorArgument<6>("metric", metric)));
      },
      py::arg("inertia") = top.inertia, py::arg("mgl") = top.mgl, py::arg("chi") = top.chi,
      py::arg("alpha") = top.alpha, py::arg("metric") = top.metric,
      "The heavy top on SE3: mu = (pi, gamma), H = pi.I^-1 pi/2 + mgl chi.gamma, k# = alpha "
      "diag(metric) (6 numbers >= 0). Hamiltonian only: the paper's symmetric variants "
      "(sddb-paper-*) do not apply. Casimirs |gamma|^2, pi.gamma. Defaults: HeavyTopSetup().");
  const KirchhoffSetup body;
  m.def(
      "kirchhoff",
      [](py::handle inertia, py::handle mass, py::handle alpha, py::handle metric) {
        return std::make_shared<System>(makeKirchhoffBody(
            vectorArgument<3>("inertia", inertia), vectorArgument<3>("mass", mass),
            realArgument("alpha", alpha), vectorArgument<6>("metric", metric)));
      },
      py::arg("inertia") = body.inertia, py::arg("mass") = body.mass, py::arg("alpha") = body.alpha,
      py::arg("metric") = body.metric,
      "The Kirchhoff body on SE3 (a rigid body with added masses `mass`), k# = alpha "
      "diag(metric). Defaults: KirchhoffSetup().");
  const PlanarKirchhoffSetup planar;
  m.def(
      "planar_kirchhoff",
      [](py::handle inertia, py::handle mass, py::handle alpha, py::handle metric) {
        return std::make_shared<System>(makePlanarKirchhoffBody(
            realArgument("inertia", inertia), vectorArgument<2>("mass", mass),
            realArgument("alpha", alpha), vectorArgument<3>("metric", metric)));
      },
      py::arg("inertia") = planar.inertia, py::arg("mass") = planar.mass,
      py::arg("alpha") = planar.alpha, py::arg("metric") = planar.metric,
      "Kirchhoff's body in the plane on SE2: mu = (pi, P1, P2), H = pi^2/(2 inertia) + "
      "P1^2/(2 m1) + P2^2/(2 m2) with mass = (m1, m2), k# = alpha diag(metric) (3 numbers >= 0). "
      "Casimir |P|^2. Defaults: PlanarKirchhoffSetup().");
  m.def(
      "manakov",
      [](py::handle J, py::handle alpha) {
        const Eigen::VectorXd j =
            vectorArgument("J", J, -1,
                           "a 1-D array of N numbers J_i > 0, one per axis of SO(N), 2 <= N <= " +
                               std::to_string(SON::kMaxN));
        // The body keeps N x N matrices (1/(J_i + J_j), and every state): refused here, before
        // they are allocated, past the N that the group's states allow.
        if (j.size() > SON::kMaxN) {
          throwInvalid("J", "an array of " + std::to_string(j.size()) + " numbers",
                       "must have at most " + std::to_string(SON::kMaxN) + " (N of SO(N))");
        }
        return std::make_shared<System>(makeManakovBody(j, realArgument("alpha", alpha)), j.size());
      },
      py::arg("J"), py::arg("alpha"),
      "The Manakov (generalised rigid) body on SO(N): M = J Omega + Omega J with J = diag(J) "
      "(N numbers > 0, 2 <= N <= 4096), k# = alpha Id. States: real skew-symmetric N x N matrices; "
      "Casimirs: "
      "the spectrum of -i M.");
}

}  // namespace ddb::python

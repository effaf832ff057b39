// Magnetohydrodynamics on the sphere (systems/zeitlin_mhd.h): ddb.zeitlin_mhd(N, alpha), a
// System on SU(N) ⋉ su(N)* whose states are complex arrays (2, N, N), [W, Θ] (quflow's MHD
// layout), with the diagnostics (both energies, cross helicity, the equilibrium residual) and
// both fields on quflow's grid.
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_grid.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <pybind11/eigen.h>

#include <memory>
#include <string>

#include "arguments.h"
#include "bindings.h"
#include "states.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

/// The magnetic fluid: a System on SU(N) ⋉ su(N)* that keeps its Hamiltonian for the diagnostics.
class ZeitlinMhd : public System {
 public:
  ZeitlinMhd(Eigen::Index n, double alpha) : ZeitlinMhd(makeZeitlinMhd(n, alpha)) {}

  const ZeitlinMhdDiagnostics& diagnostics() const { return diagnostics_; }
  /// (2, N²): the coefficients ω_lm of W and of Θ.
  Eigen::MatrixXd coefficients(const DualMatrix<Eigen::MatrixXcd>& mu) const {
    Eigen::MatrixXd out(2, n() * n());
    out.row(0) = basis_.coefficients(mu.eps).transpose();
    out.row(1) = basis_.coefficients(mu.real).transpose();
    return out;
  }
  DualMatrix<Eigen::MatrixXcd> state(const std::string& name, py::handle object) const {
    DualMatrix<Eigen::MatrixXcd> mu = stateFromArray<DualNumberSUN>(name, object, n());
    DualNumberSUN::requireState(name + "[1] (Theta)", name + "[0] (W)", mu);
    return mu;
  }

 private:
  explicit ZeitlinMhd(const SystemPointer<DualNumberSUN>& system)
      : ZeitlinMhd(system, dynamic_cast<const ZeitlinMhdHamiltonian&>(system->hamiltonian())) {}
  ZeitlinMhd(const SystemPointer<DualNumberSUN>& system, const ZeitlinMhdHamiltonian& hamiltonian)
      : System(system, hamiltonian.poisson().size()),
        diagnostics_(hamiltonian),
        basis_(hamiltonian.poisson()) {}

  ZeitlinMhdDiagnostics diagnostics_;  // refers to the Hamiltonian the base's system owns
  SphericalHarmonicBasis basis_;
};

/// f(μ) of one state (a float) or of each of a stack (an array).
template <class F>
py::object perState(const ZeitlinMhd& mhd, py::handle states, F&& f) {
  return mapStates<DualNumberSUN>(
      states, mhd.n(), true,
      [&](const DualMatrix<Eigen::MatrixXcd>& mu) { return Eigen::VectorXd::Constant(1, f(mu)); });
}

}  // namespace

void bindZeitlinMhd(py::module_& m) {
  py::class_<ZeitlinMhd, System, std::shared_ptr<ZeitlinMhd>>(
      m, "ZeitlinMhd",
      "Magnetohydrodynamics on the sphere, Zeitlin's model on SU(N) x| su(N)*: states (2, N, N) "
      "complex, [W, Theta] (vorticity, magnetic potential; skew-Hermitian, traceless), "
      "W' = ([P, W] + [B, Theta])/hbar, Theta' = [P, Theta]/hbar with P = Laplacian^-1 W, "
      "B = Laplacian Theta, plus the double bracket with alpha (docs/reference/conventions.md "
      "§2). casimirs(): tr H^k (k = 2..N) then tr(H^k K) (k = 0..N-1), H = -i Theta, K = -i W.")
      .def(
          "kinetic_energy",
          [](const ZeitlinMhd& f, py::handle states) {
            return perState(f, states,
                            [&](const auto& mu) { return f.diagnostics().kineticEnergy(mu); });
          },
          py::arg("states"), "E_kin = Re tr(W P)/(2N), of one state or each of a stack.")
      .def(
          "magnetic_energy",
          [](const ZeitlinMhd& f, py::handle states) {
            return perState(f, states,
                            [&](const auto& mu) { return f.diagnostics().magneticEnergy(mu); });
          },
          py::arg("states"), "E_mag = Re tr(Theta B)/(2N), of one state or each of a stack.")
      .def(
          "cross_helicity",
          [](const ZeitlinMhd& f, py::handle states) {
            return perState(f, states,
                            [&](const auto& mu) { return f.diagnostics().crossHelicity(mu); });
          },
          py::arg("states"), "<W, Theta>/(2N) = -Re tr(W Theta)/(2N) (a Casimir).")
      .def(
          "residual",
          [](const ZeitlinMhd& f, py::handle states) {
            return perState(
                f, states, [&](const auto& mu) { return f.diagnostics().equilibriumResidual(mu); });
          },
          py::arg("states"),
          "hypot(||[P, Theta]||_F, ||[P, W] + [B, Theta]||_F): zero exactly at magnetic "
          "equilibria.")
      .def(
          "omega_lm",
          [](const ZeitlinMhd& f, py::handle mu) { return f.coefficients(f.state("mu", mu)); },
          py::arg("mu"),
          "(2, N^2): the spherical-harmonic coefficients of W and of Theta "
          "(ZeitlinFluid.omega_lm).")
      .def(
          "fields_on_grid",
          [](const ZeitlinMhd& f, py::handle mu) {
            const Eigen::MatrixXd c = f.coefficients(f.state("mu", mu));
            const SphericalHarmonicGrid grid(f.n());
            return py::make_tuple(grid.evaluate(c.row(0).transpose()),
                                  grid.evaluate(c.row(1).transpose()));
          },
          py::arg("mu"),
          "(W, Theta) on quflow's N x (2N - 1) latitude-longitude grid (ddb.grid_coordinates(N)).");
  m.def(
      "zeitlin_mhd",
      [](py::handle n_object, py::handle alpha) {
        const auto n = integerArgument<Eigen::Index>("N", n_object, 2, DualNumberSUN::kMaxN);
        return std::make_shared<ZeitlinMhd>(n, realArgument("alpha", alpha));
      },
      py::arg("N"), py::arg("alpha"),
      "Magnetohydrodynamics on the sphere at resolution N (2 <= N <= 4096) with double-bracket "
      "coefficient alpha (any finite sign; alpha > 0 lowers the total energy E_kin + E_mag to "
      "a magnetic equilibrium, keeping tr Theta^k and tr(W Theta^k)). States: complex arrays "
      "(2, N, N), [W, Theta]; methods: every one of the matrix groups but 'reference' "
      "(system.methods()).");
}

}  // namespace ddb::python

// Zeitlin's fluid on SU(N) (systems/zeitlin_fluid.h): the system with its diagnostics
// (energy E, enstrophy Z, ||[P, W]||, the spherical-harmonic coefficients omega_lm) and
// the apps' initial vorticities (random, l1, zonal with a seed).
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_grid.h>
#include <ddb/systems/zeitlin_exact_flows.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_spectra.h>
#include <pybind11/eigen.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "arguments.h"
#include "bindings.h"
#include "states.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

/// The fluid: a System on SU(N) that keeps its Hamiltonian's type for the diagnostics.
class ZeitlinFluid : public System {
 public:
  /// With its damping and forcing, checked here (their flows built once and dropped: a bad
  /// value is refused when the fluid is made, not at its first integrate()).
  ZeitlinFluid(Eigen::Index n, double alpha, const ZeitlinPhysics& physics,
               ZeitlinDampingAndForcing flows)
      : ZeitlinFluid(makeZeitlinFluid(checked(n), alpha, physics)) {
    zeitlinExactFlows(hamiltonian_, flows);
    flows_ = std::move(flows);
  }

  /// The method Strang-split with each of the fluid's exact flows, in zeitlinExactFlows' order
  /// (fluid-relax's).
  std::unique_ptr<OneStepMethod<SUN>> withExactFlows(
      std::unique_ptr<OneStepMethod<SUN>> method) const override {
    for (auto& flow : zeitlinExactFlows(hamiltonian_, flows_)) {
      method = std::make_unique<StrangSplitting<SUN>>(std::move(method), std::move(flow));
    }
    return method;
  }

  const ZeitlinHamiltonian& hamiltonian() const { return hamiltonian_; }
  const ZeitlinDiagnostics& diagnostics() const { return diagnostics_; }
  const SphericalHarmonicBasis& basis() const { return basis_; }
  /// The coefficients ω_lm of the relative vorticity W = Q − F of a state Q.
  Eigen::VectorXd relativeCoefficients(const Eigen::MatrixXcd& Q) const {
    Eigen::MatrixXcd workspace;
    return basis_.coefficients(hamiltonian_.relativeVorticity(Q, workspace));
  }
  /// E_l and Z_l of the state Q's relative vorticity (zeitlinSpectra).
  ZeitlinSpectra spectra(py::handle Q) const {
    const Eigen::MatrixXcd state = stateFromArray<SUN>("Q", Q, n());
    return zeitlinSpectra(relativeCoefficients(state), hamiltonian_.laplacian().kappaSquared());
  }

 private:
  explicit ZeitlinFluid(const SystemPointer<SUN>& system)
      : ZeitlinFluid(system, dynamic_cast<const ZeitlinHamiltonian&>(system->hamiltonian())) {}
  ZeitlinFluid(const SystemPointer<SUN>& system, const ZeitlinHamiltonian& hamiltonian)
      : System(system, hamiltonian.laplacian().size()),
        hamiltonian_(hamiltonian),
        diagnostics_(hamiltonian),
        basis_(hamiltonian.laplacian()) {}
  static Eigen::Index checked(Eigen::Index n) {
    detail::requireResolution(n);
    return n;
  }

  // Owned by the system the base holds.
  const ZeitlinHamiltonian& hamiltonian_;
  ZeitlinDiagnostics diagnostics_;
  SphericalHarmonicBasis basis_;
  ZeitlinDampingAndForcing flows_;
};

/// f(W) of one state (a float) or of each of a stack (an array).
template <class F>
py::object perState(const ZeitlinFluid& fluid, py::handle states, F&& f) {
  return mapStates<SUN>(states, fluid.n(), true, [&](const Eigen::MatrixXcd& W) {
    return Eigen::VectorXd::Constant(1, f(W));
  });
}

}  // namespace

void bindZeitlin(py::module_& m) {
  py::class_<ZeitlinFluid, System, std::shared_ptr<ZeitlinFluid>>(
      m, "ZeitlinFluid",
      "Zeitlin's fluid on SU(N): vorticity W (complex skew-Hermitian, traceless N x N), "
      "hbar = 2/sqrt(N^2 - 1), stream matrix P = Laplacian^-1 W, "
      "W' = ([P, W] + alpha [W, [P, W]])/hbar (docs/reference/conventions.md §2). "
      "casimirs() is the "
      "spectrum of -iW.")
      .def_property_readonly("hbar", [](const ZeitlinFluid& f) { return f.hamiltonian().hbar(); })
      .def(
          "fluid_energy",
          [](const ZeitlinFluid& f, py::handle states) {
            return perState(f, states, [&](const auto& W) { return f.diagnostics().energy(W); });
          },
          py::arg("states"), "E = Re tr(W P)/(2N) = hbar H/N, of one state or each of a stack.")
      .def(
          "enstrophy",
          [](const ZeitlinFluid& f, py::handle states) {
            return perState(f, states, [&](const auto& W) { return f.diagnostics().enstrophy(W); });
          },
          py::arg("states"), "Z = ||W||_F^2/(2N), of one state or each of a stack.")
      .def(
          "commutator_norm",
          [](const ZeitlinFluid& f, py::handle states) {
            return perState(f, states,
                            [&](const auto& W) { return f.diagnostics().commutatorNorm(W); });
          },
          py::arg("states"),
          "||[P, W]||_F, zero exactly at steady Euler flows; of one state or each of a stack.")
      .def(
          "stream_matrix",
          [](const ZeitlinFluid& f, py::handle W) {
            return stateToArray<SUN>(
                f.hamiltonian().streamMatrix(stateFromArray<SUN>("W", W, f.n())));
          },
          py::arg("W"), "P = Laplacian^-1 of the traceless part of W.")
      .def(
          "omega_lm",
          [](const ZeitlinFluid& f, py::handle W) {
            return f.basis().coefficients(stateFromArray<SUN>("W", W, f.n()));
          },
          py::arg("W"),
          "The real spherical-harmonic coefficients omega_lm = Re tr(T_lm^H W)/N of W, N^2 of "
          "them, omega_lm at index l^2 + l + m (l = 0..N-1, |m| <= l): the vorticity on the "
          "sphere is sqrt(4 pi) sum omega_lm Y_lm with real, orthonormal Y_lm "
          "(systems/spherical_harmonic_grid.h).")
      .def(
          "vorticity",
          [](const ZeitlinFluid& f, py::handle omega) {
            return stateToArray<SUN>(
                f.basis().matrix(vectorArgument("omega", omega, f.n() * f.n())));
          },
          py::arg("omega"), "W = sum omega_lm T_lm: the inverse of omega_lm().")
      .def(
          "energy_spectrum",
          [](const ZeitlinFluid& f, py::handle Q) { return f.spectra(Q).energy; }, py::arg("Q"),
          "E_l = 1/2 sum_m omega_lm^2 / (l(l+1) + kappa^2), l = 0..N-1, of the relative vorticity "
          "W = Q - F: it sums to fluid_energy(Q) (systems/zeitlin_spectra.h).")
      .def(
          "enstrophy_spectrum",
          [](const ZeitlinFluid& f, py::handle Q) { return f.spectra(Q).enstrophy; }, py::arg("Q"),
          "Z_l = 1/2 sum_m omega_lm^2, l = 0..N-1, of W = Q - F: it sums to enstrophy(Q).")
      .def(
          "gamma",
          [](const ZeitlinFluid& f, py::handle Q) {
            return zeitlinGamma(f.relativeCoefficients(stateFromArray<SUN>("Q", Q, f.n())));
          },
          py::arg("Q"), "gamma = |(omega_1,-1, omega_1,0, omega_1,1)| / |omega| of W = Q - F.")
      .def(
          "scale_decomposition",
          [](const ZeitlinFluid& f, py::handle Q) {
            const Eigen::MatrixXcd state = stateFromArray<SUN>("Q", Q, f.n());
            Eigen::MatrixXcd workspace;
            const Eigen::MatrixXcd W = f.hamiltonian().relativeVorticity(state, workspace);
            const ScaleDecomposition d =
                zeitlinScaleDecomposition(W, f.hamiltonian().streamMatrix(state));
            return py::make_tuple(stateToArray<SUN>(d.steady), stateToArray<SUN>(d.remainder));
          },
          py::arg("Q"),
          "(W_s, W_r): W = Q - F split into the part diagonal in the stream matrix's eigenbasis "
          "(it commutes with psi; all of W at a steady state) and the rest.")
      .def(
          "vorticity_on_grid",
          [](const ZeitlinFluid& f, py::handle Q) {
            return SphericalHarmonicGrid(f.n()).evaluate(
                f.relativeCoefficients(stateFromArray<SUN>("Q", Q, f.n())));
          },
          py::arg("Q"),
          "The relative vorticity W = Q - F on quflow's N x (2N - 1) latitude-longitude grid "
          "(ddb.grid_coordinates(N)): vorticity_on_grid(omega_lm(Q - F)), what fluid.hdf5's "
          "'fun' holds.")
      .def(
          "planetary_vorticity",
          [](const ZeitlinFluid& f) {
            const ZeitlinHamiltonian& h = f.hamiltonian();
            return stateToArray<SUN>(h.rotating() ? h.planetaryVorticity()
                                                  : Eigen::MatrixXcd::Zero(f.n(), f.n()).eval());
          },
          "F = 2 Omega X3, the planetary vorticity (zero without rotation): the states are the "
          "absolute vorticities Q = W + F (docs/reference/conventions.md §2).");
  m.def(
      "zeitlin",
      [](py::handle n_object, py::handle alpha, py::handle rotation, py::handle deformation_radius,
         py::handle viscosity, py::handle hyperviscosity_order, py::handle drag,
         py::handle forcing_band, py::handle forcing_rate, py::handle forcing_seed,
         py::handle forcing, py::handle viscous_scheme) {
        const auto n = integerArgument<Eigen::Index>("N", n_object, 2, SUN::kMaxN);
        ZeitlinPhysics physics;
        physics.rotation = realArgument("rotation", rotation);
        if (!deformation_radius.is_none()) {
          physics.deformation_radius = realArgument("deformation_radius", deformation_radius);
        }
        ZeitlinDampingAndForcing flows;
        flows.viscosity.viscosity = realArgument("viscosity", viscosity);
        flows.viscosity.order =
            integerArgument<int>("hyperviscosity_order", hyperviscosity_order, 1, 16);
        flows.viscosity.drag = realArgument("drag", drag);
        const std::string scheme =
            py::isinstance<py::str>(viscous_scheme) ? viscous_scheme.cast<std::string>() : "";
        if (scheme != "exact" && scheme != "implicit") {
          throwInvalid("viscous_scheme", std::string(py::repr(viscous_scheme)),
                       "must be 'exact' or 'implicit'");
        }
        flows.viscosity.scheme =
            scheme == "implicit" ? ZeitlinViscousScheme::kImplicit : ZeitlinViscousScheme::kExact;
        if (!forcing_band.is_none()) {
          const auto band = vectorArgument("forcing_band", forcing_band, 2,
                                           "a pair (L, D) of whole numbers: degrees L-D..L+D");
          if (band(0) != std::floor(band(0)) || band(1) != std::floor(band(1)) ||
              !(std::abs(band(0)) < 1e6 && std::abs(band(1)) < 1e6)) {
            throwInvalid("forcing_band", std::string(py::repr(forcing_band)),
                         "must be a pair (L, D) of whole numbers: degrees L-D..L+D");
          }
          flows.forcing.band_centre = static_cast<int>(band(0));
          flows.forcing.band_half_width = static_cast<int>(band(1));
        }
        flows.forcing.rate = realArgument("forcing_rate", forcing_rate);
        if (!(flows.forcing.rate >= 0)) {
          throwInvalid("forcing_rate", formatValue(flows.forcing.rate), "must be >= 0");
        }
        flows.forcing.seed = integerArgument<std::uint64_t>("forcing_seed", forcing_seed);
        if (forcing_band.is_none() && flows.forcing.rate > 0) {
          throwInvalid("forcing_rate", formatValue(flows.forcing.rate),
                       "needs forcing_band (L, D), the forced degrees L-D..L+D");
        }
        if (!forcing_band.is_none() && !(flows.forcing.rate > 0)) {
          throwInvalid("forcing_band", std::string(py::repr(forcing_band)),
                       "needs forcing_rate > 0");
        }
        if (!forcing_band.is_none() && !flows.forcing.bandFits(n)) {
          throwInvalid("forcing_band", std::string(py::repr(forcing_band)),
                       "its degrees L-D..L+D must lie in [1, N - 1], N = " + std::to_string(n));
        }
        if (!forcing.is_none()) flows.fixed_forcing = stateFromArray<SUN>("forcing", forcing, n);
        return std::make_shared<ZeitlinFluid>(n, realArgument("alpha", alpha), physics,
                                              std::move(flows));
      },
      py::arg("N"), py::arg("alpha"), py::arg("rotation") = 0.0,
      py::arg("deformation_radius") = py::none(), py::arg("viscosity") = 0.0,
      py::arg("hyperviscosity_order") = 1, py::arg("drag") = 0.0,
      py::arg("forcing_band") = py::none(), py::arg("forcing_rate") = 0.0,
      py::arg("forcing_seed") = 1, py::arg("forcing") = py::none(),
      py::arg("viscous_scheme") = "exact",
      "Zeitlin's fluid at resolution N (2 <= N <= 4096) with double-bracket coefficient "
      "alpha (any finite sign; alpha > 0 dissipates energy), on a sphere rotating at "
      "`rotation` (Omega; its states are absolute vorticities Q = W + F, "
      "planetary_vorticity() is F) and quasi-geostrophic with `deformation_radius` L_d > 0 "
      "(the stream matrix (Laplacian - 1/L_d^2)^-1 (Q - F); None: Euler). Damped with "
      "`viscosity` nu >= 0 of order `hyperviscosity_order` p >= 1 and linear `drag` gamma >= 0 "
      "(W' gains nu (-1)^(p+1) Laplacian^p W - gamma W on W = Q - F), forced in the degrees "
      "L-D..L+D of `forcing_band` (L, D) at the mean energy injection rate `forcing_rate` "
      "epsilon > 0 with the random stream `forcing_seed`, and by a fixed `forcing` Phi (W' gains "
      "Phi; complex skew-Hermitian traceless N x N): exact flows Strang-split around "
      "integrate()'s method (the viscous one exact, or with `viscous_scheme` 'implicit' the "
      "second-order L-stable step (I + hA + (hA)^2/2)^-1, A = nu (-Laplacian)^p + gamma, far "
      "cheaper at large N; each integrate() call starts the stream anew; "
      "docs/guide/matrix-groups-and-the-fluid.md).");
  m.def(
      "vorticity_on_grid",
      [](py::handle omega) {
        const Eigen::VectorXd coefficients =
            vectorArgument("omega", omega, -1, "a 1-D array of N^2 finite numbers");
        const auto n =
            static_cast<Eigen::Index>(std::lround(std::sqrt(double(coefficients.size()))));
        if (n < 1 || n * n != coefficients.size() || !coefficients.allFinite()) {
          throwInvalid("omega", std::string(py::repr(omega)),
                       "must be a 1-D array of N^2 finite numbers (omega_lm at l^2 + l + m)");
        }
        return SphericalHarmonicGrid(n).evaluate(coefficients);
      },
      py::arg("omega"),
      "The vorticity sqrt(4 pi) sum omega_lm Y_lm(theta, phi) that the coefficients omega "
      "(N^2 of them, omega_lm at l^2 + l + m: omega_lm(W), or a frame of fluid.hdf5's 'state') "
      "quantise, on quflow's N x (2N - 1) grid (grid_coordinates(N); quflow's shr2fun without "
      "Berezin's multipliers; systems/spherical_harmonic_grid.h).");
  m.def(
      "grid_coordinates",
      [](py::handle n_object) {
        const SphericalHarmonicGrid grid(
            integerArgument<Eigen::Index>("N", n_object, 1, SUN::kMaxN));
        return py::make_tuple(grid.colatitudes(), grid.longitudes());
      },
      py::arg("N"),
      "(theta, phi): the colatitudes pi (2j + 1)/(2N - 1), j < N, and longitudes "
      "2 pi k/(2N - 1), k < 2N - 1, of vorticity_on_grid's rows and columns.");
  m.def(
      "zeitlin_vorticity",
      [](py::handle kind_object, py::handle n_object, py::handle seed_object) {
        const std::string kind = textArgument("kind", kind_object);
        const auto n = integerArgument<Eigen::Index>("N", n_object, 2, SUN::kMaxN);
        const auto seed = integerArgument<std::uint64_t>("seed", seed_object);
        if (kind == "random") return stateToArray<SUN>(randomVorticity(n, seed));
        if (kind == "l1") return stateToArray<SUN>(l1Vorticity(n, seed));
        if (kind == "zonal") return stateToArray<SUN>(zonalVorticity(n, seed));
        throwInvalid("kind", kind, "expected one of random, l1, zonal");
      },
      py::arg("kind"), py::arg("N"), py::arg("seed") = 1,
      "The apps' seeded initial vorticities (--init, --seed), normalised to ||W||_F = sqrt(N): "
      "random (i.i.d. normal real and imaginary parts, projected to su(N)), l1 (W = U X3 U^H, "
      "U a random unitary: the coadjoint orbit of the l = 1 element X3) or zonal (i diag(d), "
      "d normal: a steady state, [P, W] = 0)");
}

}  // namespace ddb::python

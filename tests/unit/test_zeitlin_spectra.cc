// The field's diagnostics of Zeitlin's fluid (systems/zeitlin_spectra.h) against what they did not
// compute: a field built from known coefficients, the fluid's own energy and enstrophy
// (ZeitlinDiagnostics: traces of W and its stream matrix), γ of fields with and without l = 1,
// and the scale decomposition's defining properties (W_s commutes with ψ; W_s = W at a steady
// state).

#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_spectra.h>
#include <gtest/gtest.h>

#include <cmath>

namespace ddb::test {
namespace {

using Matrix = Eigen::MatrixXcd;

TEST(ZeitlinSpectra, AFieldOfKnownCoefficientsHasItsSpectra) {
  const Eigen::Index n = 7;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  Eigen::VectorXd omega = Eigen::VectorXd::Zero(n * n);
  omega(SphericalHarmonicBasis::index(2, -1)) = 3.0;
  omega(SphericalHarmonicBasis::index(2, 2)) = 4.0;  // |ω_2| = 5
  omega(SphericalHarmonicBasis::index(5, 0)) = -2.0;
  const Matrix W = basis.matrix(omega);
  const ZeitlinSpectra s = zeitlinSpectra(basis.coefficients(W));
  for (Eigen::Index l = 0; l < n; ++l) {
    const double squares = l == 2 ? 25.0 : l == 5 ? 4.0 : 0.0;
    EXPECT_NEAR(s.enstrophy(l), 0.5 * squares, 1e-13) << "l = " << l;
    const double energy = l == 0 ? 0.0 : 0.5 * squares / double(l * (l + 1));
    EXPECT_NEAR(s.energy(l), energy, 1e-13) << "l = " << l;
  }
}

TEST(ZeitlinSpectra, TheSpectraSumToTheFluidsEnergyAndEnstrophy) {
  const Eigen::Index n = 12;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  const Matrix W = randomVorticity(n, 7);
  for (const double kappa_squared : {0.0, 3.0}) {
    ZeitlinPhysics physics;
    if (kappa_squared > 0) physics.deformation_radius = 1.0 / std::sqrt(kappa_squared);
    const ZeitlinHamiltonian hamiltonian(n, physics);
    const ZeitlinDiagnostics diagnostics(hamiltonian);
    const ZeitlinSpectra s = zeitlinSpectra(basis.coefficients(W), kappa_squared);
    EXPECT_NEAR(s.energy.sum(), diagnostics.energy(W), 1e-13 * diagnostics.energy(W));
    EXPECT_NEAR(s.enstrophy.sum(), diagnostics.enstrophy(W), 1e-13 * diagnostics.enstrophy(W));
  }
}

TEST(ZeitlinSpectra, GammaIsOneForPureAngularMomentumAndZeroWithoutIt) {
  const Eigen::Index n = 8;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  const Matrix l1 = 0.3 * basis.element(1, -1) - 1.2 * basis.element(1, 0) + basis.element(1, 1);
  EXPECT_NEAR(zeitlinGamma(basis.coefficients(l1)), 1.0, 1e-14);
  const Matrix without = basis.element(2, 1) + basis.element(6, -4);
  EXPECT_NEAR(zeitlinGamma(basis.coefficients(without)), 0.0, 1e-14);
  // Half of the squares in l = 1: γ = 1/√2.
  const Matrix half = basis.element(1, 0) + basis.element(3, 2);
  EXPECT_NEAR(zeitlinGamma(basis.coefficients(half)), 1.0 / std::sqrt(2.0), 1e-14);
}

TEST(ZeitlinSpectra, TheSteadyPartCommutesWithPsiAndIsAllOfASteadyState) {
  const Eigen::Index n = 10;
  const ZeitlinHamiltonian hamiltonian(n);
  const Matrix W = randomVorticity(n, 3);
  const Matrix psi = hamiltonian.streamMatrix(W);
  const ScaleDecomposition d = zeitlinScaleDecomposition(W, psi);
  EXPECT_LT((d.steady * psi - psi * d.steady).norm(), 1e-12 * W.norm() * psi.norm());
  EXPECT_LT((d.steady + d.remainder - W).norm(), 1e-14 * W.norm());
  EXPECT_GT(d.remainder.norm(), 1e-3 * W.norm());  // a random W is not steady
  // W_r is orthogonal to W_s (Re tr(W_sᴴ W_r) = 0: W_r has no part on ψ's eigenprojections).
  EXPECT_NEAR((d.steady.adjoint() * d.remainder).trace().real(), 0.0, 1e-12 * W.squaredNorm());
  // A zonal flow is steady: [ψ, W] = 0, and W_s = W.
  const Matrix zonal = zonalVorticity(n, 2);
  const ScaleDecomposition z = zeitlinScaleDecomposition(zonal, hamiltonian.streamMatrix(zonal));
  EXPECT_LT(z.remainder.norm(), 1e-12 * zonal.norm());
}

}  // namespace
}  // namespace ddb::test

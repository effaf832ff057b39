// The field's diagnostics of Zeitlin's fluid (systems/zeitlin_spectra.h) against what they did not
// compute: a field built from known coefficients, the fluid's own energy and enstrophy
// (ZeitlinDiagnostics: traces of W and its stream matrix), γ of fields with and without l = 1,
// and the scale decomposition's defining properties (W_s commutes with ψ; W_s = W at a steady
// state). The grid (systems/spherical_harmonic_grid.h) against Boost.Math's spherical harmonics
// and the closed form of the planetary vorticity, 2Ω cos θ.

#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_grid.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_spectra.h>
#include <gtest/gtest.h>

#include <boost/math/special_functions/spherical_harmonic.hpp>
#include <cmath>
#include <random>

namespace ddb::test {
namespace zeitlin_spectra_tests {

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

// γ from the matrix (three l = 1 harmonics) is γ from every coefficient.
TEST(ZeitlinSpectra, GammaFromTheMatrixIsGammaFromTheCoefficients) {
  for (const Eigen::Index n : {4, 9, 20}) {
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
    const ZeitlinGammaFromMatrix gamma(basis);
    for (const std::uint64_t seed : {1, 2, 3}) {
      Matrix W = randomVorticity(n, seed);
      W += double(seed) * basis.element(1, 0) - 0.3 * basis.element(1, 1);
      const double expected = zeitlinGamma(basis.coefficients(W));
      EXPECT_GT(expected, 0.05);
      EXPECT_NEAR(gamma(W), expected, 1e-14) << "N = " << n << ", seed " << seed;
    }
    EXPECT_EQ(gamma(Matrix::Zero(n, n)), 0.0);
  }
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

// The grid of N = 5, 16, 33 is MW sampling, and F = 2Ω X₃ is 2Ω cos θ there: the quantisation's
// scale, which fixes the factor √(4π).
TEST(SphericalHarmonicGrid, ThePlanetaryVorticityIsTwoOmegaCosTheta) {
  for (const Eigen::Index n : {5, 16, 33}) {
    const SphericalHarmonicGrid grid(n);
    ASSERT_EQ(grid.colatitudes().size(), n);
    ASSERT_EQ(grid.longitudes().size(), 2 * n - 1);
    EXPECT_NEAR(grid.colatitudes()(0), M_PI / double(2 * n - 1), 1e-15);
    EXPECT_NEAR(grid.longitudes()(1), 2.0 * M_PI / double(2 * n - 1), 1e-15);
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
    const double rotation = 1.7;
    const Eigen::MatrixXd f =
        grid.evaluate(basis.coefficients(zeitlinPlanetaryVorticity(n, rotation)));
    ASSERT_EQ(f.rows(), n);
    ASSERT_EQ(f.cols(), 2 * n - 1);
    for (Eigen::Index j = 0; j < n; ++j) {
      for (Eigen::Index k = 0; k < f.cols(); ++k) {
        EXPECT_NEAR(f(j, k), 2.0 * rotation * std::cos(grid.colatitudes()(j)), 1e-13)
            << "N = " << n << ", j = " << j << ", k = " << k;
      }
    }
  }
}

// Random coefficients of every degree l < N = 24 against √(4π) Σ ω_lm Y_lm with Y_lm from
// Boost.Math (complex harmonics with the Condon–Shortley phase; the real ones of the conventions
// are √2 (−1)^m Re Y_l^m for m > 0 and √2 (−1)^m Im Y_l^|m| for m < 0).
TEST(SphericalHarmonicGrid, EveryDegreeAgreesWithBoostsHarmonics) {
  const Eigen::Index n = 24;
  const SphericalHarmonicGrid grid(n);
  std::mt19937_64 random(11);
  std::normal_distribution<double> normal;
  Eigen::VectorXd omega(n * n);
  for (Eigen::Index i = 0; i < omega.size(); ++i) omega(i) = normal(random);
  const Eigen::MatrixXd f = grid.evaluate(omega);
  double largest = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double theta = grid.colatitudes()(j);
    for (Eigen::Index k = 0; k < f.cols(); ++k) {
      const double phi = grid.longitudes()(k);
      double expected = 0.0;
      for (int l = 0; l < int(n); ++l) {
        for (int m = -l; m <= l; ++m) {
          const double sign = (m % 2 == 0) ? 1.0 : -1.0;
          const double y =
              m == 0 ? boost::math::spherical_harmonic_r(l, 0, theta, phi)
              : m > 0
                  ? std::sqrt(2.0) * sign * boost::math::spherical_harmonic_r(l, m, theta, phi)
                  : std::sqrt(2.0) * sign * boost::math::spherical_harmonic_i(l, -m, theta, phi);
          expected += omega(SphericalHarmonicBasis::index(l, m)) * y;
        }
      }
      expected *= std::sqrt(4.0 * M_PI);
      largest = std::max(largest, std::abs(expected));
      EXPECT_NEAR(f(j, k), expected, 1e-11) << "j = " << j << ", k = " << k;
    }
  }
  EXPECT_GT(largest, 10.0);  // the values compared are not all small
}

TEST(SphericalHarmonicGrid, CoefficientsOfAnotherResolutionAreRefused) {
  EXPECT_THROW(SphericalHarmonicGrid(4).evaluate(Eigen::VectorXd::Zero(15)), InvalidArgument);
  EXPECT_THROW(SphericalHarmonicGrid(0), InvalidArgument);
}

}  // namespace zeitlin_spectra_tests
}  // namespace ddb::test

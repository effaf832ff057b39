// Zeitlin's SU(N) fluid (docs/reference/conventions.md §2), each property against something the
// library did not use to compute it: Eigen's eigensolver on the dense Laplacian, the
// defining orthonormality of T_lm, central differences along the flow, the isospectral
// midpoint rule written here from its own formula, the adaptive reference solver.
#include <ddb/core/detail/dense_lu.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/solvers/correction_predictor.h>
#include <ddb/integrators/solvers/matrix_legendre_ceres.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

#include "order_fit.h"

namespace ddb::test {
namespace {

using Matrix = Eigen::MatrixXcd;

// The dense real N²×N² matrix of Δ_N acting on gl(N) (real matrices: the coefficients
// are real, so this is the operator's matrix in the basis E_ij).
Eigen::MatrixXd denseLaplacian(const HoppeYauLaplacian& laplacian) {
  const Eigen::Index n = laplacian.size();
  Eigen::MatrixXd dense(n * n, n * n);
  Matrix unit = Matrix::Zero(n, n), image(n, n);
  for (Eigen::Index k = 0; k < n * n; ++k) {
    unit.data()[k] = 1.0;
    laplacian.apply(unit, image);
    unit.data()[k] = 0.0;
    dense.col(k) = image.real().reshaped();
  }
  return dense;
}

class LaplacianSpectrum : public ::testing::TestWithParam<int> {};

TEST_P(LaplacianSpectrum, EigenvaluesAreMinusLLPlusOneWithMultiplicity2LPlus1) {
  const int n = GetParam();
  const Eigen::MatrixXd dense = denseLaplacian(HoppeYauLaplacian(n));
  EXPECT_LT((dense - dense.transpose()).norm(), 1e-12 * dense.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(dense, Eigen::EigenvaluesOnly);
  std::vector<double> expected;  // on gl(N): l = 0 (the identity) once, then 2l + 1 each
  for (int l = 0; l < n; ++l) {
    for (int k = 0; k < 2 * l + 1; ++k) expected.push_back(-double(l) * (l + 1));
  }
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(eigen.eigenvalues().size(), Eigen::Index(expected.size()));
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(eigen.eigenvalues()(Eigen::Index(i)), expected[i], 1e-12 * n * n) << i;
  }
}
INSTANTIATE_TEST_SUITE_P(N, LaplacianSpectrum, ::testing::Values(5, 16),
                         [](const auto& info) { return "N" + std::to_string(info.param); });

TEST(HoppeYauLaplacian, PoissonSolveInvertsTheLaplacianOnSuN) {
  for (int n : {2, 3, 8, 33}) {
    const HoppeYauLaplacian laplacian(n);
    const Matrix W = randomVorticity(n, 7);
    Matrix P(n, n), back(n, n);
    laplacian.solve(W, P);
    laplacian.apply(P, back);
    EXPECT_LT((back - W).norm(), 1e-12 * W.norm()) << "N = " << n;
    EXPECT_LT(std::abs(P.trace()), 1e-14 * P.norm()) << "N = " << n;
    // On u(N) the solve uses the traceless part: adding i·I changes nothing.
    Matrix shifted = W;
    shifted.diagonal().array() += std::complex<double>(0, 0.3);
    Matrix Q(n, n);
    laplacian.solve(shifted, Q);
    EXPECT_LT((Q - P).norm(), 1e-13 * P.norm()) << "N = " << n;
  }
}

// One diagonal at a time (the distributed solve's path, docs/design/distributed.md): the diagonals
// solved separately and put back together are inverted by apply, as solve's are.
TEST(HoppeYauLaplacian, SolvingEachDiagonalAloneInvertsTheLaplacian) {
  for (int n : {2, 3, 8, 33}) {
    const HoppeYauLaplacian laplacian(n);
    const Matrix W = randomVorticity(n, 9);
    Matrix P(n, n), back(n, n);
    for (int m = -(n - 1); m < n; ++m) {
      const int length = n - std::abs(m), row = m >= 0 ? 0 : -m, col = m >= 0 ? m : 0;
      Eigen::VectorXcd values = W.block(row, col, length, length).diagonal();
      laplacian.solveDiagonal(m, values);
      P.block(row, col, length, length).diagonal() = values;
    }
    laplacian.apply(P, back);
    EXPECT_LT((back - W).norm(), 1e-12 * W.norm()) << "N = " << n;
    EXPECT_LT(std::abs(P.trace()), 1e-14 * P.norm()) << "N = " << n;
  }
  Eigen::VectorXcd one(1);
  EXPECT_THROW(HoppeYauLaplacian(4).solveDiagonal(4, one), InvalidArgument);
  EXPECT_THROW(HoppeYauLaplacian(4).solveDiagonal(2, one), InvalidArgument);
}

TEST(SphericalHarmonicBasis, OrthonormalEigenmatricesWithT10EqualRoot3X3) {
  for (int n : {2, 5, 9}) {
    const HoppeYauLaplacian laplacian(n);
    const SphericalHarmonicBasis basis(laplacian);
    std::vector<Matrix> T;
    std::vector<int> ls;
    for (int l = 0; l < n; ++l) {
      for (int m = -l; m <= l; ++m) {
        T.push_back(basis.element(l, m));
        ls.push_back(l);
      }
    }
    for (size_t a = 0; a < T.size(); ++a) {
      EXPECT_LT((T[a] + T[a].adjoint()).norm(), 1e-13) << "skew-Hermitian";
      Matrix image(n, n);
      laplacian.apply(T[a], image);
      EXPECT_LT((image + double(ls[a] * (ls[a] + 1)) * T[a]).norm(), 1e-11 * (1 + ls[a] * ls[a]));
      for (size_t b = 0; b < T.size(); ++b) {
        const double inner = (T[a].adjoint() * T[b]).trace().real() / n;
        EXPECT_NEAR(inner, a == b ? 1.0 : 0.0, 1e-12) << a << ", " << b;
      }
    }
    EXPECT_LT((basis.element(1, 0) - std::sqrt(3.0) * zeitlinX3(n)).norm(), 1e-13) << n;
    const Matrix W = randomVorticity(n, 3);
    EXPECT_LT((basis.matrix(basis.coefficients(W)) - W).norm(), 1e-13 * W.norm());
  }
}

// The transform against one built on Eigen's QR eigenvectors of each diagonal block (the
// eigensolver the basis used before its twisted factorisations; docs/reference/conventions.md §2's
// conventions, written out here), and the round trip at sizes where the blocks' eigenvalues
// spread over four orders of magnitude.
TEST(SphericalHarmonicBasis, CoefficientsMatchEigensEigenvectorsOfEachBlock) {
  for (int n : {2, 17, 48, 129}) {
    const HoppeYauLaplacian laplacian(n);
    const SphericalHarmonicBasis basis(laplacian);
    const Matrix W = randomVorticity(n, 5);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(n * n);
    Eigen::VectorXd diagonal, subdiagonal;
    for (int m = 0; m < n; ++m) {
      laplacian.block(m, diagonal, subdiagonal);
      Eigen::MatrixXd v = Eigen::MatrixXd::Ones(1, 1);
      if (n - m > 1) {
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
        eigen.computeFromTridiagonal(diagonal, subdiagonal);
        ASSERT_LT((eigen.eigenvalues().reverse().array() -
                   Eigen::ArrayXd::LinSpaced(n - m, m, n - 1).unaryExpr([](double l) {
                     return -l * (l + 1);
                   }))
                      .abs()
                      .maxCoeff(),
                  1e-9 * n * n)
            << "the block's eigenvalues are -l(l+1)";
        v = eigen.eigenvectors().rowwise().reverse();
      }
      const double sign = m % 2 == 0 ? 1.0 : -1.0;
      for (int l = m; l < n; ++l) {
        Eigen::VectorXd vl = v.col(l - m) * std::sqrt(double(n)) / v.col(l - m).norm();
        if (vl(n - m - 1) * sign < 0) vl = -vl;
        double plus = 0, minus = 0;
        for (int k = 0; k < n - m; ++k) {
          plus += vl(k) * (m == 0 ? W(k, k).imag() : (W(k, k + m) + W(k + m, k)).imag());
          minus += m == 0 ? 0.0 : vl(k) * (W(k, k + m) - W(k + m, k)).real();
        }
        const double scale = m == 0 ? 1.0 / n : sign / (std::sqrt(2.0) * n);
        expected(SphericalHarmonicBasis::index(l, m)) = scale * plus;
        if (m > 0) expected(SphericalHarmonicBasis::index(l, -m)) = scale * minus;
      }
    }
    const Eigen::VectorXd omega = basis.coefficients(W);
    EXPECT_LT((omega - expected).norm(), 1e-12 * expected.norm()) << "N = " << n;
    EXPECT_LT((basis.matrix(omega) - W).norm(), 1e-12 * W.norm()) << "N = " << n;
  }
}

// dE/dt = −α‖[P, W]‖²/(ħN) against the central difference of E along the vector field;
// Z constant along it.
TEST(ZeitlinFluid, EnergyRateMatchesCentralDifferencesAndEnstrophyIsConstant) {
  const int n = 12;
  for (double alpha : {0.0, 0.5, -0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    const auto& hamiltonian = static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian());
    const ZeitlinDiagnostics diagnostics(hamiltonian);
    const Matrix W = randomVorticity(n, 11);
    const Matrix F = fluid->vectorField(W);
    const double eps = 1e-5;
    const Matrix plus = W + eps * F, minus = W - eps * F;
    const double dE = (diagnostics.energy(plus) - diagnostics.energy(minus)) / (2 * eps);
    const double expected =
        -alpha * std::pow(diagnostics.commutatorNorm(W), 2) / (hamiltonian.hbar() * n);
    EXPECT_NEAR(dE, expected, 1e-8 * std::max(1.0, std::abs(expected))) << alpha;
    const double dZ = (diagnostics.enstrophy(plus) - diagnostics.enstrophy(minus)) / (2 * eps);
    EXPECT_NEAR(dZ, 0.0, 1e-9) << alpha;
    // The library's energy H is N·E/ħ.
    EXPECT_NEAR(fluid->energy(W), n * diagnostics.energy(W) / hamiltonian.hbar(), 1e-12);
  }
}

double stepSize(const Matrix& W, double fraction) {
  const Eigen::Index n = W.rows();
  const ZeitlinHamiltonian hamiltonian(n);
  const Eigen::JacobiSVD<Matrix> svd(hamiltonian.streamMatrix(W));
  return fraction * zeitlinHbar(n) / svd.singularValues()(0);
}

TEST(ZeitlinFluid, DdbKeepsTheSpectrumAndMovesTheEnergyOneWay) {
  const int n = 32;
  for (double alpha : {0.5, -0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    const ZeitlinDiagnostics diagnostics(
        static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
    const Matrix W0 = randomVorticity(n, 1);
    const Eigen::VectorXd spectrum0 = SUN::casimirs(W0);
    auto method = makeMethod<SUN>("ddb-cay", fluid);
    // h = 0.02 ħ/‖P₀‖₂ (the benchmark's step). With α < 0 the energy grows 50-fold and
    // ‖[P, W]‖ 18-fold from this state; at 0.1 ħ/‖P₀‖₂ the step then no longer resolves
    // the flow and the energy reverses by up to 7.5% (docs/design/architecture.md, "Measured").
    const double h = stepSize(W0, 0.02);
    double drift = 0.0, previous = diagnostics.energy(W0);
    int wrong_way = 0;
    integrate(*method, W0, 0.0, h, 1000, [&](long, double, const Matrix& W) {
      drift = std::max(drift, (SUN::casimirs(W) - spectrum0).norm() / spectrum0.norm());
      const double energy = diagnostics.energy(W);
      if (alpha * (energy - previous) > 1e-15 * std::abs(previous)) ++wrong_way;
      previous = energy;
    });
    std::cout << "alpha=" << alpha << " spectrum drift " << drift << " E0 "
              << diagnostics.energy(W0) << " E " << previous << "\n";
    EXPECT_LE(drift, 1e-12) << alpha;
    EXPECT_EQ(wrong_way, 0) << alpha;
    EXPECT_NE(previous, diagnostics.energy(W0));
  }
}

// The exact flow loses energy (dE/dt = −α‖[P, W]‖_F²/(ħN) ≤ 0 for α > 0), and so does
// DDB Cayley within the stability bound of its dissipative factor, which is explicit in
// the state: the stiffness s = h|α|‖W‖₂²/ħ (‖W‖₂ a Casimir) must stay below about 6. At
// s = 4 the energy falls at every step, at s = 10 a period-2 mode of the large scales
// grows and the energy rises (docs/design/architecture.md, "Large N: the step's stability bound";
// the benchmark's h = 0.02 ħ/‖P₀‖₂ reaches s = 8.5 at N = 512).
TEST(ZeitlinFluid, DdbCayleysEnergyFallsWithinTheDissipationsStabilityBound) {
  const double alpha = 0.5;
  for (int n : {32, 64}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    const ZeitlinDiagnostics diagnostics(
        static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
    const Matrix W0 = randomVorticity(n, 1);
    const double norm = SUN::casimirs(W0).cwiseAbs().maxCoeff();  // ‖W₀‖₂
    for (double stiffness : {4.0, 10.0}) {
      auto method = makeMethod<SUN>("ddb-cay", fluid);
      const double h = stiffness * zeitlinHbar(n) / (alpha * norm * norm);
      double previous = diagnostics.energy(W0), largest = previous;
      int rises = 0;
      // The unstable runs reach their largest energy within 40 steps (and take many sweeps).
      const long steps = stiffness < 6.0 ? 200 : 40;
      integrate(*method, W0, 0.0, h, steps, [&](long, double, const Matrix& W) {
        const double energy = diagnostics.energy(W);
        if (energy - previous > 1e-15 * previous) ++rises;
        largest = std::max(largest, energy);
        previous = energy;
      });
      if (stiffness < 6.0) {
        EXPECT_EQ(rises, 0) << "N = " << n << ", s = " << stiffness;
      } else {
        EXPECT_GT(largest, 1.5 * diagnostics.energy(W0)) << "N = " << n << ", s = " << stiffness;
      }
    }
  }
}

// The isospectral midpoint rule for Ẇ = [B(W), W], B = P/ħ, from its own formula:
//   W_k = (I − hB/2) W̃ (I + hB/2),  W_{k+1} = (I + hB/2) W̃ (I − hB/2),  B = B(W̃).
Matrix isospectralMidpoint(const ZeitlinHamiltonian& hamiltonian, const Matrix& W, double h) {
  const Eigen::Index n = W.rows();
  const Matrix I = Matrix::Identity(n, n);
  Matrix tilde = W;
  for (int k = 0; k < 500; ++k) {
    const Matrix B = hamiltonian.streamMatrix(tilde) / hamiltonian.hbar();
    // W̃ = (I − hB/2)⁻¹ W (I + hB/2)⁻¹
    const Matrix next = (I - 0.5 * h * B).inverse() * W * (I + 0.5 * h * B).inverse();
    const double change = (next - tilde).norm();
    tilde = next;
    if (change < 1e-16 * W.norm()) break;
  }
  const Matrix B = hamiltonian.streamMatrix(tilde) / hamiltonian.hbar();
  return (I + 0.5 * h * B) * tilde * (I - 0.5 * h * B);
}

TEST(ZeitlinFluid, AtAlphaZeroDdbCayleyIsTheIsospectralMidpoint) {
  const int n = 16;
  const auto fluid = makeZeitlinFluid(n, 0.0);
  const ZeitlinHamiltonian hamiltonian(n);
  const Matrix W0 = randomVorticity(n, 5);
  // The DDB step conjugates W_k, the midpoint rule reads out from W̃: they agree to
  // rounding per step, and this flow amplifies a 1e-16 perturbation 26-fold over 100
  // steps at h = 0.05 ħ/‖P₀‖₂ (1141-fold at 0.2, where rounding alone reaches 4e-13).
  const double h = stepSize(W0, 0.05);
  auto method = makeMethod<SUN>("ddb-cay", fluid);
  Matrix ddb = W0, midpoint = W0;
  for (int k = 0; k < 100; ++k) {
    ddb = method->step(ddb, k * h, h);
    midpoint = isospectralMidpoint(hamiltonian, midpoint, h);
  }
  std::cout << "DDB Cayley vs isospectral midpoint after 100 steps: "
            << (ddb - midpoint).norm() / W0.norm() << " relative\n";
  EXPECT_LT((ddb - midpoint).norm(), 1e-13 * W0.norm());
}

TEST(ZeitlinFluid, ZonalAndL1StatesAreFixedByOneStep) {
  const int n = 12;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  const Matrix l1 = 0.3 * basis.element(1, -1) - 0.7 * basis.element(1, 0) +
                    0.5 * basis.element(1, 1);  // a pure l = 1 element
  for (double alpha : {0.0, 0.5, -0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    for (const Matrix& W : {zonalVorticity(n, 2), l1}) {
      auto method = makeMethod<SUN>("ddb-cay", fluid);
      const Matrix next = method->step(W, 0.0, stepSize(W, 0.5));
      EXPECT_LT((next - W).norm(), 1e-14 * W.norm()) << alpha;
    }
  }
}

TEST(ZeitlinFluid, EnergyAscentOnTheL1OrbitReachesHalfTheEnstrophy) {
  // W = U X₃ Uᴴ (random U) lies on the isospectral orbit of the l = 1 element X₃ but is
  // not itself l = 1; with α < 0 the energy rises to the orbit's maximum E/Z = ½.
  const int n = 12;
  const auto fluid = makeZeitlinFluid(n, -0.5);
  const ZeitlinDiagnostics diagnostics(
      static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
  Matrix W = l1Vorticity(n, 4);
  const double ratio0 = diagnostics.energy(W) / diagnostics.enstrophy(W);
  auto method = makeMethod<SUN>("ddb-cay", fluid);
  integrate(*method, W, 0.0, 0.05, 4000, [&](long, double, const Matrix& state) { W = state; });
  const double ratio = diagnostics.energy(W) / diagnostics.enstrophy(W);
  std::cout << "E/Z: " << ratio0 << " -> " << ratio << "\n";
  EXPECT_LT(ratio0, 0.49);
  EXPECT_NEAR(ratio, 0.5, 1e-6);
}

// Fixed point, Newton–Krylov and Ceres solve the same Legendre equation to 1e-12.
TEST(MatrixLegendreSolver, FixedPointNewtonKrylovAndCeresAgree) {
  const int n = 8;  // u(8): 64 unknowns, the largest Ceres is asked to take
  const auto fluid = makeZeitlinFluid(n, 0.5);
  const Matrix W = randomVorticity(n, 21);
  const double h = stepSize(W, 0.8);
  std::vector<Matrix> results;
  for (auto strategy : {MatrixLegendreStrategy::kFixedPoint, MatrixLegendreStrategy::kNewtonKrylov,
                        MatrixLegendreStrategy::kExternal}) {
    Ddb<Cayley<SUN>> method(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian);
    if (strategy == MatrixLegendreStrategy::kExternal) {
      useCeres(method.legendreSolver());
    } else {
      method.legendreSolver().setStrategy(strategy);
    }
    results.push_back(method.step(W, 0.0, h));
    const auto& stats = method.legendreSolver().stats();
    std::cout << "strategy " << int(strategy) << ": fixed point " << stats.fixed_point
              << ", Newton " << stats.newton << ", Krylov " << stats.krylov << ", residual "
              << stats.residual << "\n";
  }
  EXPECT_LT((results[1] - results[0]).norm(), 1e-12 * W.norm());
  EXPECT_LT((results[2] - results[0]).norm(), 1e-12 * W.norm());
}

TEST(MatrixLegendreSolver, NewtonKrylovTakesOverWhereTheFixedPointStalls) {
  // h‖P‖₂/ħ ≈ 1.5: the fixed point contracts too slowly (docs/reference/conventions.md §2).
  const int n = 12;
  const auto fluid = makeZeitlinFluid(n, 0.5);
  const Matrix W = randomVorticity(n, 8);
  Ddb<Cayley<SUN>> method(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian);
  const Matrix next = method.step(W, 0.0, stepSize(W, 1.5));
  EXPECT_GT(method.legendreSolver().stats().newton, 0);
  EXPECT_LT((SUN::casimirs(next) - SUN::casimirs(W)).norm(), 1e-13 * W.norm());
}

// Any sequence obeying a linear recurrence of order <= 6 (polynomials of degree <= 5 in k,
// geometric sequences and their sums) is continued exactly by the linear prediction; the
// closed form of the next term is the reference.
TEST(CorrectionPredictor, ContinuesSequencesThatObeyALinearRecurrence) {
  const int n = 9;
  const Matrix A = randomVorticity(n, 31), B = randomVorticity(n, 32), C = randomVorticity(n, 33);
  const Matrix near = randomVorticity(n, 34);
  const std::vector<std::function<Matrix(int)>> sequences = {
      [&](int k) { return Matrix(A + k * B + 0.5 * k * k * C); },  // degree 2
      [&](int k) { return Matrix(1e-3 * std::pow(k, 5) * A + std::pow(k, 3) * B - C); },
      [&](int k) { return Matrix(A + std::pow(0.5, k) * B + std::pow(-0.3, k) * C); },
      [&](int k) { return Matrix(std::pow(0.9, k) * A + k * std::pow(0.9, k) * B + C); },
  };
  for (std::size_t i = 0; i < sequences.size(); ++i) {
    CorrectionPredictor<Matrix> predictor;
    Matrix guess(n, n);
    const int warm = CorrectionPredictor<Matrix>::kOrder + 3;  // the full order from here on
    for (int k = 0; k < warm; ++k) predictor.remember(near + sequences[i](k), near);
    EXPECT_EQ(predictor.order(), CorrectionPredictor<Matrix>::kOrder);
    for (int k = warm; k < warm + 5; ++k) {
      predictor.predict(near, guess);
      const Matrix expected = near + sequences[i](k);
      EXPECT_LT((guess - expected).norm(), 1e-9 * expected.norm())
          << "sequence " << i << " k " << k;
      predictor.remember(expected, near);
    }
  }
}

// A predicted correction more than twice the largest remembered one is not trusted (a
// state off the remembered trajectory, a caller that skipped reset()): the guess is then
// the newest correction. Corrections tripling at each step predict a tripled one.
TEST(CorrectionPredictor, APredictionBeyondTwiceTheRememberedCorrectionsFallsBackToTheNewest) {
  const int n = 6;
  const Matrix near = randomVorticity(n, 41), step = randomVorticity(n, 42);
  CorrectionPredictor<Matrix> predictor;
  Matrix newest;
  for (int k = 0; k < 12; ++k) {
    newest = std::pow(3.0, k) * step;
    predictor.remember(near + newest, near);
  }
  Matrix guess(n, n);
  predictor.predict(near, guess);
  EXPECT_LT((guess - (near + newest)).norm(), 1e-12 * newest.norm());
}

// The LAPACK (or Eigen LU) solves against Eigen's own inverse(), real and complex, with a
// right-hand side of another width than N; a singular matrix is reported.
TEST(DenseLu, SolvesAgreeWithEigensInverseAndASingularMatrixIsReported) {
  for (int n : {1, 2, 7, 40}) {
    Matrix A = Matrix::Random(n, n);
    A.diagonal().array() += 3.0;
    const Matrix rhs = Matrix::Random(n, n + 3);
    Matrix factors = A, solution = rhs;
    DenseLu<Matrix> complex_lu;
    ASSERT_TRUE(complex_lu.factor(factors));
    complex_lu.solve(factors, solution);
    const Matrix expected = A.inverse() * rhs;
    EXPECT_LT((solution - expected).norm(), 1e-13 * expected.norm()) << n;
    // A second solve with the same factors (the Cayley conjugation makes two).
    complex_lu.solve(factors, solution);
    const Matrix expected_twice = A.inverse() * expected;
    EXPECT_LT((solution - expected_twice).norm(), 1e-13 * expected_twice.norm()) << n;
    Eigen::MatrixXd R = Eigen::MatrixXd::Random(n, n) + 3.0 * Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd real_rhs = Eigen::MatrixXd::Random(n, 2);
    Eigen::MatrixXd real_factors = R, real_solution = real_rhs;
    DenseLu<Eigen::MatrixXd> real;
    ASSERT_TRUE(real.factor(real_factors));
    real.solve(real_factors, real_solution);
    const Eigen::MatrixXd real_expected = R.inverse() * real_rhs;
    EXPECT_LT((real_solution - real_expected).norm(), 1e-13 * real_expected.norm()) << n;
  }
  Matrix singular = Matrix::Zero(3, 3);
  DenseLu<Matrix> lu;
  EXPECT_FALSE(lu.factor(singular));
}

// One DDB Cayley step equals Uᴴ M U with U = cay(2a) cay(2b), a = hξ(p)/2 and
// b = α[p, a], formed here with Eigen's inverse: the one-product update through the
// certified frozen solution (M − 2[a, p̃]) is that conjugation to rounding.
TEST(MatrixCayleyTransport, TheCertifiedOneProductUpdateIsTheCayleyConjugation) {
  const int n = 24;
  for (double alpha : {0.0, 0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    Matrix W = randomVorticity(n, 51);
    const double h = stepSize(W, 0.05);
    Ddb<Cayley<SUN>> method(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian);
    int certified = 0;
    for (int k = 0; k < 20; ++k) {
      const Matrix M = W;
      method.advance(W, k * h, h);
      const auto& solver = method.legendreSolver();
      if (solver.frozenSolution() != nullptr) ++certified;
      const Matrix& a = solver.halfStep();
      const Matrix& p = solver.solution();
      const Matrix I = Matrix::Identity(n, n);
      const Matrix b = alpha * (p * a - a * p);
      const Matrix U = (I - a).inverse() * (I + a) * (I - b).inverse() * (I + b);
      EXPECT_LT((W - U.adjoint() * M * U).norm(), 1e-14 * M.norm()) << alpha << " step " << k;
    }
    EXPECT_GE(certified, 15) << alpha;  // the cheap update is the common case
  }
}

// Orders against the adaptive reference, N = 8, t in [0, 1] (docs/reference/conventions.md §2).
struct FluidOrderCase {
  const char* method;
  double alpha;
  double expected;
};

class FluidOrder : public ::testing::TestWithParam<FluidOrderCase> {};

TEST_P(FluidOrder, FittedSlopeAgainstTheReference) {
  const auto& c = GetParam();
  const int n = 8;
  const auto fluid = makeZeitlinFluid(n, c.alpha);
  const Matrix W0 = randomVorticity(n, 1);
  const double t_end = 1.0;
  auto finalState = [&](const std::string& name, int steps) {
    auto method = makeMethod<SUN>(name, fluid);
    Matrix last;
    integrate(*method, W0, 0.0, t_end / steps, steps,
              [&](long, double, const Matrix& W) { last = W; });
    return last;
  };
  const Matrix reference = finalState("reference", 1);
  std::vector<double> hs, errors;
  for (int steps : {20, 40, 80, 160, 320}) {
    hs.push_back(t_end / steps);
    errors.push_back((finalState(c.method, steps) - reference).norm());
  }
  const OrderFit fit = fitOrder(hs, errors, 1e-11);
  std::cout << c.method << " alpha=" << c.alpha << " slope=" << fit.slope << "\n";
  ASSERT_GE(fit.points, 4);
  EXPECT_NEAR(fit.slope, c.expected, 0.15);
}
INSTANTIATE_TEST_SUITE_P(Zeitlin, FluidOrder,
                         ::testing::Values(FluidOrderCase{"ddb-cay", 0.0, 2},
                                           FluidOrderCase{"ddb-cay", 0.5, 1},
                                           FluidOrderCase{"ddb-cay", -0.5, 1},
                                           FluidOrderCase{"sddb-cay", 0.5, 2}),
                         [](const auto& info) {
                           const double a = info.param.alpha;
                           std::string name = std::string(info.param.method) +
                                              (a < 0 ? "_alpha_minus" : "_alpha_") +
                                              std::to_string(int(std::abs(a) * 10));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(ZeitlinFluid, Rk4LeavesTheOrbitWhereDdbStaysOnIt) {
  const int n = 16;
  const auto fluid = makeZeitlinFluid(n, 0.5);
  const Matrix W0 = randomVorticity(n, 2);
  const Eigen::VectorXd spectrum0 = SUN::casimirs(W0);
  const double h = stepSize(W0, 0.2);
  for (const char* name : {"rk4", "ddb-cay"}) {
    auto method = makeMethod<SUN>(name, fluid);
    Matrix last;
    integrate(*method, W0, 0.0, h, 200, [&](long, double, const Matrix& W) { last = W; });
    const double drift = (SUN::casimirs(last) - spectrum0).norm() / spectrum0.norm();
    std::cout << name << " spectrum drift " << drift << "\n";
    if (std::string(name) == "rk4") {
      EXPECT_GT(drift, 1e-10);
    } else {
      EXPECT_LT(drift, 1e-13);
    }
  }
}

TEST(ZeitlinFluid, BadStatesAreRejectedWithTheirSizeAndWorstEntry) {
  const int n = 40;
  Matrix W = randomVorticity(n, 3);
  EXPECT_NO_THROW(SUN::requireState("W", W));
  Matrix hermitian = W;
  hermitian(3, 5) += 1.0;
  try {
    SUN::requireState("W", hermitian);
    FAIL() << "not skew-Hermitian accepted";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("40x40"), std::string::npos) << what;
    EXPECT_LT(what.size(), 300u) << what;
  }
  Matrix traced = W;
  traced.diagonal().array() += std::complex<double>(0, 0.1);
  EXPECT_THROW(SUN::requireState("W", traced), InvalidArgument);
  Matrix nan = W;
  nan(1, 1) = std::complex<double>(NAN, 0);
  EXPECT_THROW(SUN::requireState("W", nan), InvalidArgument);
  EXPECT_THROW(SUN::requireState("W", Matrix::Zero(1, 1)), InvalidArgument);
  EXPECT_THROW(makeZeitlinFluid(1, 0.5), InvalidArgument);
  EXPECT_THROW(makeZeitlinFluid(8, NAN), InvalidArgument);
}

}  // namespace
}  // namespace ddb::test

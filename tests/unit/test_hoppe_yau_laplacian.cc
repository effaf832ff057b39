// The Hoppe–Yau Laplacian Δ_N on gl(N) (docs/reference/conventions.md §2): its spectrum against
// Eigen's eigensolver on the dense N²×N² matrix, and its Poisson solve, whole and one diagonal
// at a time, inverted by apply.

#include <ddb/core/errors.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <string>

namespace ddb::test {
namespace hoppe_yau_laplacian_tests {

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

}  // namespace hoppe_yau_laplacian_tests
}  // namespace ddb::test

// The spherical-harmonic basis T_lm of u(N) (docs/reference/conventions.md §2): the defining
// orthonormality and eigenvalues, T_10 = √3 X3, and the transform against one built on Eigen's
// eigenvectors of each diagonal block.

#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

namespace ddb::test {
namespace spherical_harmonic_basis_tests {

using Matrix = Eigen::MatrixXcd;

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

}  // namespace spherical_harmonic_basis_tests
}  // namespace ddb::test

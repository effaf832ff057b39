// The dense backend's LU (core/detail/dense_lu.h) against Eigen's own inverse().

#include <ddb/core/detail/dense_lu.h>
#include <gtest/gtest.h>

#include <Eigen/LU>

namespace ddb::test {
namespace dense_lu_tests {

using Matrix = Eigen::MatrixXcd;

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

}  // namespace dense_lu_tests
}  // namespace ddb::test

// The dense matrix backend's reductions (core/matrix_backend.h) against loops over the
// entries with std::abs and std::norm, at ordinary scales and where squares of entries
// under- or overflow.
#include <ddb/core/matrix_backend.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "test_support.h"

namespace ddb::test {
namespace {

using Matrix = Eigen::MatrixXcd;
using B = MatrixBackend<Matrix>;

TEST(MatrixBackend, OneNormIsTheLargestColumnSumOfModuliAtEveryScale) {
  std::srand(7);
  const Matrix base = Matrix::Random(37, 23);
  // 1e-170: |z|² underflows to 0; 1e170: it overflows to inf. Mixed: one huge column
  // beside ordinary ones, and ordinary entries beside subnormal-squared ones.
  for (const double scale : {1.0, 1e-3, 1e3, 1e-170, 1e170, 1e-300, 1e300}) {
    const Matrix x = scale * base;
    const double expected = oneNormByLoops(x);
    EXPECT_NEAR(B::oneNorm(x), expected, 1e-14 * expected) << "scale " << scale;
  }
  Matrix mixed = base;
  mixed.col(3) *= 1e200;
  EXPECT_NEAR(B::oneNorm(mixed), oneNormByLoops(mixed), 1e-14 * oneNormByLoops(mixed));
  mixed = base;
  mixed.col(5) *= 1e-200;
  EXPECT_NEAR(B::oneNorm(mixed), oneNormByLoops(mixed), 1e-14 * oneNormByLoops(mixed));
  EXPECT_EQ(B::oneNorm(Matrix::Zero(4, 4)), 0.0);
  Matrix infinite = base;
  infinite(2, 2) = {INFINITY, 0.0};
  EXPECT_EQ(B::oneNorm(infinite), INFINITY);
  infinite(2, 2) = {NAN, 0.0};
  EXPECT_TRUE(std::isnan(B::oneNorm(infinite)));
}

}  // namespace
}  // namespace ddb::test

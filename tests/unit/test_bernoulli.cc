// B_j/j! (core/detail/bernoulli.h) against references the table does not use: the exact
// rationals B_{2m} up to j = 30, and for j >= 8 the zeta-function form
// B_{2m}/(2m)! = (-1)^{m+1} 2 ζ(2m) / (2π)^{2m}, both in long double. Every entry must be
// the double nearest to the reference: within half an ulp of it, plus the reference's own
// long-double error (below 1e-17 relative).
#include <ddb/core/detail/bernoulli.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ddb::test {
namespace bernoulli_tests {

/// Whether `value` is the double nearest to `reference` (up to the reference's error).
bool nearest(double value, long double reference) {
  const double ulp = std::nextafter(std::abs(value), INFINITY) - std::abs(value);
  return std::abs(value - reference) <= 0.5L * ulp + 1e-17L * std::abs(reference);
}

long double factorial(int j) {
  long double f = 1.0L;
  for (int i = 2; i <= j; ++i) f *= i;
  return f;
}

TEST(Bernoulli, FirstTermsAreExact) {
  EXPECT_EQ(bernoulliOverFactorial(0), 1.0);
  EXPECT_EQ(bernoulliOverFactorial(1), -0.5);
  EXPECT_EQ(bernoulliOverFactorial(2), 1.0 / 12.0);  // the ddb-exp series stops here
  for (int j = 3; j <= kMaxBernoulliIndex; j += 2) EXPECT_EQ(bernoulliOverFactorial(j), 0.0) << j;
}

TEST(Bernoulli, IsTheNearestDoubleToTheExactRationals) {
  // B_2, B_4, ..., B_30.
  const long double numerator[] = {
      1.0L,      -1.0L,         1.0L,       -1.0L,           5.0L,
      -691.0L,   7.0L,          -3617.0L,   43867.0L,        -174611.0L,
      854513.0L, -236364091.0L, 8553103.0L, -23749461029.0L, 8615841276005.0L};
  const long double denominator[] = {6,   30,  42,  30,   66, 2730, 6,    510,
                                     798, 330, 138, 2730, 6,  870,  14322};
  for (int m = 1; m <= 15; ++m) {
    const int j = 2 * m;
    const long double exact = numerator[m - 1] / denominator[m - 1] / factorial(j);
    const double value = bernoulliOverFactorial(j);
    EXPECT_TRUE(nearest(value, exact)) << "j = " << j;
  }
}

TEST(Bernoulli, IsTheNearestDoubleToTheZetaFormUpToTheLastIndex) {
  const long double two_pi = 2.0L * 3.141592653589793238462643383279502884L;
  for (int j = 8; j <= kMaxBernoulliIndex; j += 2) {
    // ζ(j) - Σ_{n<=2000} n^{-j} < 2000^{1-j}/(j-1): below 1e-22 for j >= 8.
    long double zeta = 0.0L;
    for (int n = 2000; n >= 1; --n) zeta += std::pow(static_cast<long double>(n), -j);
    const long double sign = (j / 2) % 2 == 1 ? 1.0L : -1.0L;
    const long double reference = sign * 2.0L * zeta / std::pow(two_pi, j);
    const double value = bernoulliOverFactorial(j);
    EXPECT_TRUE(nearest(value, reference)) << "j = " << j;
  }
}

}  // namespace bernoulli_tests
}  // namespace ddb::test

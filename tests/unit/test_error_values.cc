// Numbers in the library's error messages (core/errors.h, formatValue): the shortest decimal
// that reads back as the same double, checked against strtod and against printf's %.{p}g for
// p = 1..17 (none that reads back is shorter), on random bit patterns.
#include <ddb/core/errors.h>
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

namespace ddb::test {
namespace error_values_tests {

/// The shortest text printf's %.{p}g gives, p = 1..17, that reads back as x.
std::size_t shortestPrintf(double x) {
  char buffer[64];
  std::size_t shortest = 64;
  for (int p = 1; p <= 17; ++p) {
    const int length = std::snprintf(buffer, sizeof buffer, "%.*g", p, x);
    if (std::strtod(buffer, nullptr) == x) shortest = std::min(shortest, std::size_t(length));
  }
  return shortest;
}

TEST(ErrorValues, ADoubleIsItsShortestDecimalThatReadsBack) {
  EXPECT_EQ(formatValue(-0.1), "-0.1");
  EXPECT_EQ(formatValue(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(formatValue(1e-300), "1e-300");
  EXPECT_EQ(formatValue(NAN), "nan");
  EXPECT_EQ(formatValue(INFINITY), "inf");
  EXPECT_EQ(formatValue(-INFINITY), "-inf");
  std::mt19937_64 random(7);
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = random();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    const std::string text = formatValue(x);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    // No printf form that reads back is shorter (a large integer may be its exact digits,
    // "53165205877497296", where %g would need "5.31652058774973e+16").
    EXPECT_LE(text.size(), shortestPrintf(x)) << text;
  }
}

TEST(ErrorValues, MessagesCarryTheShortestDecimals) {
  const SolveFailure failure("a solve", 3, 0.30000000000000004, 0.1, 2.5e-8, 1e-12);
  EXPECT_STREQ(failure.what(),
               "a solve did not converge at step 3 (t = 0.30000000000000004, h = 0.1): residual "
               "2.5e-08 > tolerance 1e-12");
  const NonFiniteState state("ddb-cay", 2, 0.2, 0.1, Eigen::Vector3d(0.1, NAN, 1.0));
  EXPECT_THAT(state.what(), ::testing::HasSubstr("(t = 0.2, h = 0.1)"));
  EXPECT_THAT(state.what(), ::testing::EndsWith("state = (0.1, nan, 1)"));
  const Eigen::Vector2cd complex(std::complex<double>(0.1, -0.2), std::complex<double>(1, 0));
  EXPECT_EQ(formatValue(complex), "((0.1,-0.2), (1,0))");
  try {
    requirePositive("h", -0.1);
    FAIL() << "h = -0.1 was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "h = -0.1 is invalid: must be finite and > 0");
  }
}

}  // namespace error_values_tests
}  // namespace ddb::test

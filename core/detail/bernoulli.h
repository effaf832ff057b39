// Bernoulli numbers divided by factorials, B_j / j!, with B_1 = -1/2: the
// coefficients of dexp^{-1}_x = Σ_j B_j/j! ad_x^j (paper, eq. (4.14);
// Iserles, Munthe-Kaas, Nørsett and Zanna 2000).
#pragma once

#include <array>
#include <cmath>

namespace ddb {

/// Largest j for which bernoulliOverFactorial(j) is tabulated.
inline constexpr int kMaxBernoulliIndex = 120;

/// B_j / j! for 0 <= j <= kMaxBernoulliIndex.
inline double bernoulliOverFactorial(int j) {
  static const std::array<double, kMaxBernoulliIndex + 1> table = [] {
    std::array<double, kMaxBernoulliIndex + 1> t{};
    // Exact B_{2m} for small indices.
    const double exact[] = {1.0 / 6,
                            -1.0 / 30,
                            1.0 / 42,
                            -1.0 / 30,
                            5.0 / 66,
                            -691.0 / 2730,
                            7.0 / 6,
                            -3617.0 / 510,
                            43867.0 / 798,
                            -174611.0 / 330,
                            854513.0 / 138,
                            -236364091.0 / 2730,
                            8553103.0 / 6,
                            -23749461029.0 / 870,
                            8615841276005.0 / 14322};
    t[0] = 1.0;
    t[1] = -0.5;
    double factorial = 1.0;
    for (int j = 1; j <= kMaxBernoulliIndex; ++j) {
      factorial *= j;
      if (j % 2 == 1) continue;  // B_j = 0 for odd j > 1.
      if (j <= 30) {
        t[j] = exact[j / 2 - 1] / factorial;
      } else {
        // B_{2m}/(2m)! = (-1)^{m+1} 2 ζ(2m) / (2π)^{2m}; ζ(2m) = 1 + 2^{-2m} + ... to round-off.
        double zeta = 0.0;
        for (int n = 1; n <= 6; ++n) zeta += std::pow(n, -j);
        const double sign = (j / 2) % 2 == 1 ? 1.0 : -1.0;
        t[j] = sign * 2.0 * zeta / std::pow(2.0 * M_PI, j);
      }
    }
    return t;
  }();
  return table[j];
}

}  // namespace ddb

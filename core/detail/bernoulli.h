// Bernoulli numbers divided by factorials, B_j / j!, with B_1 = -1/2: the
// coefficients of dexp^{-1}_x = Σ_j B_j/j! ad_x^j (paper, eq. (4.14);
// Iserles, Munthe-Kaas, Nørsett and Zanna 2000). B_{2m} and j! come from Boost.Math,
// divided in long double and rounded once to double (tests/unit/test_bernoulli.cc checks
// every entry against the zeta-function form in long double).
#pragma once

#include <array>
#include <boost/math/special_functions/bernoulli.hpp>
#include <boost/math/special_functions/factorials.hpp>

namespace ddb {

/// Largest j for which bernoulliOverFactorial(j) is tabulated.
inline constexpr int kMaxBernoulliIndex = 120;

/// B_j / j! for 0 <= j <= kMaxBernoulliIndex.
inline double bernoulliOverFactorial(int j) {
  static const std::array<double, kMaxBernoulliIndex + 1> table = [] {
    std::array<double, kMaxBernoulliIndex + 1> t{};  // B_j = 0 for odd j > 1
    t[0] = 1.0;
    t[1] = -0.5;
    for (int j = 2; j <= kMaxBernoulliIndex; j += 2) {
      t[j] = static_cast<double>(boost::math::bernoulli_b2n<long double>(j / 2) /
                                 boost::math::factorial<long double>(static_cast<unsigned>(j)));
    }
    return t;
  }();
  return table[j];
}

}  // namespace ddb

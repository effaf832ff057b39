// Bernoulli numbers divided by factorials, B_j / j!, with B_1 = -1/2: the
// coefficients of dexp^{-1}_x = Σ_j B_j/j! ad_x^j (paper, eq. (4.14);
// Iserles, Munthe-Kaas, Nørsett and Zanna 2000). The even entries are written out as
// hexadecimal literals, each the double nearest to B_j / j! (once computed from Boost.Math's
// B_{2m} and j! in long double, rounded once; a table keeps Boost.Math out of every group's
// header). tests/unit/test_bernoulli.cc checks every entry against the exact rationals and the
// zeta-function form, neither of which is used here.
#pragma once

#include <array>

namespace ddb {

/// Largest j for which bernoulliOverFactorial(j) is tabulated.
inline constexpr int kMaxBernoulliIndex = 120;

namespace detail {
/// B_{2m} / (2m)! for m = 0, ..., kMaxBernoulliIndex / 2.
inline constexpr std::array<double, kMaxBernoulliIndex / 2 + 1> kEvenBernoulliOverFactorial{{
    0x1p+0,
    0x1.5555555555555p-4,
    -0x1.6c16c16c16c17p-10,
    0x1.1566abc011567p-15,
    -0x1.bbd779334ef0bp-21,
    0x1.66a8f2bf70ebep-26,
    -0x1.22805d644267fp-31,
    0x1.d6db2c4e09162p-37,
    -0x1.7da4e1f79955cp-42,
    0x1.355871d652e9ep-47,
    -0x1.f57d968caacf1p-53,
    0x1.967e1f09c376fp-58,
    -0x1.497d9033a2b5cp-63,
    0x1.0b132d7c6ad06p-68,
    -0x1.b0f72d59f1c16p-74,
    0x1.5ef2da4cca26dp-79,
    -0x1.1c77df96de38bp-84,
    0x1.cd299de521b62p-90,
    -0x1.75cde656574a7p-95,
    0x1.2efe8db3b4adfp-100,
    -0x1.eb322904761ffp-106,
    0x1.8e25ff9328464p-111,
    -0x1.42ba1a349b5d3p-116,
    0x1.0597b61cb30d4p-121,
    -0x1.a813f6eaa7073p-127,
    0x1.57bea2950f124p-132,
    -0x1.16a101c5fde97p-137,
    0x1.c3b23b05e39f9p-143,
    -0x1.6e2193ae496d5p-148,
    0x1.28c65557ea2a6p-153,
    -0x1.e11cf33c632a8p-159,
    0x1.85f9bf8d6b2b2p-164,
    -0x1.3c1a3035e663dp-169,
    0x1.00390e238ecb8p-174,
    -0x1.9f5f74b6c869p-180,
    0x1.50b0462832a12p-185,
    -0x1.10e8d36905d5ep-190,
    0x1.ba6c96ed10bc4p-196,
    -0x1.669d9371721f7p-201,
    0x1.22aecc05ace19p-206,
    -0x1.d73cb99591091p-212,
    0x1.7df8723315bfcp-217,
    -0x1.359d1628b7da8p-222,
    0x1.f5ed3bd476459p-228,
    -0x1.96d8b1366dc4p-233,
    0x1.49c6fe119408fp-238,
    -0x1.0b4eb33edc78ap-243,
    0x1.b157ac319d001p-249,
    -0x1.5f4111bbef1f7p-254,
    0x1.1cb745fc9b633p-259,
    -0x1.cd9065a12ae55p-265,
    0x1.762135d3b7626p-270,
    -0x1.2f42151d3e836p-275,
    0x1.eb9fa2508e48dp-281,
    -0x1.8e7ebc0670e83p-286,
    0x1.4302077771e3dp-291,
    -0x1.05d20356e10a9p-296,
    0x1.a8727ac8a00c8p-302,
    -0x1.580b3f036df3ap-307,
    0x1.16df1b02e485dp-312,
    -0x1.c416e6a7847b9p-318,
}};
}  // namespace detail

/// B_j / j! for 0 <= j <= kMaxBernoulliIndex (B_j = 0 for odd j > 1).
constexpr double bernoulliOverFactorial(int j) {
  if (j == 1) return -0.5;
  return j % 2 == 0 ? detail::kEvenBernoulliOverFactorial[j / 2] : 0.0;
}

}  // namespace ddb

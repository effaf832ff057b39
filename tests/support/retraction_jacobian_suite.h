// The generic suite of a fixed-size retraction's ∂_x[(dτ^{-1}_x)* μ]
// (dTauInverseDualJacobian, the Legendre solver's Newton matrix: integrators/solvers/
// legendre_equation.h) and of (dτ^{-1}_x)* as a matrix (dTauInverseDualMatrix), each against what
// it represents. A type-parameterised suite: test_legendre_jacobian.cc instantiates it for the
// basic groups' retractions, test_group_products.cc for the products', in the unit that compiles
// their method tables, whose Newton solves instantiate the same Jacobians (compiled beside those
// tables, the products' cases cost no measurable time; in test_legendre_jacobian.cc, 31 of its
// 69 s: docs/results/compile-costs.md, "The retraction Jacobians of the products").
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "test_support.h"

namespace ddb::test {

/// Central differences of a map R^n → R^n at x, step eps·(1 + |x|).
template <int N, class Map>
Eigen::Matrix<double, N, N> centralDifferences(const Map& f, const Eigen::Matrix<double, N, 1>& x) {
  const double eps = 1e-6 * (1.0 + x.norm());
  Eigen::Matrix<double, N, N> jacobian;
  for (int j = 0; j < N; ++j) {
    Eigen::Matrix<double, N, 1> step = Eigen::Matrix<double, N, 1>::Zero();
    step(j) = eps;
    const Eigen::Matrix<double, N, 1> plus = x + step, minus = x - step;
    jacobian.col(j) = (f(plus) - f(minus)) / (2 * eps);
  }
  return jacobian;
}

template <class R>
class RetractionJacobianTest : public ::testing::Test {};
TYPED_TEST_SUITE_P(RetractionJacobianTest);

TYPED_TEST_P(RetractionJacobianTest, MatchesCentralDifferences) {
  using G = typename TypeParam::Group;
  using V = Eigen::Matrix<double, G::kDim, 1>;
  const TypeParam retraction;
  Sampler s;
  // Small (the series branches), O(1), and up to |ω| = 3 (exp's poles are at 2π).
  for (double size : {1e-4, 0.09, 0.11, 0.5, 1.0, 2.0, 3.0}) {
    const V x = size * s.vector<V>().normalized(), mu = s.vector<V>();
    const auto analytic = retraction.dTauInverseDualJacobian(x, mu);
    const auto numeric = centralDifferences<G::kDim>(
        [&](const V& y) { return V(retraction.dTauInverseDual(y, mu)); }, x);
    EXPECT_LT((analytic - numeric).norm(), 1e-8 * (1 + x.squaredNorm()) * mu.norm())
        << "|x| = " << size;
  }
}

// (dτ^{-1}_x)* as a matrix against the map it represents.
TYPED_TEST_P(RetractionJacobianTest, MatrixRepresentsTheDual) {
  using G = typename TypeParam::Group;
  using V = Eigen::Matrix<double, G::kDim, 1>;
  const TypeParam retraction;
  Sampler s;
  for (double size : {1e-4, 0.5, 3.0}) {
    const V x = size * s.vector<V>().normalized(), mu = s.vector<V>();
    EXPECT_LT((retraction.dTauInverseDualMatrix(x) * mu - retraction.dTauInverseDual(x, mu)).norm(),
              1e-14 * (1 + x.squaredNorm()) * mu.norm())
        << "|x| = " << size;
  }
}

REGISTER_TYPED_TEST_SUITE_P(RetractionJacobianTest, MatchesCentralDifferences,
                            MatrixRepresentsTheDual);

}  // namespace ddb::test

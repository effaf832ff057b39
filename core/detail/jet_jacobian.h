// Jacobians where no closed form is written: of a scalar-generic map, by one evaluation on
// ceres::Jet (automatic differentiation). The fixed-size groups' deduced retraction Jacobians
// (core/retraction_jacobians.h) and the symmetric methods' Legendre targets, and the independent
// check of the closed forms. The one library header of the groups' path that includes Ceres's Jet.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>

namespace ddb {

/// ∂f/∂x at x for f: R^N → R^M, scalar-generic (called once on Jet<double, N>).
template <int N, class Function>
auto jacobianByJets(const Function& f, const Eigen::Matrix<double, N, 1>& x) {
  using J = ceres::Jet<double, N>;
  Eigen::Matrix<J, N, 1> seeded;
  for (int i = 0; i < N; ++i) seeded(i) = J(x(i), i);
  const auto y = f(seeded);
  Eigen::Matrix<double, decltype(y)::RowsAtCompileTime, N> jacobian(y.rows(), N);
  for (Eigen::Index i = 0; i < y.rows(); ++i) jacobian.row(i) = y(i).v.transpose();
  return jacobian;
}

/// d/du f(a(u), b(u)) at u for f: R^N × R^N → R^M, given a(u), b(u) and their Jacobians
/// da = ∂a/∂u, db = ∂b/∂u (N × K): one evaluation of f on Jet<double, K> (chain rule).
template <int K, class Function, int N>
auto jacobianByJets(const Function& f, const Eigen::Matrix<double, N, 1>& a,
                    const Eigen::Matrix<double, N, K>& da, const Eigen::Matrix<double, N, 1>& b,
                    const Eigen::Matrix<double, N, K>& db) {
  using J = ceres::Jet<double, K>;
  Eigen::Matrix<J, N, 1> a_seeded, b_seeded;
  for (int i = 0; i < N; ++i) {
    a_seeded(i) = J(a(i));
    a_seeded(i).v = da.row(i).transpose();
    b_seeded(i) = J(b(i));
    b_seeded(i).v = db.row(i).transpose();
  }
  const auto y = f(a_seeded, b_seeded);
  Eigen::Matrix<double, decltype(y)::RowsAtCompileTime, K> jacobian(y.rows(), K);
  for (Eigen::Index i = 0; i < y.rows(); ++i) jacobian.row(i) = y(i).v.transpose();
  return jacobian;
}

}  // namespace ddb

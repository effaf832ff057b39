// ∂/∂x [(dτ^{-1}_x)* μ], the kDim × kDim matrix the Legendre Jacobian needs
// (docs/reference/conventions.md §4), for the Cayley map and the exponential of a fixed-size
// group: the group's closed form where it writes one (SO3, SE3), else by automatic
// differentiation on ceres::Jet through its dτ^{-1}*. Kept out of LieGroupBase so that a group's
// header does not pull Ceres's Jet; only the retractions' Legendre Jacobians include this.
#pragma once

#include <ddb/core/detail/has_retraction_jacobian.h>
#include <ddb/core/detail/jet_jacobian.h>

#include <Eigen/Core>
#include <type_traits>
#include <utility>

namespace ddb {

namespace detail {

/// mu with the scalar of the Jet vector y.
template <class Y, class D>
auto castLike(const D& mu) {
  using T = typename std::decay_t<Y>::Scalar;
  return Eigen::Matrix<T, D::RowsAtCompileTime, 1>(mu.template cast<T>());
}

}  // namespace detail

/// ∂/∂x [(dcay^{-1}_x)* mu] by Jets through G::dcayInvDual (the independent check of a closed
/// form, and the fallback where a group has none).
template <class G, class A, class D>
auto dcayInvDualJacobianByJets(const A& x, const D& mu) {
  return jacobianByJets<A::RowsAtCompileTime>(
      [&](const auto& y) { return G::dcayInvDual(y, detail::castLike<decltype(y)>(mu)); }, x);
}

/// ∂/∂x [(dexp^{-1}_x)* mu] by Jets through G::dexpInvDual.
template <class G, class A, class D>
auto dexpInvDualJacobianByJets(const A& x, const D& mu) {
  return jacobianByJets<A::RowsAtCompileTime>(
      [&](const auto& y) { return G::dexpInvDual(y, detail::castLike<decltype(y)>(mu)); }, x);
}

/// ∂/∂x [(dcay^{-1}_x)* mu]: G::dcayInvDualJacobian where G writes it, else by Jets.
template <class G, class A, class D>
auto dcayInvDualJacobian(const A& x, const D& mu) {
  if constexpr (detail::HasDcayInvDualJacobian<G, A, D>::value) {
    return G::dcayInvDualJacobian(x, mu);
  } else {
    return dcayInvDualJacobianByJets<G>(x, mu);
  }
}

/// ∂/∂x [(dexp^{-1}_x)* mu]: G::dexpInvDualJacobian where G writes it, else by Jets.
template <class G, class A, class D>
auto dexpInvDualJacobian(const A& x, const D& mu) {
  if constexpr (detail::HasDexpInvDualJacobian<G, A, D>::value) {
    return G::dexpInvDualJacobian(x, mu);
  } else {
    return dexpInvDualJacobianByJets<G>(x, mu);
  }
}

}  // namespace ddb

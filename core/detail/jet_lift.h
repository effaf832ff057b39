// Chain rule onto ceres::Jet for maps that users implement in double only.
//
// The user-facing interfaces (Lagrangian, Hamiltonian, DissipationMetric) are
// virtual and double-valued. The implicit equations, however, are differentiated
// by ceres::Jet. A map f evaluated at a Jet argument x = a + Σ_k v_k ε_k is
// f(a) + Σ_k Df(a)[v_k] ε_k; these helpers build that Jet from f(a) and the
// directional derivatives the interfaces provide.
#pragma once

#include <ddb/core/detail/scalar.h>

#include <Eigen/Core>

namespace ddb {

namespace detail {
template <class Derived>
auto valuePart(const Eigen::MatrixBase<Derived>& x) {
  return x.unaryExpr([](const typename Derived::Scalar& s) { return s.a; }).eval();
}
template <class Derived>
auto directionPart(const Eigen::MatrixBase<Derived>& x, int k) {
  return x.unaryExpr([k](const typename Derived::Scalar& s) { return s.v[k]; }).eval();
}
// Writes value `a` and derivative columns into a Jet-valued object of the same shape.
template <class Out, class Value>
void setValue(Out& out, const Value& a) {
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    out.data()[i].a = a.data()[i];
    out.data()[i].v.setZero();
  }
}
template <class Out, class Direction>
void setDirection(Out& out, int k, const Direction& d) {
  for (Eigen::Index i = 0; i < out.size(); ++i) out.data()[i].v[k] = d.data()[i];
}
}  // namespace detail

/// Gradient of a smooth function (Lagrangian or Hamiltonian) at a double or Jet
/// argument. For Jets the derivative part is Hess f(a)[v_k], from hessianTimes.
template <class Function, class Arg>
auto liftGradient(const Function& f, const Arg& x) {
  using T = typename Arg::Scalar;
  if constexpr (JetTraits<T>::kDirections == 0) {
    return f.gradient(x);
  } else {
    const auto a = detail::valuePart(x);
    const auto g = f.gradient(a);
    Eigen::Matrix<T, decltype(g)::RowsAtCompileTime, decltype(g)::ColsAtCompileTime> out(g.rows(),
                                                                                         g.cols());
    detail::setValue(out, g);
    for (int k = 0; k < JetTraits<T>::kDirections; ++k) {
      detail::setDirection(out, k, f.hessianTimes(a, detail::directionPart(x, k)));
    }
    return out;
  }
}

/// A linear map (given in double) applied to a double or Jet argument.
template <class LinearMap, class Arg>
auto liftLinear(const LinearMap& map, const Arg& x) {
  using T = typename Arg::Scalar;
  if constexpr (JetTraits<T>::kDirections == 0) {
    return map(x);
  } else {
    const auto y = map(detail::valuePart(x));
    Eigen::Matrix<T, decltype(y)::RowsAtCompileTime, decltype(y)::ColsAtCompileTime> out(y.rows(),
                                                                                         y.cols());
    detail::setValue(out, y);
    for (int k = 0; k < JetTraits<T>::kDirections; ++k) {
      detail::setDirection(out, k, map(detail::directionPart(x, k)));
    }
    return out;
  }
}

}  // namespace ddb

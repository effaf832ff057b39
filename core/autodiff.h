// AutoDiff<Derived, Interface>: implements gradient and hessianTimes of a
// Lagrangian or Hamiltonian from one scalar-generic `evaluate` with ceres::Jet.
//
//   class MyLagrangian : public ddb::AutoDiffLagrangian<MyLagrangian, ddb::SO3> {
//    public:
//     template <class T> T evaluate(const Eigen::Matrix<T, 3, 1>& xi) const { ... }
//   };
//
// gradient uses Jet<double, n>; hessianTimes nests Jet<Jet<double, 1>, n>, so the
// directional derivative of the gradient costs one evaluation. Constants inside
// `evaluate` must be lifted explicitly (constant<T>(0.5) * x), as nested Jets require.
// For fixed-size (vector-coordinate) algebras; a subclass may override any member
// with an analytic formula for speed.
#pragma once

#include <ceres/jet.h>
#include <ddb/core/lagrangian.h>

namespace ddb {

template <class Derived, class Interface>
class AutoDiff : public Interface {
 public:
  using Domain = typename Interface::DomainType;
  using Codomain = typename Interface::CodomainType;
  static constexpr int kDim = Domain::RowsAtCompileTime;
  static_assert(kDim > 0, "AutoDiff needs a fixed-size vector domain");

  double value(const Domain& x) const override { return derived().evaluate(x); }

  Codomain gradient(const Domain& x) const override {
    using J = ceres::Jet<double, kDim>;
    Eigen::Matrix<J, kDim, 1> xj;
    for (int i = 0; i < kDim; ++i) xj(i) = J(x(i), i);
    const J f = derived().evaluate(xj);
    return f.v;
  }

  Codomain hessianTimes(const Domain& x, const Domain& v) const override {
    using Inner = ceres::Jet<double, 1>;
    using Outer = ceres::Jet<Inner, kDim>;
    Eigen::Matrix<Outer, kDim, 1> xj;
    for (int i = 0; i < kDim; ++i) {
      xj(i).a = Inner(x(i));
      xj(i).a.v(0) = v(i);
      xj(i).v.setZero();
      xj(i).v(i) = Inner(1.0);
    }
    const Outer f = derived().evaluate(xj);
    Codomain out;
    for (int i = 0; i < kDim; ++i) out(i) = f.v(i).v(0);
    return out;
  }

 private:
  const Derived& derived() const { return static_cast<const Derived&>(*this); }
};

template <class Derived, class G>
using AutoDiffLagrangian = AutoDiff<Derived, Lagrangian<G>>;
template <class Derived, class G>
using AutoDiffHamiltonian = AutoDiff<Derived, Hamiltonian<G>>;

}  // namespace ddb

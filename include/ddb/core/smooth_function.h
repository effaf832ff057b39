// SmoothFunction: a scalar function with its gradient and Hessian action, the
// common shape of a reduced Lagrangian l: g → R and a Hamiltonian H: g* → R.
#pragma once

#include <Eigen/Core>

namespace ddb {

/// f: Domain → R with gradient in Codomain (the dual space of Domain).
/// hessianTimes(x, v) = D(∇f)(x)[v] is all the implicit solvers need, so no
/// dim × dim matrix is ever required of a large algebra.
template <class Domain, class Codomain>
class SmoothFunction {
 public:
  using DomainType = Domain;
  using CodomainType = Codomain;

  virtual ~SmoothFunction() = default;
  virtual double value(const Domain& x) const = 0;
  virtual Codomain gradient(const Domain& x) const = 0;
  virtual Codomain hessianTimes(const Domain& x, const Domain& v) const = 0;

  /// In-place forms for large (matrix) algebras, `out` already of x's size: the
  /// matrix-free solvers call these so that no iteration allocates. The defaults
  /// forward to the value-returning forms; a large system overrides them.
  virtual void gradientInto(const Domain& x, Codomain& out) const { out = gradient(x); }
  virtual void hessianTimesInto(const Domain& x, const Domain& v, Codomain& out) const {
    out = hessianTimes(x, v);
  }
};

/// The Hessian of f at x as a matrix, column j = hessianTimes(x, e_j): fixed-size
/// domains only (the small implicit solvers' Jacobians and the Legendre transform).
template <class Domain, class Codomain>
Eigen::Matrix<double, Domain::RowsAtCompileTime, Domain::RowsAtCompileTime> hessianMatrix(
    const SmoothFunction<Domain, Codomain>& f, const Domain& x) {
  constexpr int n = Domain::RowsAtCompileTime;
  static_assert(n != Eigen::Dynamic, "hessianMatrix needs a fixed-size domain");
  Eigen::Matrix<double, n, n> hessian;
  for (int j = 0; j < n; ++j) hessian.col(j) = f.hessianTimes(x, Domain::Unit(j));
  return hessian;
}

}  // namespace ddb

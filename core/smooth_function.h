// SmoothFunction: a scalar function with its gradient and Hessian action, the
// common shape of a reduced Lagrangian l: g → R and a Hamiltonian H: g* → R.
#pragma once

#include <ddb/core/matrix_backend.h>
#include <ddb/core/matrix_traits.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <type_traits>

namespace ddb {

/// f: Domain → R with gradient in Codomain (the dual space of Domain).
/// A subclass must provide value and gradient; hessianTimes(x, v) = D(∇f)(x)[v] is
/// optional. It is all the Newton-type solvers need, so no dim × dim matrix is ever
/// required of a large algebra.
template <class Domain, class Codomain>
class SmoothFunction {
 public:
  using DomainType = Domain;
  using CodomainType = Codomain;

  virtual ~SmoothFunction() = default;
  virtual double value(const Domain& x) const = 0;
  virtual Codomain gradient(const Domain& x) const = 0;
  /// D(∇f)(x)[v]. The default is the central difference of `gradient` along v with the step
  /// s = ∛u·‖x‖/‖v‖ (u the unit rounding; ‖x‖ → 1 at x = 0), whose truncation and rounding
  /// errors balance at about u^{2/3} ≈ 4e-11 relative. Only Newton-type solves use it (the
  /// matrix groups' Newton–Krylov fallbacks, the small solvers' Jacobians), and they judge
  /// convergence on the exact residual: an approximate derivative costs iterations, not
  /// accuracy (docs/reference/conventions.md §4, "Derivatives"). Override it with the formula where
  /// Newton runs often, e.g. at large h on matrix groups.
  virtual Codomain hessianTimes(const Domain& x, const Domain& v) const {
    if constexpr (isEigenMatrix<Domain>) {
      const double s = differenceStep(x.norm(), v.norm());
      const Domain plus = x + s * v, minus = x - s * v;
      return Codomain((gradient(plus) - gradient(minus)) / (2.0 * s));
    } else {  // a backend's matrices (docs/design/matrix-backend.md)
      using B = MatrixBackend<Domain>;
      const double s = differenceStep(B::frobeniusNorm(x), B::frobeniusNorm(v));
      Domain plus = x, minus = x;
      B::axpy(s, v, plus);
      B::axpy(-s, v, minus);
      Codomain out = gradient(plus);
      B::axpy(-1.0, gradient(minus), out);
      B::divide(out, 2.0 * s);
      return out;
    }
  }

  /// In-place forms for large (matrix) algebras, `out` already of x's size: the
  /// matrix-free solvers call these so that no iteration allocates. The defaults
  /// forward to the value-returning forms; a large system overrides them.
  virtual void gradientInto(const Domain& x, Codomain& out) const { out = gradient(x); }
  virtual void hessianTimesInto(const Domain& x, const Domain& v, Codomain& out) const {
    out = hessianTimes(x, v);
  }

 private:
  // The central difference's step s = ∛u·‖x‖/‖v‖ (‖x‖ → 1 at x = 0).
  static double differenceStep(double norm_x, double norm_v) {
    return norm_v > 0.0 ? std::cbrt(std::numeric_limits<double>::epsilon()) *
                              (norm_x > 0.0 ? norm_x : 1.0) / norm_v
                        : 1.0;
  }
};

/// A SmoothFunction on a fixed-size (vector) domain, which can also give its Hessian whole:
/// the small implicit solvers assemble their Jacobians from it (docs/reference/conventions.md §4).
/// The default asks hessianTimes for each column (n virtual calls, each a Jet evaluation inside
/// AutoDiff); a system with an analytic Hessian returns it in one call, which for the heavy
/// top removes six virtual calls from each Jacobian.
template <class Domain, class Codomain>
class SmallSmoothFunction : public SmoothFunction<Domain, Codomain> {
 public:
  static constexpr int kDim = Domain::RowsAtCompileTime;
  static_assert(kDim != Eigen::Dynamic, "SmallSmoothFunction needs a fixed-size domain");
  using HessianMatrix = Eigen::Matrix<double, kDim, kDim>;

  /// D²f(x), column j = hessianTimes(x, e_j).
  virtual HessianMatrix hessian(const Domain& x) const {
    HessianMatrix out;
    for (int j = 0; j < kDim; ++j) out.col(j) = this->hessianTimes(x, Domain::Unit(j));
    return out;
  }
};

/// SmallSmoothFunction for fixed-size domains, SmoothFunction for the matrix algebras (of any
/// backend).
template <class Domain, class Codomain>
using SmoothFunctionFor =
    std::conditional_t<hasFixedSize<Domain>, SmallSmoothFunction<Domain, Codomain>,
                       SmoothFunction<Domain, Codomain>>;

/// The Hessian of f at x as a matrix: fixed-size domains only (the small implicit solvers'
/// Jacobians and the Legendre transform).
template <class Domain, class Codomain>
typename SmallSmoothFunction<Domain, Codomain>::HessianMatrix hessianMatrix(
    const SmallSmoothFunction<Domain, Codomain>& f, const Domain& x) {
  return f.hessian(x);
}

}  // namespace ddb

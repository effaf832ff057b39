// SmoothFunction: a scalar function with its gradient and Hessian action, the
// common shape of a reduced Lagrangian l: g → R and a Hamiltonian H: g* → R.
#pragma once

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
};

}  // namespace ddb

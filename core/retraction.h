// Retraction: the abstract interface of a map τ: g → G with τ(0) = e and
// τ(x)τ(-x) = e (paper, Section 4.1, Definition "Retr"). CRTP, like LieGroupBase.
//
// A retraction `R : Retraction<R, G>` provides scalar-generic const members:
//   tau(x) -> Matrix           τ(x), a group element
//   tauInverse(g) -> Algebra   τ^{-1}(g) near e
//   dTau(x, y)                 right-trivialised tangent: T_xτ(y) = dτ_x(y) τ(x)
//   dTauInverse(x, y)          its inverse, dτ^{-1}_x
//   dTauInverseDual(x, mu)     the dual (dτ^{-1}_x)*, which the discrete Legendre
//                              transform M = (dτ^{-1}_{hξ})* ∂l/∂ξ uses (paper, Section 4.1, DDB
//                              method step (a))
// and, for fixed-size groups in double, the two parts of the Legendre Jacobian
// (docs/reference/conventions.md §4):
//   dTauInverseDualMatrix(x)   the matrix of mu ↦ (dτ^{-1}_x)* mu
//   dTauInverseDualJacobian(x, mu)  ∂/∂x [(dτ^{-1}_x)* mu]
// Composed here, written once:
//   transport(a, b, mu) = Ad*_{τ(a)τ(b)} mu, the DDB update (paper, eq. (4.7)).
#pragma once

#include <ddb/core/group_traits.h>

namespace ddb {

template <class Derived, class G>
class Retraction {
  static_assert(sizeof(GroupTraits<G>) > 0, "checks G's minimum API (core/group_traits.h)");

 public:
  using Group = G;

  /// Ad*_{τ(a) τ(b)} mu.
  template <class T>
  typename G::template Dual<T> transport(const typename G::template Algebra<T>& a,
                                         const typename G::template Algebra<T>& b,
                                         const typename G::template Dual<T>& mu) const {
    const auto& self = static_cast<const Derived&>(*this);
    return G::AdDual(G::compose(self.tau(a), self.tau(b)), mu);
  }
};

}  // namespace ddb

// The Cayley retraction cay(x) = (I - X/2)^{-1}(I + X/2) (paper, Section 4.1 b),
// eqs. (4.15), (4.16)). The formulas live in the group: LieGroupBase has them for
// any matrix representation, and a group may shadow them with closed forms (SO3).
#pragma once

#include <ddb/core/retraction.h>
#include <ddb/core/retraction_jacobians.h>

namespace ddb {

template <class G>
class Cayley : public Retraction<Cayley<G>, G> {
 public:
  static constexpr const char* kName = "cay";

  template <class A>
  auto tau(const A& x) const {
    return G::cay(x);
  }
  template <class M>
  auto tauInverse(const M& g) const {
    return G::cayInverse(g);
  }
  template <class A>
  A dTau(const A& x, const A& y) const {
    return G::dcay(x, y);
  }
  template <class A>
  A dTauInverse(const A& x, const A& y) const {
    return G::dcayInv(x, y);
  }
  template <class A, class D>
  EIGEN_ALWAYS_INLINE D dTauInverseDual(const A& x, const D& mu) const {
    return G::dcayInvDual(x, mu);
  }
  template <class A>
  EIGEN_ALWAYS_INLINE auto dTauInverseDualMatrix(const A& x) const {
    return G::dcayInvDualMatrix(x);
  }
  template <class A, class D>
  EIGEN_ALWAYS_INLINE auto dTauInverseDualJacobian(const A& x, const D& mu) const {
    return ddb::dcayInvDualJacobian<G>(x, mu);
  }
  /// Ad*_{cay(a) cay(b)} mu through the group, which may apply it without forming the
  /// product (SO3: docs/results/casimir-drift.md); shadows Retraction::transport.
  template <class A, class D>
  EIGEN_ALWAYS_INLINE D transport(const A& a, const A& b, const D& mu) const {
    return G::cayTransport(a, b, mu);
  }
};

}  // namespace ddb

// The exponential retraction (paper, Section 4.1 a)): τ = exp, with dexp^{-1}
// either in closed form / summed to round-off (Exponential) or truncated after the
// ad^order term (TruncatedExponential; the paper's runs use order 2).
#pragma once

#include <ddb/core/detail/bernoulli.h>
#include <ddb/core/detail/jet_jacobian.h>
#include <ddb/core/detail/linear_map_matrix.h>
#include <ddb/core/errors.h>
#include <ddb/core/retraction.h>
#include <ddb/core/retraction_jacobians.h>

#include <type_traits>

namespace ddb {

template <class G>
class Exponential : public Retraction<Exponential<G>, G> {
 public:
  static constexpr const char* kName = "exp";

  template <class T>
  using Algebra = typename G::template Algebra<T>;
  template <class T>
  using Dual = typename G::template Dual<T>;
  template <class T>
  using Matrix = typename G::template Matrix<T>;

  template <class T>
  Matrix<T> tau(const Algebra<T>& x) const {
    return G::exp(x);
  }
  template <class T>
  Algebra<T> tauInverse(const Matrix<T>& g) const {
    return G::log(g);
  }
  template <class T>
  Algebra<T> dTau(const Algebra<T>& x, const Algebra<T>& y) const {
    return G::dexp(x, y);
  }
  template <class T>
  Algebra<T> dTauInverse(const Algebra<T>& x, const Algebra<T>& y) const {
    return G::dexpInv(x, y);
  }
  template <class T>
  Dual<T> dTauInverseDual(const Algebra<T>& x, const Dual<T>& mu) const {
    return G::dexpInvDual(x, mu);
  }
  auto dTauInverseDualMatrix(const Algebra<double>& x) const { return G::dexpInvDualMatrix(x); }
  auto dTauInverseDualJacobian(const Algebra<double>& x, const Dual<double>& mu) const {
    return ddb::dexpInvDualJacobian<G>(x, mu);
  }
};

/// τ = exp with dτ^{-1} replaced by its Bernoulli series truncated after ad^order.
/// Not an exact retraction pair (dτ ∘ dτ^{-1} = I + O(|x|^{order+1})): it is the
/// paper's practical choice, offered for reproduction. τ, τ^{-1} and dτ are exp's.
template <class G>
class TruncatedExponential : public Exponential<G> {
 public:
  static constexpr const char* kName = "exp-truncated";

  explicit TruncatedExponential(int order = 2) : order_(order) {
    if (order < 0 || order > kMaxBernoulliIndex) {
      throwInvalid("order", std::to_string(order),
                   "must be in [0, " + std::to_string(kMaxBernoulliIndex) + "]");
    }
  }
  int order() const { return order_; }

  template <class A>
  A dTauInverse(const A& x, const A& y) const {
    return G::dexpInvSeries(x, y, order_);
  }
  template <class A, class D>
  D dTauInverseDual(const A& x, const D& mu) const {
    return G::dexpInvDualSeries(x, mu, order_);
  }
  auto dTauInverseDualMatrix(const typename G::template Algebra<double>& x) const {
    return linearMapMatrix<G::kDim>([&](const auto& mu) { return dTauInverseDual(x, mu); });
  }
  auto dTauInverseDualJacobian(const typename G::template Algebra<double>& x,
                               const typename G::template Dual<double>& mu) const {
    return jacobianByJets<G::kDim>(
        [&](const auto& y) {
          using T = typename std::decay_t<decltype(y)>::Scalar;
          using Dual = typename G::template Dual<T>;
          return G::dexpInvDualSeries(y, Dual(mu.template cast<T>()), order_);
        },
        x);
  }

 private:
  int order_;
};

}  // namespace ddb

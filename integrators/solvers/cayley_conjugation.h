// Ad*_{cay x} μ on any group, as OrbitNewton retracts its steps onto the orbit: on matrix groups
// the in-place MatrixCayleyConjugation (two LU solves and a product), on the small groups the
// closed form G::cayTransport(x, 0, μ). CayleyConjugationFor<G> chooses by the group's traits,
// so the search's body names neither.
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/integrators/matrix_kernels/matrix_conjugation.h>

#include <type_traits>

namespace ddb {

/// The small groups' conjugation: prepare(x) keeps x, apply(μ) sets μ ← Ad*_{cay x} μ.
template <class G>
class FixedSizeCayleyConjugation {
 public:
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  void prepare(const Algebra& x) { x_ = x; }
  void apply(Dual& mu) const { mu = G::cayTransport(x_, Algebra::Zero().eval(), mu); }

 private:
  Algebra x_;
};

template <class G>
using CayleyConjugationFor = std::conditional_t<isDynamicGroup<G>, MatrixCayleyConjugation<G>,
                                                FixedSizeCayleyConjugation<G>>;

}  // namespace ddb

// Representations of a fixed-size group G on Rᵐ, for SemidirectProduct<G, Representation>
// (groups/semidirect_product.h; docs/reference/conventions.md §1, "Semidirect products"). A
// representation states
//   static constexpr int kDim;                        m
//   template <class T> static Map<T> ofGroup(g);      ρ(g), an m×m matrix, ρ(gh) = ρ(g)ρ(h)
//   template <class T> static Map<T> ofAlgebra(ω);    ρ'(ω) = d/dt ρ(exp tω) at t = 0
// with Map<T> = Eigen::Matrix<T, m, m>. Ready-made: G's own matrices (DefiningRepresentation, the
// action of SE(N) and of the heavy top), the adjoint action on 𝔤 and the coadjoint action on 𝔤*
// (the action of SU(N) ⋉ su(N)*, which the magnetic fluid has in groups/dual_number_sun.h).
#pragma once

#include <ddb/core/detail/linear_map_matrix.h>

#include <Eigen/Core>
#include <type_traits>

namespace ddb {

/// G acting on Rⁿ by its own real n×n matrices: ρ(g) = g, ρ'(ω) = hat_G(ω).
template <class G>
struct DefiningRepresentation {
  static constexpr int kDim = G::template Matrix<double>::RowsAtCompileTime;
  template <class T>
  using Map = typename G::template Matrix<T>;

  template <class T>
  static Map<T> ofGroup(const typename G::template Matrix<T>& g) {
    return g;
  }
  template <class T>
  static Map<T> ofAlgebra(const typename G::template Algebra<T>& w) {
    return G::hat(w);
  }
};

/// G acting on its algebra 𝔤 (as kDim-vectors) by Ad: ρ(g) = Ad_g, ρ'(ω) = ad_ω = [ω, ·],
/// column by column from G's own Ad and bracket.
template <class G>
struct AdjointRepresentation {
  static constexpr int kDim = G::kDim;
  template <class T>
  using Map = Eigen::Matrix<T, kDim, kDim>;

  template <class T>
  static Map<T> ofGroup(const typename G::template Matrix<T>& g) {
    using A = typename G::template Algebra<T>;
    return linearMapMatrix<kDim, T>([&](const A& y) -> A { return G::Ad(g, y); });
  }
  template <class T>
  static Map<T> ofAlgebra(const typename G::template Algebra<T>& w) {
    using A = typename G::template Algebra<T>;
    return linearMapMatrix<kDim, T>([&](const A& y) -> A { return G::bracket(w, y); });
  }
};

/// G acting on the dual 𝔤* (as kDim-vectors) from the left by g·μ = Ad*_{g⁻¹}μ (the library's
/// Ad*_g is the dual of Ad_g, a right action: Ad*_{gh} = Ad*_h Ad*_g): ρ(g) = Ad*_{g⁻¹},
/// ρ'(ω) = −ad*_ω.
template <class G>
struct CoadjointRepresentation {
  static constexpr int kDim = G::kDim;
  template <class T>
  using Map = Eigen::Matrix<T, kDim, kDim>;
  static_assert(
      std::is_same_v<typename G::template Algebra<double>, typename G::template Dual<double>>,
      "CoadjointRepresentation<G>: G's Algebra and Dual must be the same vector type");

  template <class T>
  static Map<T> ofGroup(const typename G::template Matrix<T>& g) {
    using D = typename G::template Dual<T>;
    const typename G::template Matrix<T> g_inverse = G::inverse(g);
    return linearMapMatrix<kDim, T>([&](const D& mu) -> D { return G::AdDual(g_inverse, mu); });
  }
  template <class T>
  static Map<T> ofAlgebra(const typename G::template Algebra<T>& w) {
    using D = typename G::template Dual<T>;
    return linearMapMatrix<kDim, T>([&](const D& mu) -> D { return -G::adDual(w, mu); });
  }
};

}  // namespace ddb

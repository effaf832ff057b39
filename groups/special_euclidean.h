// SE(N) = SO(N) ⋉ Rᴺ for a fixed N, composed by SemidirectProduct (groups/semidirect_product.h)
// from SpecialOrthogonal<N> (groups/special_orthogonal.h): ξ = (ω, v), μ = (π, γ), elements the
// (N+1)×(N+1) matrices [[R, r], [0, 1]]; the group of Ratiu's N-dimensional heavy top
// (systems/heavy_top.h). At N = 3 it is SE(3) in SpecialOrthogonal<3>'s coordinates.
//
// Casimirs (docs/reference/conventions.md §1, "SO(N) and SE(N) of a fixed size"): the coadjoint
// action moves M = hat(π) by rotation and by M ↦ M + γaᵀ − aγᵀ, which the projection P = I −
// γγᵀ/|γ|² onto γ's complement removes, so |γ|² and the spectrum of P M P are invariant. As
// polynomials:
//   c₀ = |γ|²,  c_k = (−1)ᵏ tr(Q^{2k}),  Q = |γ|² P M P = |γ|² M − γ(γᵀM) − (Mγ)γᵀ,
// k = 1 … ⌊(N−1)/2⌋, as many as the index of se(N) (1 + that of the stabiliser so(N−1)).
// At N = 3: c₁ = 2|γ|²(m·γ)² with m the axial vector of M (SE3's π·γ), at N = 2 only |γ|²
// (SE2's).
#pragma once

#include <ddb/groups/semidirect_product.h>
#include <ddb/groups/special_orthogonal.h>

#include <Eigen/Core>
#include <array>

namespace ddb {

template <int N>
struct SemidirectProductTraits<SpecialOrthogonal<N>> {
  static constexpr std::array<char, detail::MatrixGroupName<N>::kLength> kNameStorage =
      detail::MatrixGroupName<N>::make('S', 'E');
  static constexpr const char* kName = kNameStorage.data();
  static constexpr int kNumCasimirs = 1 + (N - 1) / 2;
  static constexpr int kFactorDim = SpecialOrthogonal<N>::kDim;

  template <class T>
  static Eigen::Matrix<T, kNumCasimirs, 1> casimirs(const Eigen::Matrix<T, kFactorDim, 1>& pi,
                                                    const Eigen::Matrix<T, N, 1>& gamma) {
    using Matrix = Eigen::Matrix<T, N, N>;
    const Matrix M = SpecialOrthogonal<N>::hat(pi);
    const Eigen::Matrix<T, N, 1> Mgamma = M * gamma;
    const T gamma2 = gamma.squaredNorm();
    // γ(γᵀM) = −γ(Mγ)ᵀ, M being skew.
    const Matrix Q = M * gamma2 + gamma * Mgamma.transpose() - Mgamma * gamma.transpose();
    Eigen::Matrix<T, kNumCasimirs, 1> c;
    c(0) = gamma2;
    c.template tail<kNumCasimirs - 1>() =
        SpecialOrthogonal<N>::template evenPowerTraces<kNumCasimirs - 1, T>(Q);
    return c;
  }
};

/// SE(N), rigid motions of Rᴺ.
template <int N>
using SpecialEuclidean = SemidirectProduct<SpecialOrthogonal<N>>;

}  // namespace ddb

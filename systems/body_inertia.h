// The principal inertia of an N-dimensional rigid body (Ratiu 1982; docs/reference/conventions.md
// §2, "The N-dimensional heavy top"): mass moments J give the inertia operator 𝕁Ω = ΩJ + JΩ on
// so(N), diagonal in SpecialOrthogonal<N>'s coordinates.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/groups/special_orthogonal.h>

#include <Eigen/Core>

namespace ddb {

/// The principal inertia of an N-dimensional rigid body with mass moments J (all > 0) in
/// SpecialOrthogonal<N>'s coordinates: 𝕁Ω = ΩJ + JΩ has (𝕁Ω)_ji = (J_i + J_j)Ω_ji, so the entry of
/// the pair (i, j) is J_i + J_j (as the Manakov body's, systems/manakov_body.h). At N = 3 the pair
/// (i, j) is SO3's axis k ∉ {i, j}, and J_i + J_j its principal moment.
template <int N>
Eigen::Matrix<double, SpecialOrthogonal<N>::kDim, 1> bodyInertiaOf(
    const Eigen::Matrix<double, N, 1>& mass_moments) {
  requirePositive("mass_moments", mass_moments);
  Eigen::Matrix<double, SpecialOrthogonal<N>::kDim, 1> inertia;
  for (int p = 0; p < SpecialOrthogonal<N>::kDim; ++p) {
    const auto& pair = SpecialOrthogonal<N>::kPairs[p];
    inertia(p) = mass_moments(pair[0]) + mass_moments(pair[1]);
  }
  return inertia;
}

}  // namespace ddb

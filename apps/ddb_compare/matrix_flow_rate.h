// The flow's rate on a matrix group (SO(N), SU(N)), for ddb-compare's check that the
// reference can follow it (docs/reference/bad-inputs.md, "Decisions"). flowRate() differentiates
// the vector field by Jets, one per coordinate: N² of them here, each an N×N matrix,
// O(N⁵) work. This is a bound of the same scale instead, from the form of the field
// (docs/reference/conventions.md §2): f(μ) = [μ, ξ + φ], φ = α[μ, ξ], ξ = ∂H/∂μ = Lμ linear for
// both systems, so ∂f/∂μ δ = [δ, ξ + φ] + [μ, Lδ + α([δ, ξ] + [μ, Lδ])] and, with
// ‖[A, B]‖ ≤ 2‖A‖‖B‖ and ‖L‖‖μ₀‖ taken as ‖ξ₀‖, ‖∂f/∂μ‖ ≲ 4‖ξ₀‖₂ (1 + 3|α|‖μ₀‖₂).
#pragma once

#include <ddb/core/lie_poisson_system.h>

#include <cmath>
#include <limits>

namespace ddb::compare {

/// 4‖ξ₀‖₂ (1 + 3|α|‖μ₀‖₂) with ξ₀ = ∂H/∂μ(μ₀); infinity if H(μ₀) or ξ₀ is not finite.
template <class G>
double matrixFlowRate(const LiePoissonSystem<G>& system,
                      const typename G::template Dual<double>& mu0, double alpha) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (!std::isfinite(system.energy(mu0))) return kInfinity;
  const auto xi = system.hamiltonian().gradient(mu0);
  if (!xi.allFinite()) return kInfinity;
  const double rate =
      4.0 * G::spectralNorm(xi) * (1.0 + 3.0 * std::abs(alpha) * G::spectralNorm(mu0));
  return std::isfinite(rate) ? rate : kInfinity;
}

}  // namespace ddb::compare

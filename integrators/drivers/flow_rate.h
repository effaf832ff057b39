// The stiffness of a flow at a point: ‖∂f/∂μ‖∞ of the vector field μ̇ = f(μ) =
// ad*_{ξ+φ(ξ)} μ (docs/reference/conventions.md §2), by Jets (exact to round-off, no step size to
// choose). Its inverse is the flow's fastest time scale there, which an explicit adaptive
// solver such as the reference must resolve; ddb-compare refuses a problem whose rate
// times the horizon exceeds what 1e9 steps can follow (docs/reference/bad-inputs.md).
#pragma once

#include <ceres/jet.h>
#include <ddb/core/lie_poisson_system.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddb {

/// ‖∂f/∂μ‖∞ (the largest absolute row sum) at μ₀, for fixed-size groups; infinity if
/// H(μ₀), f(μ₀) or a derivative is not finite.
template <class G>
double flowRate(const LiePoissonSystem<G>& system, const typename G::template Dual<double>& mu0) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  using Jet = ceres::Jet<double, G::kDim>;
  typename G::template Dual<Jet> mu;
  for (int i = 0; i < G::kDim; ++i) mu(i) = Jet(mu0(i), i);
  if (!std::isfinite(system.energy(mu0))) return kInfinity;
  const auto f = system.vectorField(mu);
  double rate = 0.0;
  for (int i = 0; i < G::kDim; ++i) {
    const double row = f(i).v.cwiseAbs().sum();
    if (!std::isfinite(f(i).a) || !std::isfinite(row)) return kInfinity;
    rate = std::max(rate, row);
  }
  return rate;
}

}  // namespace ddb

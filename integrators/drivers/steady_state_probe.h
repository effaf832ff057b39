// SteadyStateProbe: how far a state is from a steady state of the conservative flow, and
// how fast the energy falls there, from one evaluation of ξ = ∂H/∂μ and φ = k♯(ad*_ξ μ)
// (eq. (3.4)):
//   r(μ)     = ‖ad*_ξ μ‖ / (‖ξ‖ ‖μ‖),        zero exactly where μ̇ = 0 for every α;
//   dH/dt(μ) = −⟨ad*_ξ μ, k♯(ad*_ξ μ)⟩      (Proposition 3.3).
// r is dimensionless: invariant under scaling μ, H or time. On the fluid, ξ = −P/ħ and
// ad*_ξ W = −[W, P]/ħ, so r = ‖[P, W]‖_F/(‖P‖_F ‖W‖_F). The norms are the Euclidean norms
// of the coordinates (fixed-size groups) or Frobenius (matrix groups; both parts together on
// SU(N) ⋉ su(N)*, whose pairing is not their inner product).
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>

namespace ddb {

template <class G>
class SteadyStateProbe {
 public:
  using Dual = typename G::template Dual<double>;

  explicit SteadyStateProbe(const LiePoissonSystem<G>& system) : system_(system) {}

  /// Evaluates at μ; residual() and energyRate() then describe μ, from the parts of the
  /// system's in-place field (no allocation once the size is known).
  void evaluate(const Dual& mu) {
    w_.resize(mu);
    if (!B::sameShape(field_, mu)) B::zeroLike(field_, mu);
    system_.fieldPartsInto(mu, w_, field_);
    // ad*_ξ μ is w_.commutator (matrix groups: [Pμ, ξ]); the rate pairs it with φ by the
    // group's pairing (dualPairing: Re tr(AᴴB) on matrix groups).
    const double scale =
        MatrixBackend<Algebra>::frobeniusNorm(w_.xi) * B::frobeniusNorm(w_.argument);
    residual_ = scale > 0 ? B::frobeniusNorm(w_.commutator) / scale : 0.0;
    energy_rate_ = -dualPairing<G>(w_.commutator, w_.phi);
  }

  /// r(μ) = ‖ad*_ξ μ‖/(‖ξ‖ ‖μ‖); 0 where ξ or μ vanishes (the flow is at rest there).
  double residual() const { return residual_; }
  /// dH/dt(μ) of the continuous flow: ≤ 0 for a positive metric k (α > 0).
  double energyRate() const { return energy_rate_; }

 private:
  using B = MatrixBackend<Dual>;
  using Algebra = typename G::template Algebra<double>;

  const LiePoissonSystem<G>& system_;
  FieldWorkspace<G> w_;
  Dual field_;  // the field itself, unused here
  double residual_ = 0.0, energy_rate_ = 0.0;
};

/// r(μ) of SteadyStateProbe for one state.
template <class G>
double steadyStateResidual(const LiePoissonSystem<G>& system,
                           const typename G::template Dual<double>& mu) {
  SteadyStateProbe<G> probe(system);
  probe.evaluate(mu);
  return probe.residual();
}

}  // namespace ddb

// SteadyStateProbe: how far a state is from a steady state of the conservative flow, and
// how fast the energy falls there, from one evaluation of ξ = ∂H/∂μ and φ = k♯(ad*_ξ μ)
// (eq. (3.4)):
//   r(μ)     = ‖ad*_ξ μ‖ / (‖ξ‖ ‖μ‖),        zero exactly where μ̇ = 0 for every α;
//   dH/dt(μ) = −⟨ad*_ξ μ, k♯(ad*_ξ μ)⟩      (Proposition 3.3).
// r is dimensionless: invariant under scaling μ, H or time. On the fluid, ξ = −P/ħ and
// ad*_ξ W = −[W, P]/ħ, so r = ‖[P, W]‖_F/(‖P‖_F ‖W‖_F). The norms are the Euclidean norms
// of the coordinates (fixed-size groups) or Frobenius (matrix groups), the pairing's.
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>

#include <cmath>
#include <complex>
#include <type_traits>

namespace ddb {

template <class G>
class SteadyStateProbe {
 public:
  using Dual = typename G::template Dual<double>;

  explicit SteadyStateProbe(const LiePoissonSystem<G>& system) : system_(system) {}

  /// Evaluates at μ; residual() and energyRate() then describe μ. On matrix groups it
  /// evaluates the system's in-place field (no allocation once the size is known).
  void evaluate(const Dual& mu) {
    if constexpr (isDynamicGroup<G>) {
      using B = MatrixBackend<Dual>;
      w_.resize(mu);
      if (!B::sameShape(out_, mu)) B::zeroLike(out_, mu);
      system_.vectorFieldInto(mu, w_, out_);
      // ad*_ξ μ is the commutator [Pμ, ξ]; the pairing is Re tr(AᴴB).
      setFrom(B::frobeniusNorm(w_.commutator), B::innerProduct(w_.commutator, w_.phi),
              B::frobeniusNorm(w_.xi), B::frobeniusNorm(w_.argument));
    } else {
      const auto xi = system_.velocity(mu);
      const auto ad = G::adDual(xi, mu).eval();
      set(ad, system_.dissipation(xi, mu), xi.norm(), mu.norm());
    }
  }

  /// r(μ) = ‖ad*_ξ μ‖/(‖ξ‖ ‖μ‖); 0 where ξ or μ vanishes (the flow is at rest there).
  double residual() const { return residual_; }
  /// dH/dt(μ) of the continuous flow: ≤ 0 for a positive metric k (α > 0).
  double energyRate() const { return energy_rate_; }

 private:
  template <class A, class P>
  void set(const A& ad, const P& phi, double xi_norm, double mu_norm) {
    setFrom(ad.norm(), std::real(ad.conjugate().cwiseProduct(phi).sum()), xi_norm, mu_norm);
  }
  // From ‖ad*_ξ μ‖, ⟨ad*_ξ μ, k♯(ad*_ξ μ)⟩, ‖ξ‖ and ‖μ‖.
  void setFrom(double ad_norm, double ad_dot_phi, double xi_norm, double mu_norm) {
    const double scale = xi_norm * mu_norm;
    residual_ = scale > 0 ? ad_norm / scale : 0.0;
    energy_rate_ = -ad_dot_phi;
  }

  const LiePoissonSystem<G>& system_;
  struct Unused {};
  std::conditional_t<isDynamicGroup<G>, MatrixFieldWorkspace<G>, Unused> w_;
  std::conditional_t<isDynamicGroup<G>, Dual, Unused> out_;  // the field, unused here
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

// LinearlyImplicitDdb: a DDB step whose dissipative factor lowers the energy for every step
// size (docs/guide/steady-states.md, "A dissipative factor that lowers the energy at any h").
// DDB's step is a conservative factor, τ(hξ) from the discrete Legendre equation, and an
// explicit dissipative one, τ(hφ) with φ = k♯(ad*_ξ μ) (eq. (4.12)); the explicit factor is
// stable only for h|α| below a bound set by the largest curvature of H on the orbit, beyond
// which the energy rises (docs/design/architecture.md, "Large N: the step's stability bound").
// Here, with k♯ = α·I and f = σH (σ = sign α: the flow lowers f; on a group whose pairing is
// not its coordinates' inner product, k♯ = α·R with R the pairing's Riesz map, and ∇f, J are
// taken in that inner product: DissipationMetric::scalarMultiple, OrbitNewton):
//   (i)  μ̃ = the DDB step of the system without dissipation (the same Legendre solve);
//   (ii) μ_{k+1} = Ad*_{cay(s v)} μ̃, v ≈ −(J + I/τ)⁻¹ ∇f at μ̃, τ = h|α|,
// where ∇f and J are the gradient and Hessian of f(Ad*_{cay x} μ̃) at x = 0: one Newton step of
// the minimizing movement min_x f + ‖x‖²/(2τ), i.e. linearly implicit Euler on the gradient
// flow whose explicit Euler step −τ∇f = hφ(μ̃) is DDB's own factor. s = 1, ½, … is the first
// that lowers f by Armijo's rule (OrbitNewton::advanceProximal). So the factor never raises f,
// for any h, and every state is a conjugate of the last (Casimirs kept to rounding); for small
// h, v = hφ(μ̃) + O(h²): first order, as DDB with α ≠ 0, and DDB itself at α = 0. As h|α| → ∞
// the factor becomes a step of the Newton search on the orbit (OrbitNewton). The conservative
// factor still changes H by its own error, of either sign: a step as a whole is monotone in H
// only up to that (the energy step control checks every step).
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/solvers/orbit_newton.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace ddb {

namespace detail {
/// α of the system's metric k♯ = α·R (DissipationMetric::scalarMultiple), which the linearly
/// implicit factor needs; InvalidArgument naming `method` where the metric is no such multiple.
template <class G>
double requireScalarMetric(const LiePoissonSystem<G>& system, const std::string& method) {
  const std::optional<double> alpha = system.metric().scalarMultiple();
  if (!alpha) {
    throwInvalid("method", method,
                 "needs the metric alpha * identity (on SU(N) x| su(N)*, alpha times the swap of "
                 "its parts), which '" +
                     system.name() + "' has not");
  }
  return *alpha;
}
}  // namespace detail

template <class R>
class LinearlyImplicitDdb : public Ddb<R> {
 public:
  using typename Ddb<R>::G;
  using typename Ddb<R>::Dual;

  /// `system` must have the metric k♯ = α·I (DissipationMetric::scalarMultiple).
  LinearlyImplicitDdb(std::shared_ptr<const LiePoissonSystem<G>> system, R retraction = R(),
                      LegendreForm form = LegendreForm::kLagrangian, SolverOptions options = {})
      : Ddb<R>(system->withoutDissipation(), std::move(retraction), form, options),
        with_dissipation_(std::move(system)),
        alpha_(detail::requireScalarMetric(*with_dissipation_, "ddb-*-implicit")),
        dissipative_factor_(*with_dissipation_, alpha_) {}

  std::string name() const override { return this->nameWith("ddb-") + "-implicit"; }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }

  void advance(Dual& mu, double t, double h) override {
    Ddb<R>::advance(mu, t, h);  // Ddb's own step, not this class's override
    factor_steps_ = 0;
    if (alpha_ == 0.0) return;  // no dissipative factor: the step is Ddb's
    double energy = with_dissipation_->energy(mu);
    typename OrbitNewton<G>::Report report;
    if (!dissipative_factor_.advanceProximal(mu, energy, h * std::abs(alpha_), report)) {
      throw SolveFailure("linearly implicit dissipative factor (no step length lowered the energy)",
                         -1, t, h, dissipative_factor_.residual(), 0.0);
    }
    factor_steps_ = report.length > 0 ? 1 : 0;
  }

  /// The Legendre solve's iterations and the dissipative factor's Newton step (one, unless
  /// the state was at rest).
  long lastStepIterations() const override { return Ddb<R>::lastStepIterations() + factor_steps_; }

 private:
  std::shared_ptr<const LiePoissonSystem<G>> with_dissipation_;  // Ddb's system has none
  double alpha_;
  OrbitNewton<G> dissipative_factor_;
  long factor_steps_ = 0;  // the dissipative factor's Newton steps in the last step
};

}  // namespace ddb

// integrate(): a method driven over N steps of one size h from (t0, μ0), each taken by takeStep,
// the library's one stepping rule (integrators/methods/one_step_method.h), an observer shown every
// state μ_k (the read-out, not a method's internal variables); Trajectory, an observer that keeps
// them. A failed step keeps the valid prefix: the observer has seen every state before it when
// the typed SolveFailure propagates. Relaxation (relax.h) is the loop with a stop rule and step
// control.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <string>
#include <vector>

namespace ddb {

/// Advances `steps` steps of size h from (t0, mu0); observer(k, t_k, mu_k) sees k = 0..steps.
/// Throws SolveFailure with the failing step index, after the observer saw the states before it.
template <class G, class Observer>
void integrate(OneStepMethod<G>& method, const typename G::template Dual<double>& mu0, double t0,
               double h, long steps, Observer&& observer) {
  requireFiniteMatrix("mu0", mu0);
  requireFinite("t0", t0);
  requirePositive("h", h);
  if (steps < 0) throwInvalid("steps", std::to_string(steps), "must be >= 0");
  method.reset();
  typename G::template Dual<double> mu = mu0;
  observer(0L, t0, mu);
  for (long k = 0; k < steps; ++k) {
    const double t = t0 + static_cast<double>(k) * h;
    try {
      takeStep(method, mu, t, h);
    } catch (const SolveFailure& failure) {
      failure.rethrowAtStep(k, t, h);
    }
    observer(k + 1, t0 + static_cast<double>(k + 1) * h, mu);
  }
}

/// The states of a trajectory, filled by integrate() through record().
template <class G>
struct Trajectory {
  std::vector<double> times;
  std::vector<typename G::template Dual<double>> states;

  auto record() {
    return [this](long, double t, const typename G::template Dual<double>& mu) {
      times.push_back(t);
      states.push_back(mu);
    };
  }
};

}  // namespace ddb

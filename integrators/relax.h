// relax(): integrates a system until it is steady (docs/steady-states.md). The run stops
// at the first state whose residual r = ‖ad*_ξ μ‖/(‖ξ‖ ‖μ‖) (SteadyStateProbe) is at most
// the tolerance, or at a cap on the accepted steps or on the time, or at a failure, and
// says which. With StepSizeControl::adaptive the steps are chosen by EnergyStepControl
// (for the Casimir-keeping methods: every accepted step keeps the state on the orbit and
// moves the energy the way the flow does); without, every step has the first h, as in
// runMethod(). The sink sees every accepted state, in order, as it is computed.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/energy_step_control.h>
#include <ddb/integrators/one_step_method.h>
#include <ddb/integrators/steady_state_probe.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace ddb {

/// Why relax() stopped.
enum class RelaxStop {
  kSteady,   ///< r ≤ tolerance
  kStepCap,  ///< max_steps accepted steps taken
  kTimeCap,  ///< t_end reached
  kFailure,  ///< a step failed (fixed h) or h fell below its floor (adaptive)
};

inline const char* relaxStopName(RelaxStop stop) {
  switch (stop) {
    case RelaxStop::kSteady:
      return "steady";
    case RelaxStop::kStepCap:
      return "step cap";
    case RelaxStop::kTimeCap:
      return "time cap";
    case RelaxStop::kFailure:
      break;
  }
  return "failure";
}

struct RelaxOptions {
  double tolerance = 0.0;  ///< stop when r ≤ tolerance (0: only at a cap or at rest)
  long max_steps = 0;      ///< cap on accepted steps
  double t_end = std::numeric_limits<double>::infinity();  ///< cap on the time
  StepSizeControl control;
};

/// What the sink sees with each accepted state: its index k, time, the step that reached
/// it (0 for k = 0), its energy H and residual r (NaN unless a tolerance or the step
/// control needs it: SteadyStateProbe costs four products on matrix groups).
struct RelaxState {
  long k = 0;
  double t = 0.0, h = 0.0, energy = 0.0, residual = 0.0;
};

/// What relax() did. A failed run keeps its valid prefix: `final` is the last accepted state.
template <class G>
struct RelaxResult {
  using Dual = typename G::template Dual<double>;

  Dual final;
  RelaxState last;  // of `final`
  RelaxStop stop = RelaxStop::kFailure;
  long steps_rejected = 0;  // tried and retried smaller (adaptive only)
  double runtime_s = 0.0;   // wall time, sink included
  std::string failure;      // the message, for kFailure
  long failed_step = -1;    // index k of the step from state k that failed

  bool steady() const { return stop == RelaxStop::kSteady; }
  bool ok() const { return stop != RelaxStop::kFailure; }
};

namespace detail {

/// The message of `failure` as integrate() would raise it at step k.
inline std::string messageAtStep(const SolveFailure& failure, long k, double t, double h) {
  std::string message;
  try {
    failure.rethrowAtStep(k, t, h);
  } catch (const SolveFailure& located) {
    message = located.what();
  }
  return message;
}

}  // namespace detail

/// Relaxes mu0 with `method` from the step h0 (options: when to stop, how to choose h).
/// Bad arguments throw InvalidArgument; a failed step is recorded in the result.
template <class G, class Sink>
RelaxResult<G> relax(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                     const typename G::template Dual<double>& mu0, double h0,
                     const RelaxOptions& options, Sink&& sink) {
  using Dual = typename G::template Dual<double>;
  requireFinite("mu0", mu0);
  requirePositive("h", h0);
  if (!(options.tolerance >= 0 && options.tolerance < 1)) {
    throwInvalid("tolerance", formatValue(options.tolerance), "must be in [0, 1)");
  }
  if (options.max_steps < 0) {
    throwInvalid("max_steps", std::to_string(options.max_steps), "must be >= 0");
  }
  if (!(options.t_end > 0)) throwInvalid("t_end", formatValue(options.t_end), "must be > 0");
  const auto start = std::chrono::steady_clock::now();
  EnergyStepControl control(options.control, h0);
  const bool adaptive = options.control.adaptive;
  // r and dH/dt cost four products on matrix groups: evaluated only where a tolerance or
  // the step control reads them.
  const bool probing = adaptive || options.tolerance > 0;
  SteadyStateProbe<G> probe(system);
  const auto residualAt = [&](const Dual& mu) {
    if (!probing) return std::numeric_limits<double>::quiet_NaN();
    probe.evaluate(mu);
    return probe.residual();
  };
  RelaxResult<G> result;
  result.final = mu0;
  RelaxState& state = result.last;
  state.energy = system.energy(mu0);
  state.residual = residualAt(mu0);
  if (adaptive && probe.energyRate() == 0 && state.residual > options.tolerance) {
    throwInvalid("adaptive", "true", "needs dissipation: dH/dt = 0 at mu0 (alpha = 0?)");
  }
  sink(state, result.final);
  // Times as in integrate(): t = t_start + j·h over a stretch of equal steps, so that a
  // fixed-h run lands on the same times.
  double t_start = 0.0, h_stretch = control.h();
  long j = 0;
  Dual trial = mu0;
  method.reset();
  while (true) {
    if (probing && state.residual <= options.tolerance) {
      result.stop = RelaxStop::kSteady;
      break;
    }
    if (state.k >= options.max_steps) {
      result.stop = RelaxStop::kStepCap;
      break;
    }
    const double left = options.t_end - state.t;
    if (std::isfinite(options.t_end) && left <= 1e-12 * options.t_end) {
      result.stop = RelaxStop::kTimeCap;
      break;
    }
    const double h = std::min(control.h(), left);
    const double rate = probe.energyRate();
    trial = result.final;
    std::string rejected;
    try {
      method.advance(trial, state.t, h);
      if (!trial.allFinite()) throw NonFiniteState(method.name(), -1, state.t, h, trial);
    } catch (const SolveFailure& failure) {
      if (!adaptive) {
        result.failure = detail::messageAtStep(failure, state.k, state.t, h);
        result.failed_step = state.k;
        break;
      }
      rejected = control.reject(failure.what());
    }
    const double energy = rejected.empty() ? system.energy(trial) : 0.0;
    if (adaptive && rejected.empty()) rejected = control.judge(h, rate, state.energy, energy);
    if (!rejected.empty()) {
      ++result.steps_rejected;
      if (control.exhausted()) {
        result.failure = "relax: step " + std::to_string(state.k) +
                         " from t = " + formatValue(state.t) +
                         " rejected down to h = " + formatValue(h) +
                         " (below 2^-30 of the first h): " + rejected;
        result.failed_step = state.k;
        break;
      }
      continue;
    }
    if (h != h_stretch) {
      t_start = state.t;
      h_stretch = h;
      j = 0;
    }
    std::swap(result.final, trial);
    ++state.k;
    state.t = t_start + static_cast<double>(++j) * h;
    state.h = h;
    state.energy = energy;
    state.residual = residualAt(result.final);
    sink(state, result.final);
  }
  result.runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// relax() with no sink.
template <class G>
RelaxResult<G> relax(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                     const typename G::template Dual<double>& mu0, double h0,
                     const RelaxOptions& options) {
  return relax(method, system, mu0, h0, options,
               [](const RelaxState&, const typename G::template Dual<double>&) {});
}

}  // namespace ddb

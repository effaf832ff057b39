// One method over one trajectory, streamed: runMethod() drives integrate() and shows a
// sink every K-th state and the last one as they are computed, so that memory stays
// constant however many steps are taken. It also keeps what a comparison needs: the
// final state, the largest relative Casimir drift over every state (not only the ones
// the sink sees), the wall time, and a failure with its step instead of an exception.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/drivers/integrate.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>

namespace ddb {

/// max over observed states and i of |C_i(μ) − C_i(μ₀)| / |C_i(μ₀)| (absolute where
/// C_i(μ₀) = 0): the casimir_drift of docs/reference/command-lines-and-files.md.
template <class G>
class CasimirDrift {
 public:
  using Dual = typename G::template Dual<double>;

  CasimirDrift(const LiePoissonSystem<G>& system, const Dual& mu0)
      : system_(system), c0_(system.casimirs(mu0)) {}

  void observe(const Dual& mu) {
    const auto c = system_.casimirs(mu);
    for (Eigen::Index i = 0; i < c.size(); ++i) {
      const double scale = std::abs(c0_(i)) > 0 ? std::abs(c0_(i)) : 1.0;
      drift_ = std::max(drift_, std::abs(c(i) - c0_(i)) / scale);
    }
  }
  double value() const { return drift_; }

 private:
  const LiePoissonSystem<G>& system_;
  typename LiePoissonSystem<G>::Casimirs c0_;
  double drift_ = 0.0;
};

/// Forwards states k = 0, K, 2K, ... to `sink(k, t, mu)` as they arrive, and on finish()
/// the last state seen if it was not one of them. Holds one state, never the trajectory.
template <class Dual, class Sink>
class EveryKth {
 public:
  EveryKth(long every, Sink& sink) : every_(requireAtLeastOne(every)), sink_(sink) {}

  void operator()(long k, double t, const Dual& mu) {
    if (k % every_ == 0) {
      sink_(k, t, mu);
      pending_ = false;
    } else {
      last_k_ = k;
      last_t_ = t;
      last_ = mu;
      pending_ = true;
    }
  }
  void finish() {
    if (pending_) sink_(last_k_, last_t_, last_);
    pending_ = false;
  }

 private:
  static long requireAtLeastOne(long every) {
    if (every < 1) throwInvalid("every", std::to_string(every), "must be >= 1");
    return every;
  }

  long every_;
  Sink& sink_;
  bool pending_ = false;
  long last_k_ = 0;
  double last_t_ = 0.0;
  Dual last_;
};

/// What runMethod() saw. A failed run keeps its valid prefix: `final` is the last state
/// computed before the failing step (μ₀ if the first step failed).
template <class G>
struct RunResult {
  using Dual = typename G::template Dual<double>;

  Dual final;
  double t_final = 0.0;
  long steps = 0;              // steps completed
  double casimir_drift = 0.0;  // over every state computed, μ₀ included
  double runtime_s = 0.0;      // wall time of the whole run, sink included
  std::string failure;         // the error message; empty if every step succeeded
  long failed_step = -1;       // index k of the step from t_k that failed

  bool ok() const { return failure.empty(); }
};

struct RunOptions {
  long every = 1;  // the sink sees every `every`-th state and the last one
  /// Called with (steps done, steps requested) every `progress_interval` steps, so that a
  /// long run can report within itself; empty: no calls.
  std::function<void(long, long)> progress;
  long progress_interval = 4096;
};

/// Integrates `steps` steps of size h from (0, mu0) with `method`, showing `sink(k, t, mu)`
/// the states chosen by options.every. A SolveFailure raised inside a step (a solver or a
/// series out of its budget, a non-finite state, an exp step past its injectivity limit:
/// docs/reference/guarantees.md) ends the run and is recorded in the result; bad arguments to
/// runMethod itself throw InvalidArgument.
template <class G, class Sink>
RunResult<G> runMethod(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                       const typename G::template Dual<double>& mu0, double h, long steps,
                       const RunOptions& options, Sink&& sink) {
  using Dual = typename G::template Dual<double>;
  requireFinite("mu0", mu0);
  requirePositive("h", h);
  if (steps < 0) throwInvalid("steps", std::to_string(steps), "must be >= 0");
  if (options.progress_interval < 1) {
    throwInvalid("progress_interval", std::to_string(options.progress_interval), "must be >= 1");
  }
  RunResult<G> result;
  result.final = mu0;
  CasimirDrift<G> drift(system, mu0);
  EveryKth<Dual, Sink> thinned(options.every, sink);
  const auto start = std::chrono::steady_clock::now();
  try {
    integrate(method, mu0, 0.0, h, steps, [&](long k, double t, const Dual& mu) {
      drift.observe(mu);
      result.final = mu;
      result.t_final = t;
      result.steps = k;
      thinned(k, t, mu);
      if (options.progress && k % options.progress_interval == 0) options.progress(k, steps);
    });
  } catch (const SolveFailure& failure) {
    result.failure = failure.what();
    result.failed_step = failure.step();
  }
  thinned.finish();
  result.runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.casimir_drift = drift.value();
  return result;
}

/// runMethod() with no sink: final state, drift, time and failure only.
template <class G>
RunResult<G> runMethod(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                       const typename G::template Dual<double>& mu0, double h, long steps,
                       const RunOptions& options = {}) {
  return runMethod(method, system, mu0, h, steps, options,
                   [](long, double, const typename G::template Dual<double>&) {});
}

}  // namespace ddb

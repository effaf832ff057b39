// relax() and Relaxation: integrate a system until it is steady (docs/guide/steady-states.md). The
// run stops at the first state whose residual r = ‖ad*_ξ μ‖/(‖ξ‖ ‖μ‖) (SteadyStateProbe) is at most
// the tolerance, or at a cap on the accepted steps or on the time, or at a failure, and says which.
// With StepSizeControl::adaptive the steps are chosen by EnergyStepControl (for the Casimir-keeping
// methods: every accepted step keeps the state on the orbit and moves the energy the way the flow
// does); without, every step has the first h, as in runMethod(). With RelaxOptions::newton there is
// no method and no time: each step is an iteration of OrbitNewton, Newton's method for a critical
// point of H on the orbit. The sink sees every accepted state, in order, as it is computed.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/drivers/energy_step_control.h>
#include <ddb/integrators/drivers/steady_state_probe.h>
#include <ddb/integrators/methods/one_step_method.h>
#include <ddb/integrators/solvers/orbit_newton.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

namespace ddb {

/// Why relax() stopped.
enum class RelaxStop {
  kSteady,       ///< r ≤ tolerance
  kStepCap,      ///< max_steps accepted steps taken
  kTimeCap,      ///< t_end reached
  kFailure,      ///< a step failed (fixed h) or h fell below its floor (adaptive)
  kInterrupted,  ///< the caller ended the run (Relaxation::interrupt)
};

inline const char* relaxStopName(RelaxStop stop) {
  switch (stop) {
    case RelaxStop::kSteady:
      return "steady";
    case RelaxStop::kStepCap:
      return "step cap";
    case RelaxStop::kTimeCap:
      return "time cap";
    case RelaxStop::kInterrupted:
      return "interrupted";
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
  /// Search by OrbitNewton instead of integrating: needs a tolerance and no time cap; a
  /// state's h is the length of the step that reached it on the orbit, and t stays 0.
  bool newton = false;
};

/// What the sink sees with each accepted state: its index k, time, the step that reached
/// it (0 for k = 0; with newton, its length ‖x‖ on the orbit), its energy H and residual r (NaN
/// unless a tolerance or the step control needs it: SteadyStateProbe costs four products on matrix
/// groups).
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
  long steps_rejected = 0;  // tried and retried smaller (adaptive; newton: the halvings)
  double runtime_s = 0.0;   // wall time, sink included
  std::string failure;      // the message, for kFailure
  long failed_step = -1;    // index k of the step from state k that failed

  bool steady() const { return stop == RelaxStop::kSteady; }
  bool ok() const { return stop != RelaxStop::kFailure; }
};

/// A relaxation as an object (Boost.Odeint's steppers and GeometricIntegrators.jl's
/// integrators keep problem, method and cursor apart likewise): advance() takes one
/// accepted step at a time, and save()/load() carry the whole cursor (state, time, step
/// control, the method's warm start) so that a run resumed from a checkpoint takes the
/// uninterrupted run's steps to the bit (docs/reference/command-lines-and-files.md, "Checkpoints").
template <class G>
class Relaxation {
 public:
  using Dual = typename G::template Dual<double>;

  /// Starts at mu0 with the step h0 (options: when to stop, how to choose h). Bad arguments
  /// throw InvalidArgument; calls method.reset().
  Relaxation(OneStepMethod<G>& method, const LiePoissonSystem<G>& system, const Dual& mu0,
             double h0, const RelaxOptions& options)
      : method_(&method),
        system_(system),
        options_(checked(options)),
        probing_(options.control.adaptive || options.tolerance > 0),
        probe_(system) {
    if (options.newton) throwInvalid("newton", "true", "a Newton search takes no method and no h");
    control_.emplace(options.control, requirePositive("h", h0));
    start(mu0, "adaptive");
    times_.h = control_->h();
    method_->reset();
  }

  /// A Newton search from mu0 (options.newton; OrbitNewton): until r ≤ options.tolerance or
  /// options.max_steps iterations. Bad arguments throw InvalidArgument.
  Relaxation(const LiePoissonSystem<G>& system, const Dual& mu0, const RelaxOptions& options)
      : system_(system), options_(checked(options)), probing_(true), probe_(system) {
    if (!options.newton) throwInvalid("newton", "false", "this constructor is the Newton search's");
    if (options.control.adaptive) {
      throwInvalid("adaptive", "true", "a Newton search chooses its own steps");
    }
    if (!(options.tolerance > 0)) {
      throwInvalid("tolerance", formatValue(options.tolerance), "a Newton search needs one > 0");
    }
    if (std::isfinite(options.t_end)) {
      throwInvalid("t_end", formatValue(options.t_end),
                   "a Newton search simulates no time: cap it by max_steps");
    }
    start(mu0, "newton");
    newton_.emplace(system, probe_.energyRate() < 0 ? 1.0 : -1.0);
  }

  /// The accepted state: its index, time, step, energy and residual, and the state itself.
  const RelaxState& state() const { return result_.last; }
  const Dual& current() const { return result_.final; }
  bool stopped() const { return stopped_; }
  /// What the run did so far (its stop once stopped()); runtime_s is the caller's to fill.
  const RelaxResult<G>& result() const { return result_; }

  /// Tries steps until one is accepted (true) or the run stops (false: result().stop says
  /// why). A failed step is recorded in the result; the state stays the last accepted one.
  bool advance() {
    if (stopped_) return false;
    if (newton_) return advanceByNewton();
    while (true) {
      if (probing_ && state().residual <= options_.tolerance) return stop(RelaxStop::kSteady);
      if (state().k >= options_.max_steps) return stop(RelaxStop::kStepCap);
      if (reachedTimeCap(state().t, options_.t_end)) return stop(RelaxStop::kTimeCap);
      const double h = std::min(control_->h(), options_.t_end - state().t);
      trial_ = result_.final;
      const StepAttempt attempt = attemptStep(h);
      if (attempt.rejected) ++result_.steps_rejected;
      if (!attempt.failure.empty()) {
        result_.failure = attempt.failure;
        result_.failed_step = state().k;
        return stop(RelaxStop::kFailure);
      }
      if (!attempt.accepted) continue;
      std::swap(result_.final, trial_);
      RelaxState& s = cursor();
      ++s.k;
      s.t = times_.after(s.t, h);
      s.h = h;
      s.energy = attempt.energy;
      s.residual = residualAt(result_.final);
      return true;
    }
  }

  /// Ends the run before its stop (a signal, a caller's own rule): result().stop is
  /// kInterrupted. A run already stopped keeps its stop.
  void interrupt() {
    if (!stopped_) stop(RelaxStop::kInterrupted);
  }

  /// Replaces the caps (a resumed run may extend them); the tolerance and step control stay.
  void setCaps(long max_steps, double t_end) {
    RelaxOptions options = options_;
    options.max_steps = max_steps;
    options.t_end = t_end;
    options_ = checked(options);
  }

  /// The cursor: the accepted state and its record, the stretch of equal steps, the step
  /// control and the method's warm start.
  void save(BinaryRecordWriter& out) const {
    out.tag("relaxation");
    out.put(state().k);
    out.put(state().t);
    out.put(state().h);
    out.put(state().energy);
    out.put(state().residual);
    MatrixBackend<Dual>::save(out, result_.final);
    out.put(result_.steps_rejected);
    out.put(times_.t_start);
    out.put(times_.h);
    out.put(times_.j);
    if (newton_) {
      newton_->save(out);
    } else {
      control_->save(out);
      method_->saveWarmStart(out);
    }
  }
  /// Continues from what save() wrote, with this object's method, system and options.
  void load(BinaryRecordReader& in) {
    loadCursor(in);
    if (newton_) {
      newton_->load(in);
    } else {
      control_->load(in);
      method_->loadWarmStart(in, result_.final);
    }
    // The probe as the uninterrupted run left it: evaluated at the accepted state.
    if (probing_) probe_.evaluate(result_.final);
    stopped_ = false;
    result_.stop = RelaxStop::kFailure;
  }

 private:
  /// The times of accepted steps as integrate() counts them: t = t_start + j·h over a stretch
  /// of equal steps h, so that a fixed-h run lands on the same times however it was resumed.
  struct StepTimes {
    double t_start = 0.0, h = 0.0;
    long j = 0;

    /// The time after an accepted step of `step` from t (a new stretch if the step changed).
    double after(double t, double step) {
      if (step != h) {
        t_start = t;
        h = step;
        j = 0;
      }
      return t_start + static_cast<double>(++j) * step;
    }
  };

  /// What one attempted step did.
  struct StepAttempt {
    bool accepted = false;  ///< the trial is the next state; `energy` is its H
    bool rejected = false;  ///< the step control rejected it: h halved (a rejected step)
    double energy = 0.0;
    std::string failure;  ///< non-empty: the run fails (a failed fixed step, or h exhausted)
  };

  /// Whether t has reached the cap t_end (infinite: none), up to the rounding of a sum of steps.
  static bool reachedTimeCap(double t, double t_end) {
    return std::isfinite(t_end) && t_end - t <= 1e-12 * t_end;
  }

  /// One step of size h from the accepted state into trial_ (takeStep: the loops' one rule).
  /// With a fixed h a failure ends the run; adaptive, a failure or the judge's verdict
  /// (EnergyStepControl::judge) rejects the step, and the run fails only once h has fallen
  /// below its floor.
  StepAttempt attemptStep(double h) {
    const bool adaptive = options_.control.adaptive;
    const long k = state().k;
    const double t = state().t;
    StepAttempt attempt;
    std::string why;
    try {
      takeStep(*method_, trial_, t, h);
    } catch (const SolveFailure& failure) {
      if (!adaptive) {
        attempt.failure = messageAtStep(failure, k, t, h);
        return attempt;
      }
      why = control_->reject(failure.what());
    }
    if (why.empty()) {
      attempt.energy = system_.energy(trial_);
      if (adaptive) why = control_->judge(h, probe_.energyRate(), state().energy, attempt.energy);
    }
    attempt.accepted = why.empty();
    attempt.rejected = !attempt.accepted;
    if (attempt.rejected && control_->exhausted()) {
      attempt.failure = "relax: step " + std::to_string(k) + " from t = " + formatValue(t) +
                        " rejected down to h = " + formatValue(h) +
                        " (below 2^-30 of the first h): " + why;
    }
    return attempt;
  }

  /// The message of `failure` as integrate() would raise it at step k.
  static std::string messageAtStep(const SolveFailure& failure, long k, double t, double h) {
    std::string message;
    try {
      failure.rethrowAtStep(k, t, h);
    } catch (const SolveFailure& located) {
      message = located.what();
    }
    return message;
  }

  /// Reads what save() wrote up to the step control, for a state of the current one's size
  /// (and, distributed, layout: MatrixBackend::load); throws CorruptRecord.
  void loadCursor(BinaryRecordReader& in) {
    using B = MatrixBackend<Dual>;
    in.expectTag("relaxation");
    RelaxState s;
    in.get(s.k);
    in.get(s.t);
    in.get(s.h);
    in.get(s.energy);
    in.get(s.residual);
    Dual mu = result_.final;
    B::load(in, mu);
    // Not finite: its Frobenius norm, which every rank of a distributed state agrees on, is
    // NaN or inf (a state so large that its norm overflows is refused too).
    if (!std::isfinite(B::frobeniusNorm(mu)) || s.k < 0) {
      throw CorruptRecord("a relaxation state with a negative index or not finite");
    }
    cursor() = s;
    result_.final = std::move(mu);
    in.get(result_.steps_rejected);
    in.get(times_.t_start);
    in.get(times_.h);
    in.get(times_.j);
  }

  static RelaxOptions checked(const RelaxOptions& options) {
    if (!(options.tolerance >= 0 && options.tolerance < 1)) {
      throwInvalid("tolerance", formatValue(options.tolerance), "must be in [0, 1)");
    }
    if (options.max_steps < 0) {
      throwInvalid("max_steps", std::to_string(options.max_steps), "must be >= 0");
    }
    if (!(options.t_end > 0)) throwInvalid("t_end", formatValue(options.t_end), "must be > 0");
    return options;
  }
  RelaxState& cursor() { return result_.last; }

  // The first state; `needs` names the option that needs dissipation at mu0 when not steady.
  void start(const Dual& mu0, const char* needs) {
    requireFiniteMatrix("mu0", mu0);
    result_.final = mu0;
    result_.stop = RelaxStop::kFailure;
    cursor().energy = system_.energy(mu0);
    cursor().residual = residualAt(mu0);
    const bool directed = options_.control.adaptive || options_.newton;
    if (directed && probe_.energyRate() == 0 && state().residual > options_.tolerance) {
      throwInvalid(needs, "true", "needs dissipation: dH/dt = 0 at mu0 (alpha = 0?)");
    }
    trial_ = mu0;
  }

  // One OrbitNewton iteration; t stays, h is the step's length on the orbit.
  bool advanceByNewton() {
    if (state().residual <= options_.tolerance) return stop(RelaxStop::kSteady);
    if (state().k >= options_.max_steps) return stop(RelaxStop::kStepCap);
    typename OrbitNewton<G>::Report report;
    double energy = state().energy;
    bool accepted = false;
    std::string why = "no step length along its direction was accepted (" +
                      std::to_string(OrbitNewton<G>::kMaxHalvings) + " halvings)";
    try {
      accepted = newton_->advance(result_.final, energy, report);
    } catch (const SolveFailure& failure) {
      why = failure.what();
    }
    if (!accepted) {
      result_.failure = "relax: Newton step " + std::to_string(state().k) +
                        " from r = " + formatValue(state().residual) + ": " + why;
      result_.failed_step = state().k;
      return stop(RelaxStop::kFailure);
    }
    result_.steps_rejected += report.halvings;
    RelaxState& s = cursor();
    ++s.k;
    s.h = report.length;
    s.energy = energy;
    s.residual = residualAt(result_.final);
    return true;
  }
  bool stop(RelaxStop why) {
    result_.stop = why;
    stopped_ = true;
    return false;
  }
  // r and dH/dt cost four products on matrix groups: evaluated only where a tolerance or
  // the step control reads them.
  double residualAt(const Dual& mu) {
    if (!probing_) return std::numeric_limits<double>::quiet_NaN();
    probe_.evaluate(mu);
    return probe_.residual();
  }

  OneStepMethod<G>* method_ = nullptr;  // none in a Newton search
  const LiePoissonSystem<G>& system_;
  RelaxOptions options_;
  std::optional<EnergyStepControl> control_;  // step control (fixed or adaptive)
  std::optional<OrbitNewton<G>> newton_;      // or the Newton search
  bool probing_;
  SteadyStateProbe<G> probe_;
  RelaxResult<G> result_;
  bool stopped_ = false;
  StepTimes times_;
  Dual trial_;
};

namespace detail {

/// Runs `relaxation` to its stop, showing the sink every accepted state, the first included.
template <class G, class Sink>
RelaxResult<G> runToStop(Relaxation<G>& relaxation, Sink&& sink) {
  const auto start = std::chrono::steady_clock::now();
  sink(relaxation.state(), relaxation.current());
  while (relaxation.advance()) sink(relaxation.state(), relaxation.current());
  RelaxResult<G> result = relaxation.result();
  result.runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace detail

/// Relaxes mu0 with `method` from the step h0 (options: when to stop, how to choose h);
/// sink(state, μ) sees every accepted state, the first included. Bad arguments throw
/// InvalidArgument; a failed step is recorded in the result.
template <class G, class Sink>
RelaxResult<G> relax(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                     const typename G::template Dual<double>& mu0, double h0,
                     const RelaxOptions& options, Sink&& sink) {
  Relaxation<G> relaxation(method, system, mu0, h0, options);
  return detail::runToStop(relaxation, sink);
}

/// relax() with no sink.
template <class G>
RelaxResult<G> relax(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                     const typename G::template Dual<double>& mu0, double h0,
                     const RelaxOptions& options) {
  return relax(method, system, mu0, h0, options,
               [](const RelaxState&, const typename G::template Dual<double>&) {});
}

/// The Newton search (options.newton: OrbitNewton) from mu0, with the same stops, sink and
/// result as relax(); t stays 0.
template <class G, class Sink>
RelaxResult<G> relaxByNewton(const LiePoissonSystem<G>& system,
                             const typename G::template Dual<double>& mu0,
                             const RelaxOptions& options, Sink&& sink) {
  Relaxation<G> relaxation(system, mu0, options);
  return detail::runToStop(relaxation, sink);
}

}  // namespace ddb

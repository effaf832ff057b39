// TimeRelaxation: a steady state reached by integrating (docs/guide/steady-states.md): the
// method's steps until r ≤ the tolerance, or a cap on the accepted steps or on the time, or a
// failure. With StepSizeControl::adaptive the steps are chosen by EnergyStepControl (for the
// Casimir-keeping methods: every accepted step keeps the state on the orbit and moves the energy
// the way the flow does); without, every step has the first h, as in runMethod(). Each step is
// taken by takeStep, the library's one stepping rule (integrators/methods/one_step_method.h).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/drivers/energy_step_control.h>
#include <ddb/integrators/drivers/steady_state_search.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace ddb {

template <class G>
class TimeRelaxation final : public SteadyStateSearch<G> {
  using Base = SteadyStateSearch<G>;

 public:
  using Dual = typename Base::Dual;

  /// Starts at mu0 with the step h0 (options: when to stop, how to choose h). Bad arguments
  /// throw InvalidArgument; calls method.reset().
  TimeRelaxation(OneStepMethod<G>& method, const LiePoissonSystem<G>& system, const Dual& mu0,
                 double h0, const RelaxOptions& options)
      : Base(system, options, options.control.adaptive || options.tolerance > 0), method_(method) {
    if (options.newton) throwInvalid("newton", "true", "a Newton search takes no method and no h");
    control_.emplace(options.control, requirePositive("h", h0));
    this->start(mu0, "adaptive", options.control.adaptive);
    trial_ = mu0;
    times_.h = control_->h();
    method_.reset();
  }

  bool advance() override {
    if (this->stopped()) return false;
    const RelaxOptions& options = this->options();
    while (true) {
      if (this->probing() && this->state().residual <= options.tolerance) {
        return this->stop(RelaxStop::kSteady);
      }
      if (this->state().k >= options.max_steps) return this->stop(RelaxStop::kStepCap);
      if (reachedTimeCap(this->state().t, options.t_end)) return this->stop(RelaxStop::kTimeCap);
      const double h = std::min(control_->h(), options.t_end - this->state().t);
      trial_ = this->current();
      const StepAttempt attempt = attemptStep(h);
      if (attempt.rejected) ++this->rejections();
      if (!attempt.failure.empty()) return this->fail(attempt.failure);
      if (!attempt.accepted) continue;
      this->accept(trial_, times_.after(this->state().t, h), h, attempt.energy);
      return true;
    }
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

  /// The stretch of equal steps, the step control and the method's warm start.
  void saveOwn(BinaryRecordWriter& out) const override {
    out.put(times_.t_start);
    out.put(times_.h);
    out.put(times_.j);
    control_->save(out);
    method_.saveWarmStart(out);
  }
  void loadOwn(BinaryRecordReader& in) override {
    in.get(times_.t_start);
    in.get(times_.h);
    in.get(times_.j);
    control_->load(in);
    method_.loadWarmStart(in, this->current());
  }

  /// Whether t has reached the cap t_end (infinite: none), up to the rounding of a sum of steps.
  static bool reachedTimeCap(double t, double t_end) {
    return std::isfinite(t_end) && t_end - t <= 1e-12 * t_end;
  }

  /// One step of size h from the accepted state into trial_ (takeStep: the loops' one rule).
  /// With a fixed h a failure ends the run; adaptive, a failure or the judge's verdict
  /// (EnergyStepControl::judge) rejects the step, and the run fails only once h has fallen
  /// below its floor.
  StepAttempt attemptStep(double h) {
    const bool adaptive = this->options().control.adaptive;
    const long k = this->state().k;
    const double t = this->state().t;
    StepAttempt attempt;
    std::string why;
    try {
      takeStep(method_, trial_, t, h);
    } catch (const SolveFailure& failure) {
      if (!adaptive) {
        attempt.failure = messageAtStep(failure, k, t, h);
        return attempt;
      }
      why = control_->reject(failure.what());
    }
    if (why.empty()) {
      attempt.energy = this->system().energy(trial_);
      if (adaptive) {
        why = control_->judge(h, this->probe().energyRate(), this->state().energy, attempt.energy);
      }
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

  OneStepMethod<G>& method_;
  std::optional<EnergyStepControl> control_;  // constructed after h0 is checked
  StepTimes times_;
  Dual trial_;
};

}  // namespace ddb

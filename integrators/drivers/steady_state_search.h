// SteadyStateSearch: the one small interface of the two ways to a steady state
// (docs/guide/steady-states.md), TimeRelaxation (a method's time steps) and NewtonSearch (Newton's
// method on the orbit), and what both report: the accepted state and its record, why the search
// stopped, the residual r = ‖ad*_ξ μ‖/(‖ξ‖ ‖μ‖) (SteadyStateProbe) that says when it is steady.
// The cursor common to both (state, record, rejections) is kept here, once, and saved first in a
// checkpoint; each search appends its own part (docs/reference/command-lines-and-files.md,
// "Checkpoints").
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/drivers/energy_step_control.h>
#include <ddb/integrators/drivers/steady_state_probe.h>

#include <cmath>
#include <limits>
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

/// A search for a steady state as an object (Boost.Odeint's steppers and GeometricIntegrators.jl's
/// integrators keep problem, method and cursor apart likewise): advance() takes one accepted step
/// at a time, and save()/load() carry the whole cursor so that a search resumed from a checkpoint
/// takes the uninterrupted search's steps to the bit. The derived class is the algorithm:
/// advance(), and its own part of the cursor (saveOwn/loadOwn).
template <class G>
class SteadyStateSearch {
 public:
  using Dual = typename G::template Dual<double>;

  virtual ~SteadyStateSearch() = default;
  SteadyStateSearch(const SteadyStateSearch&) = delete;
  SteadyStateSearch& operator=(const SteadyStateSearch&) = delete;

  /// The accepted state: its index, time, step, energy and residual, and the state itself.
  const RelaxState& state() const { return result_.last; }
  const Dual& current() const { return result_.final; }
  bool stopped() const { return stopped_; }
  /// What the search did so far (its stop once stopped()); runtime_s is the caller's to fill.
  const RelaxResult<G>& result() const { return result_; }

  /// Tries steps until one is accepted (true) or the search stops (false: result().stop says
  /// why). A failed step is recorded in the result; the state stays the last accepted one.
  virtual bool advance() = 0;

  /// Ends the search before its stop (a signal, a caller's own rule): result().stop is
  /// kInterrupted. A search already stopped keeps its stop.
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

  /// The cursor: the accepted state and its record, then the search's own part.
  void save(BinaryRecordWriter& out) const {
    out.tag("relaxation");
    out.put(state().k);
    out.put(state().t);
    out.put(state().h);
    out.put(state().energy);
    out.put(state().residual);
    MatrixBackend<Dual>::save(out, result_.final);
    out.put(result_.steps_rejected);
    saveOwn(out);
  }
  /// Continues from what save() wrote, with this object's method, system and options.
  void load(BinaryRecordReader& in) {
    loadCursor(in);
    loadOwn(in);
    // The probe as the uninterrupted search left it: evaluated at the accepted state.
    if (probing_) probe_.evaluate(result_.final);
    stopped_ = false;
    result_.stop = RelaxStop::kFailure;
  }

 protected:
  /// probing: whether r and dH/dt are evaluated at each accepted state (four products on
  /// matrix groups: only where a tolerance or a step rule reads them).
  SteadyStateSearch(const LiePoissonSystem<G>& system, const RelaxOptions& options, bool probing)
      : system_(system), options_(checked(options)), probing_(probing), probe_(system) {}

  /// The search's own part of the cursor, after the common one.
  virtual void saveOwn(BinaryRecordWriter& out) const = 0;
  virtual void loadOwn(BinaryRecordReader& in) = 0;

  /// The first state. A search `directed` by dH/dt needs dissipation at mu0 unless mu0 is
  /// already steady; `needs` names the option that asked for it.
  void start(const Dual& mu0, const char* needs, bool directed) {
    requireFiniteMatrix("mu0", mu0);
    result_.final = mu0;
    result_.stop = RelaxStop::kFailure;
    cursor().energy = system_.energy(mu0);
    cursor().residual = residualAt(mu0);
    if (directed && probe_.energyRate() == 0 && state().residual > options_.tolerance) {
      throwInvalid(needs, "true", "needs dissipation: dH/dt = 0 at mu0 (alpha = 0?)");
    }
  }

  /// Accepts `next` as state k + 1, reached by a step h at time t with energy H.
  void accept(Dual& next, double t, double h, double energy) {
    std::swap(result_.final, next);
    RelaxState& s = cursor();
    ++s.k;
    s.t = t;
    s.h = h;
    s.energy = energy;
    s.residual = residualAt(result_.final);
  }

  /// Records the failure of the step from the accepted state and stops.
  bool fail(std::string message) {
    result_.failure = std::move(message);
    result_.failed_step = state().k;
    return stop(RelaxStop::kFailure);
  }

  bool stop(RelaxStop why) {
    result_.stop = why;
    stopped_ = true;
    return false;
  }

  double residualAt(const Dual& mu) {
    if (!probing_) return std::numeric_limits<double>::quiet_NaN();
    probe_.evaluate(mu);
    return probe_.residual();
  }

  RelaxState& cursor() { return result_.last; }
  Dual& currentState() { return result_.final; }
  long& rejections() { return result_.steps_rejected; }
  const RelaxOptions& options() const { return options_; }
  const LiePoissonSystem<G>& system() const { return system_; }
  const SteadyStateProbe<G>& probe() const { return probe_; }
  bool probing() const { return probing_; }

 private:
  /// Reads what save() wrote before the search's own part, for a state of the current one's
  /// size (and, distributed, layout: MatrixBackend::load); throws CorruptRecord.
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

  const LiePoissonSystem<G>& system_;
  RelaxOptions options_;
  bool probing_;
  SteadyStateProbe<G> probe_;
  RelaxResult<G> result_;
  bool stopped_ = false;
};

}  // namespace ddb

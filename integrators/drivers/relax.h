// relax(), relaxByNewton() and Relaxation: take a system to a steady state
// (docs/guide/steady-states.md) by a method's time steps (TimeRelaxation) or by Newton's method on
// the orbit (NewtonSearch, RelaxOptions::newton). The run stops at the first state whose residual
// r = ‖ad*_ξ μ‖/(‖ξ‖ ‖μ‖) (SteadyStateProbe) is at most the tolerance, or at a cap on the accepted
// steps or on the time, or at a failure, and says which. The sink sees every accepted state, in
// order, as it is computed.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/drivers/newton_search.h>
#include <ddb/integrators/drivers/steady_state_search.h>
#include <ddb/integrators/drivers/time_relaxation.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <chrono>
#include <memory>

namespace ddb {

/// A search for a steady state, by time steps or by Newton's method, behind one handle: the
/// constructor chooses the search (TimeRelaxation or NewtonSearch), and every other member is
/// the interface's (SteadyStateSearch).
template <class G>
class Relaxation {
 public:
  using Dual = typename G::template Dual<double>;

  /// Integrates from mu0 with the step h0 (TimeRelaxation). Bad arguments throw InvalidArgument;
  /// calls method.reset().
  Relaxation(OneStepMethod<G>& method, const LiePoissonSystem<G>& system, const Dual& mu0,
             double h0, const RelaxOptions& options)
      : search_(std::make_unique<TimeRelaxation<G>>(method, system, mu0, h0, options)) {}

  /// A Newton search from mu0 (options.newton; NewtonSearch). Bad arguments throw
  /// InvalidArgument.
  Relaxation(const LiePoissonSystem<G>& system, const Dual& mu0, const RelaxOptions& options)
      : search_(std::make_unique<NewtonSearch<G>>(system, mu0, options)) {}

  const RelaxState& state() const { return search_->state(); }
  const Dual& current() const { return search_->current(); }
  bool stopped() const { return search_->stopped(); }
  const RelaxResult<G>& result() const { return search_->result(); }
  bool advance() { return search_->advance(); }
  void interrupt() { search_->interrupt(); }
  void setCaps(long max_steps, double t_end) { search_->setCaps(max_steps, t_end); }
  void save(BinaryRecordWriter& out) const { search_->save(out); }
  void load(BinaryRecordReader& in) { search_->load(in); }

 private:
  std::unique_ptr<SteadyStateSearch<G>> search_;
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

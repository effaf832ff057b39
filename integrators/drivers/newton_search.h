// NewtonSearch: a steady state reached by Newton's method for a critical point of H on the orbit
// (OrbitNewton; docs/guide/steady-states.md, "Newton on the orbit"): no method and no time, each
// accepted step an iteration, until r ≤ the tolerance or a cap on the iterations. A state's h is
// the length ‖x‖ of the step that reached it on the orbit, and t stays 0.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/drivers/steady_state_search.h>
#include <ddb/integrators/solvers/orbit_newton.h>

#include <cmath>
#include <optional>
#include <string>

namespace ddb {

template <class G>
class NewtonSearch final : public SteadyStateSearch<G> {
  using Base = SteadyStateSearch<G>;

 public:
  using Dual = typename Base::Dual;

  /// A Newton search from mu0 (options.newton): until r ≤ options.tolerance or
  /// options.max_steps iterations. Bad arguments throw InvalidArgument.
  NewtonSearch(const LiePoissonSystem<G>& system, const Dual& mu0, const RelaxOptions& options)
      : Base(system, options, true) {
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
    this->start(mu0, "newton", true);
    // Downhill where the flow lowers the energy, uphill where it raises it.
    newton_.emplace(system, this->probe().energyRate() < 0 ? 1.0 : -1.0);
  }

  /// One OrbitNewton iteration.
  bool advance() override {
    if (this->stopped()) return false;
    if (this->state().residual <= this->options().tolerance) {
      return this->stop(RelaxStop::kSteady);
    }
    if (this->state().k >= this->options().max_steps) return this->stop(RelaxStop::kStepCap);
    typename OrbitNewton<G>::Report report;
    next_ = this->current();
    double energy = this->state().energy;
    bool accepted = false;
    std::string why = "no step length along its direction was accepted (" +
                      std::to_string(OrbitNewton<G>::kMaxHalvings) + " halvings)";
    try {
      accepted = newton_->advance(next_, energy, report);
    } catch (const SolveFailure& failure) {
      why = failure.what();
    }
    if (!accepted) {
      return this->fail("relax: Newton step " + std::to_string(this->state().k) +
                        " from r = " + formatValue(this->state().residual) + ": " + why);
    }
    this->rejections() += report.halvings;
    this->accept(next_, this->state().t, report.length, energy);
    return true;
  }

 private:
  /// The record's slot of the time relaxation's stretch of equal steps (t_start, h, j), written
  /// as zeros (a search takes no time steps) so that both searches' records have one layout;
  /// then OrbitNewton's own state.
  void saveOwn(BinaryRecordWriter& out) const override {
    out.put(0.0);
    out.put(0.0);
    out.put(0L);
    newton_->save(out);
  }
  void loadOwn(BinaryRecordReader& in) override {
    double unused_time = 0.0;
    long unused_count = 0;
    in.get(unused_time);
    in.get(unused_time);
    in.get(unused_count);
    newton_->load(in);
  }

  std::optional<OrbitNewton<G>> newton_;  // constructed once the direction is known
  Dual next_;
};

}  // namespace ddb

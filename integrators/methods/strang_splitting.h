// StrangSplitting: a one-step method for μ̇ = X(μ) + Y(μ) from a method for the Lie–Poisson part X
// and the exact flow of the rest Y (ExactFlow: viscosity, drag): Ψ_h = φ^Y_{h/2} ∘ Φ^X_h ∘
// φ^Y_{h/2} (G. Strang, SIAM J. Numer. Anal. 5 (1968) 506–517; Hairer, Lubich, Wanner, Geometric
// Numerical Integration, II.5). Second order when Φ^X is symmetric or of order ≥ 2; the method's
// Casimirs are kept only by the X part.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/exact_flow.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <memory>
#include <string>
#include <utility>

namespace ddb {

template <class G>
class StrangSplitting final : public OneStepMethod<G> {
 public:
  using Dual = typename G::template Dual<double>;

  StrangSplitting(std::unique_ptr<OneStepMethod<G>> method, std::unique_ptr<ExactFlow<G>> flow)
      : method_(std::move(method)), flow_(std::move(flow)) {}

  /// The Lie–Poisson part's method, then the flow's name: "ddb-cay+viscosity".
  std::string name() const override { return method_->name() + "+" + flow_->name(); }
  void reset() override { method_->reset(); }
  /// The method's warm start, then the flow's state (ExactFlow::save; nothing for a viscosity, so
  /// that a damped run's record is what it was before flows had state).
  void saveWarmStart(BinaryRecordWriter& out) const override {
    method_->saveWarmStart(out);
    flow_->save(out);
  }
  void loadWarmStart(BinaryRecordReader& in, const Dual& state) override {
    method_->loadWarmStart(in, state);
    flow_->load(in);
  }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }
  void advance(Dual& mu, double t, double h) override {
    flow_->advance(mu, 0.5 * h);
    method_->advance(mu, t, h);
    flow_->advance(mu, 0.5 * h);
  }
  bool solvesEquations() const override { return method_->solvesEquations(); }
  long lastStepIterations() const override { return method_->lastStepIterations(); }

  OneStepMethod<G>& method() { return *method_; }

 private:
  std::unique_ptr<OneStepMethod<G>> method_;
  std::unique_ptr<ExactFlow<G>> flow_;
};

}  // namespace ddb

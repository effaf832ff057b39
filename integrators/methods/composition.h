// Symmetric compositions of a symmetric one-step method (Hairer, Lubich, Wanner,
// Geometric Numerical Integration, II.4): Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ_1 h}. The
// schemes are data; the wrapper works for any OneStepMethod, and since every stage
// of a DDB method is a coadjoint action, the composition stays on the orbit.
#pragma once

#include <ddb/integrators/methods/one_step_method.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ddb {

/// The step fractions γ_1..γ_s of a symmetric composition (their order is the method
/// table's, integrators/methods/method_table.h).
struct CompositionScheme {
  std::vector<double> coefficients;
};

/// Triple jump: γ₁ = γ₃ = 1/(2 − 2^{1/3}), γ₂ = 1 − 2γ₁ (order 4; HLW II.4, eq. (4.4)).
inline const CompositionScheme& tripleJump() {
  static const CompositionScheme scheme = [] {
    const double g = 1.0 / (2.0 - std::cbrt(2.0));
    return CompositionScheme{{g, 1.0 - 2.0 * g, g}};
  }();
  return scheme;
}

/// Yoshida's 7-stage symmetric composition of order 6, "solution A" (H. Yoshida,
/// Construction of higher order symplectic integrators, Phys. Lett. A 150 (1990)
/// 262–268, Table 1; HLW II.4, eq. (4.8)): w₃ w₂ w₁ w₀ w₁ w₂ w₃, w₀ = 1 − 2(w₁+w₂+w₃).
inline const CompositionScheme& yoshida6() {
  static const CompositionScheme scheme = [] {
    const double w1 = -1.17767998417887, w2 = 0.235573213359357, w3 = 0.784513610477560;
    const double w0 = 1.0 - 2.0 * (w1 + w2 + w3);
    return CompositionScheme{{w3, w2, w1, w0, w1, w2, w3}};
  }();
  return scheme;
}

template <class G>
class Composition : public OneStepMethod<G> {
 public:
  using Dual = typename G::template Dual<double>;

  Composition(std::string name, std::unique_ptr<OneStepMethod<G>> base, CompositionScheme scheme)
      : name_(std::move(name)), base_(std::move(base)), scheme_(std::move(scheme)) {}

  std::string name() const override { return name_; }
  void reset() override { base_->reset(); }
  void saveWarmStart(BinaryRecordWriter& out) const override { base_->saveWarmStart(out); }
  void loadWarmStart(BinaryRecordReader& in, const Dual& state) override {
    base_->loadWarmStart(in, state);
  }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }
  void advance(Dual& mu, double t, double h) override {
    iterations_ = 0;
    for (double gamma : scheme_.coefficients) {
      base_->advance(mu, t, gamma * h);
      iterations_ += base_->lastStepIterations();
      t += gamma * h;
    }
  }
  bool solvesEquations() const override { return base_->solvesEquations(); }
  /// The base method's iterations summed over the substeps.
  long lastStepIterations() const override { return iterations_; }

 private:
  std::string name_;
  std::unique_ptr<OneStepMethod<G>> base_;
  CompositionScheme scheme_;
  long iterations_ = 0;
};

}  // namespace ddb

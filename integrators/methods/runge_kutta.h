// Runge–Kutta methods on the continuous vector field μ̇ = ad*_{ξ+φ(ξ)} μ, driven by
// a ButcherTableau: explicit tableaus step directly, implicit ones solve the stage
// equations K_i = f(μ + h Σ_j a_ij K_j) by Levenberg–Marquardt (core/detail/tiny_solver.h, S·n
// unknowns). Neither keeps the coadjoint orbit: they are the paper's general-purpose peers.
#pragma once

#include <ddb/core/detail/tiny_solver.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/methods/butcher_tableau.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <array>
#include <memory>
#include <string>
#include <type_traits>

namespace ddb {

template <class G, int S>
class ExplicitRungeKutta : public OneStepMethod<G> {
 public:
  using Dual = typename G::template Dual<double>;

  ExplicitRungeKutta(std::shared_ptr<const LiePoissonSystem<G>> system,
                     const ButcherTableau<S>& tableau)
      : system_(std::move(system)), tableau_(tableau) {
    if (!tableau_.isExplicit()) {
      throw InvalidArgument(std::string("tableau = ") + tableau_.name + " is not explicit");
    }
  }
  std::string name() const override { return tableau_.name; }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }

  /// In place, the stages in workspaces (ExplicitStages): on the stack for a fixed-size state,
  /// where they stay in registers (kept in the object they would be stored and reloaded around
  /// every field evaluation: 7% of a heavy-top step), kept and sized once for a matrix state: no
  /// allocation once the size is known. The stages' arithmetic is the backend's
  /// (core/explicit_runge_kutta_sweep.h). A four-stage tableau's step is the system's own
  /// (LiePoissonSystem::explicitStep), which a TypedLiePoissonSystem takes with its field
  /// inlined; other tableaus evaluate the field through vectorFieldInto, the same sweep and bits.
  void advance(Dual& mu, double, double h) override {
    if constexpr (hasFixedSize<Dual>) {
      ExplicitStages<G, S> w;
      sweep(w, mu, h);
    } else {
      stages_.resize(mu);
      sweep(stages_, mu, h);
    }
  }

 private:
  EIGEN_ALWAYS_INLINE void sweep(ExplicitStages<G, S>& w, Dual& mu, double h) const {
    if constexpr (S == 4) {
      system_->explicitStep(tableau_, h, w, mu);
    } else {
      LiePoissonSystem<G>::explicitSweep(*system_, tableau_, h, w, mu);
    }
  }

  std::shared_ptr<const LiePoissonSystem<G>> system_;
  ButcherTableau<S> tableau_;
  struct NoStages {};
  std::conditional_t<hasFixedSize<Dual>, NoStages, ExplicitStages<G, S>> stages_;
};

template <class G, int S>
class ImplicitRungeKutta : public OneStepMethod<G> {
 public:
  using Dual = typename G::template Dual<double>;
  static constexpr int kDim = G::kDim;
  static constexpr int kUnknowns = S * kDim;
  using Stages = Eigen::Matrix<double, kUnknowns, 1>;

  ImplicitRungeKutta(std::shared_ptr<const LiePoissonSystem<G>> system,
                     const ButcherTableau<S>& tableau, SolverOptions options = {})
      : system_(std::move(system)), tableau_(tableau), options_(options) {}
  std::string name() const override { return tableau_.name; }
  bool solvesEquations() const override { return true; }
  /// The stage solve's Newton (Levenberg–Marquardt) iterations.
  long lastStepIterations() const override { return iterations_; }

  Dual step(const Dual& mu, double t, double h) override {
    const Dual f0 = system_->vectorField(mu);
    Stages K;
    for (int i = 0; i < S; ++i) K.template segment<kDim>(i * kDim) = f0;  // warm start
    const StageEquations equations{*system_, tableau_, mu, h};
    // Scale: the stage slopes and the state (so that equilibria, K = 0, are handled).
    iterations_ = solveTiny<kUnknowns>(equations, K, f0.norm() * std::sqrt(double(S)) + mu.norm(),
                                       options_, "Runge-Kutta stage equations", t, h)
                      .iterations;
    Dual next = mu;
    for (int i = 0; i < S; ++i) next += (h * tableau_.b[i]) * K.template segment<kDim>(i * kDim);
    return next;
  }

 private:
  // r_i = K_i - f(μ + h Σ_j a_ij K_j)
  struct StageEquations {
    const LiePoissonSystem<G>& system;
    const ButcherTableau<S>& tableau;
    const Dual& mu;
    double h;
    template <class T>
    bool operator()(const T* x, T* r) const {
      using D = typename G::template Dual<T>;
      for (int i = 0; i < S; ++i) {
        D stage = mu.template cast<T>();
        for (int j = 0; j < S; ++j) {
          stage += Eigen::Map<const D>(x + j * kDim) * T(h * tableau.a[i][j]);
        }
        Eigen::Map<D>(r + i * kDim) = Eigen::Map<const D>(x + i * kDim) - system.vectorField(stage);
      }
      return true;
    }
  };

  std::shared_ptr<const LiePoissonSystem<G>> system_;
  ButcherTableau<S> tableau_;
  SolverOptions options_;
  long iterations_ = 0;  // of the last step's stage solve
};

}  // namespace ddb

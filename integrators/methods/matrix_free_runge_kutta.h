// An implicit Runge–Kutta method on a matrix group (SO(N), SU(N)), its stage equations
//   K_i = f(μ + h Σ_j a_ij K_j),  i = 1..S,   f(μ) = P ad*_{ξ+φ}(Pμ) (LiePoissonSystem),
// solved matrix-free (docs/reference/conventions.md §2, "Runge–Kutta peers", and §4): first the
// fixed point K ← f(μ + h A K) while it contracts, then Newton–Krylov, GMRES (MatrixFreeGmres) on
// the exact Jacobian–vector products (J δ)_i = δ_i − Df(Y_i)[h Σ_j a_ij δ_j], Df from
// hessianTimes and the linearised brackets (LiePoissonSystem::vectorFieldDerivativeInto).
// The S stage slopes are a StageTuple (integrators/solvers/stage_tuple.h), so GMRES's inner
// product Re tr(XᴴY) is the sum over the stages. Written against the matrix backend
// (core/matrix_backend.h): the stages may be distributed matrices. Workspaces are sized on the
// first step of a size and reused: a step allocates nothing after that.
//
// Convergence: the fixed point's error bound ρ/(1 − ρ)·‖update‖ (ρ the measured rate) or
// Newton's residual ‖K − f(Y(K))‖, below relative_tolerance·(√S‖f(μ)‖ + ‖μ‖), the scale of
// the fixed-size ImplicitRungeKutta; otherwise a SolveFailure with the last residual.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/solver_options.h>
#include <ddb/integrators/methods/butcher_tableau.h>
#include <ddb/integrators/methods/one_step_method.h>
#include <ddb/integrators/solvers/matrix_free_gmres.h>
#include <ddb/integrators/solvers/stage_tuple.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

namespace ddb {

template <class G, int S>
class MatrixFreeImplicitRungeKutta : public OneStepMethod<G> {
  static_assert(isDynamicGroup<G>, "the matrix-free stage solver is for matrix groups");

 public:
  using Dual = typename G::template Dual<double>;
  using B = MatrixBackend<Dual>;
  using Stages = StageTuple<Dual, S>;
  using StagesBackend = MatrixBackend<Stages>;

  /// A fixed-point sweep that shrinks the update by less than this hands over to Newton.
  static constexpr double kSlowContraction = 0.5;
  static constexpr int kMaxFixedPoint = 60;
  static constexpr int kMaxNewton = 12;
  static constexpr int kMaxKrylov = 300;

  MatrixFreeImplicitRungeKutta(std::shared_ptr<const LiePoissonSystem<G>> system,
                               const ButcherTableau<S>& tableau, SolverOptions options = {})
      : system_(std::move(system)), tableau_(tableau), options_(options) {}

  std::string name() const override { return tableau_.name; }

  /// Forces Newton–Krylov from the first iterate (tests), instead of after the fixed point.
  void setNewtonOnly(bool newton_only) { newton_only_ = newton_only; }
  /// Fixed-point sweeps and Newton steps of the last step.
  int fixedPointSweeps() const { return sweeps_; }
  int newtonSteps() const { return newton_; }
  bool solvesEquations() const override { return true; }
  long lastStepIterations() const override { return sweeps_ + newton_; }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }

  void advance(Dual& mu, double t, double h) override {
    allocate(mu);
    system_->vectorFieldInto(mu, field_[0], f0_);
    for (int i = 0; i < S; ++i) B::copy(f0_, stages_[i]);  // warm start K_i = f(μ)
    const double tolerance = options_.relative_tolerance *
                             (B::frobeniusNorm(f0_) * std::sqrt(double(S)) + B::frobeniusNorm(mu));
    sweeps_ = newton_ = 0;
    double residual = newton_only_ ? INFINITY : fixedPoint(mu, h, tolerance);
    if (!(residual <= tolerance)) residual = newtonKrylov(mu, h, tolerance);
    if (!std::isfinite(residual)) {
      throw NonFiniteState("Runge-Kutta stage equations (matrix-free)", -1, t, h,
                           StagesBackend::describe(stages_), "stage slopes");
    }
    if (!(residual <= tolerance)) {
      throw SolveFailure(std::string("Runge-Kutta stage equations (matrix-free, ") +
                             (newton_ > 0 ? "Newton-Krylov" : "fixed point") + ")",
                         -1, t, h, residual, tolerance);
    }
    for (int i = 0; i < S; ++i) B::axpy(h * tableau_.b[i], stages_[i], mu);
  }

 private:
  void allocate(const Dual& like) {
    if (B::sameShape(f0_, like)) return;
    for (Dual* m : {&f0_, &stage_, &slope_}) B::zeroLike(*m, like);
    for (Stages* m : {&stages_, &next_, &residual_, &delta_}) {
      for (int i = 0; i < S; ++i) B::zeroLike((*m)[i], like);
    }
    for (auto& w : field_) w.resize(like);
  }

  // stage_ = Σ_j h a_ij v_j, added to stage_'s value.
  void addCombination(const Stages& v, int i, double h) {
    for (int j = 0; j < S; ++j) {
      if (tableau_.a[i][j] != 0.0) B::axpy(h * tableau_.a[i][j], v[j], stage_);
    }
  }

  // next_ = f(Y(stages_)) stage by stage, Y_i = μ + h Σ_j a_ij K_j; each stage's workspace
  // keeps its Y_i for Df(Y_i).
  void evaluate(const Dual& mu, double h) {
    for (int i = 0; i < S; ++i) {
      B::copy(mu, stage_);
      addCombination(stages_, i, h);
      system_->vectorFieldInto(stage_, field_[i], next_[i]);
    }
  }

  // K ← f(Y(K)) while the sweeps contract. A contraction of rate ρ leaves the new iterate
  // an error of at most ρ/(1 − ρ)·‖update‖; ρ is the ratio of the last two updates.
  // Returns that bound once it meets the tolerance, else INFINITY (Newton takes over).
  double fixedPoint(const Dual& mu, double h, double tolerance) {
    double previous = INFINITY;
    for (int k = 0; k < kMaxFixedPoint; ++k) {
      evaluate(mu, h);
      ++sweeps_;
      const double update = StagesBackend::frobeniusDistance(next_, stages_);
      if (!std::isfinite(update)) return INFINITY;
      stages_.swap(next_);
      if (update == 0.0) return 0.0;
      if (std::isfinite(previous)) {
        const double rate = update / previous;
        const double error = rate / (1.0 - rate) * update;
        if (rate < kSlowContraction && error <= tolerance) return error;
        if (k >= 2 && !(rate < kSlowContraction)) return INFINITY;
      }
      previous = update;
    }
    return INFINITY;
  }

  // Newton on r(K) = K − f(Y(K)) with GMRES on J δ = −r. Returns the last ‖r‖.
  double newtonKrylov(const Dual& mu, double h, double tolerance) {
    gmres_.resize(stages_);  // its basis only when Newton–Krylov is needed
    double residual = INFINITY;
    for (int k = 0; k <= kMaxNewton; ++k) {
      evaluate(mu, h);
      StagesBackend::sum(1.0, stages_, -1.0, next_, residual_);
      residual = StagesBackend::frobeniusNorm(residual_);
      if (!std::isfinite(residual) || residual <= tolerance || k == kMaxNewton) return residual;
      ++newton_;
      StagesBackend::scale(-1.0, residual_, residual_);
      StagesBackend::setZero(delta_);
      const auto apply = [&](const Stages& v, Stages& out) {
        // (J v)_i = v_i − Df(Y_i)[h Σ_j a_ij v_j]
        for (int i = 0; i < S; ++i) {
          B::setZero(stage_);
          addCombination(v, i, h);
          system_->vectorFieldDerivativeInto(stage_, field_[i], slope_);
          B::sum(1.0, v[i], -1.0, slope_, out[i]);
        }
      };
      // Inexact Newton: GMRES to 1e-4 of the current residual (never below a tenth of
      // the final tolerance), as in the Legendre solver's Newton–Krylov.
      const double forcing = std::max(0.1 * tolerance, 1e-4 * residual);
      gmres_.solve(apply, residual_, delta_, forcing, kMaxKrylov);
      StagesBackend::axpy(1.0, delta_, stages_);
    }
    return residual;
  }

  std::shared_ptr<const LiePoissonSystem<G>> system_;
  ButcherTableau<S> tableau_;
  SolverOptions options_;
  bool newton_only_ = false;
  int sweeps_ = 0, newton_ = 0;
  Dual f0_, stage_, slope_;
  Stages stages_, next_, residual_, delta_;
  std::array<MatrixFieldWorkspace<G>, S> field_;
  MatrixFreeGmres<Stages> gmres_;
};

}  // namespace ddb

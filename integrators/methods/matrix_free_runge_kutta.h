// An implicit Runge–Kutta method on a matrix group (SO(N), SU(N)), its stage equations
//   K_i = f(μ + h Σ_j a_ij K_j),  i = 1..S,   f(μ) = P ad*_{ξ+φ}(Pμ) (LiePoissonSystem),
// solved matrix-free (docs/reference/conventions.md §2, "Runge–Kutta peers", and §4): first the
// fixed point K ← f(μ + h A K) while it contracts, then Newton–Krylov, GMRES (MatrixFreeGmres) on
// the exact Jacobian–vector products (J δ)_i = δ_i − Df(Y_i)[h Σ_j a_ij δ_j], Df from
// hessianTimes and the linearised brackets (LiePoissonSystem::vectorFieldDerivativeInto).
// The S stages are the N × N blocks of one N × SN matrix, so GMRES's inner product
// Re tr(XᴴY) is the sum over the stages. Workspaces are sized on the first step of a size
// and reused: a step allocates nothing after that.
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
    allocate(mu.rows());
    const Eigen::Index n = mu.rows();
    system_->vectorFieldInto(mu, field_[0], f0_);
    for (int i = 0; i < S; ++i) stages_.middleCols(i * n, n) = f0_;  // warm start K_i = f(μ)
    const double tolerance =
        options_.relative_tolerance * (f0_.norm() * std::sqrt(double(S)) + mu.norm());
    sweeps_ = newton_ = 0;
    double residual = newton_only_ ? INFINITY : fixedPoint(mu, h, tolerance);
    if (!(residual <= tolerance)) residual = newtonKrylov(mu, h, tolerance);
    if (!std::isfinite(residual)) {
      throw NonFiniteState("Runge-Kutta stage equations (matrix-free)", -1, t, h, stages_,
                           "stage slopes");
    }
    if (!(residual <= tolerance)) {
      throw SolveFailure(std::string("Runge-Kutta stage equations (matrix-free, ") +
                             (newton_ > 0 ? "Newton-Krylov" : "fixed point") + ")",
                         -1, t, h, residual, tolerance);
    }
    for (int i = 0; i < S; ++i) mu += (h * tableau_.b[i]) * stages_.middleCols(i * n, n);
  }

 private:
  void allocate(Eigen::Index n) {
    if (f0_.rows() == n) return;
    f0_.setZero(n, n);
    stage_.setZero(n, n);
    slope_.setZero(n, n);
    for (Dual* m : {&stages_, &next_, &residual_, &delta_}) m->setZero(n, S * n);
    for (auto& w : field_) w.resize(f0_);
  }

  // Y_i = μ + h Σ_j a_ij K_j from the blocks of `slopes`, into stage_.
  void stageValue(const Dual& mu, const Dual& slopes, int i, double h) {
    const Eigen::Index n = mu.rows();
    stage_ = mu;
    for (int j = 0; j < S; ++j) {
      if (tableau_.a[i][j] != 0.0) stage_ += (h * tableau_.a[i][j]) * slopes.middleCols(j * n, n);
    }
  }

  // next_ = f(Y(stages_)) block by block; each stage's workspace keeps its Y_i for Df(Y_i).
  void evaluate(const Dual& mu, double h) {
    const Eigen::Index n = mu.rows();
    for (int i = 0; i < S; ++i) {
      stageValue(mu, stages_, i, h);
      system_->vectorFieldInto(stage_, field_[i], slope_);
      next_.middleCols(i * n, n) = slope_;
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
      const double update = (next_ - stages_).norm();
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
    const Eigen::Index n = mu.rows();
    gmres_.resize(stages_);  // its basis only when Newton–Krylov is needed
    double residual = INFINITY;
    for (int k = 0; k <= kMaxNewton; ++k) {
      evaluate(mu, h);
      residual_ = stages_ - next_;
      residual = residual_.norm();
      if (!std::isfinite(residual) || residual <= tolerance || k == kMaxNewton) return residual;
      ++newton_;
      residual_ = -residual_;
      delta_.setZero();
      const auto apply = [&](const Dual& v, Dual& out) {
        // (J v)_i = v_i − Df(Y_i)[h Σ_j a_ij v_j]
        for (int i = 0; i < S; ++i) {
          stage_.setZero();
          for (int j = 0; j < S; ++j) {
            if (tableau_.a[i][j] != 0.0) stage_ += (h * tableau_.a[i][j]) * v.middleCols(j * n, n);
          }
          system_->vectorFieldDerivativeInto(stage_, field_[i], slope_);
          out.middleCols(i * n, n) = v.middleCols(i * n, n) - slope_;
        }
      };
      // Inexact Newton: GMRES to 1e-4 of the current residual (never below a tenth of the
      // final tolerance), as in the Legendre solver's Newton–Krylov.
      const double forcing = std::max(0.1 * tolerance, 1e-4 * residual);
      gmres_.solve(apply, residual_, delta_, forcing, kMaxKrylov);
      stages_ += delta_;
    }
    return residual;
  }

  std::shared_ptr<const LiePoissonSystem<G>> system_;
  ButcherTableau<S> tableau_;
  SolverOptions options_;
  bool newton_only_ = false;
  int sweeps_ = 0, newton_ = 0;
  Dual f0_, stage_, slope_;
  Dual stages_, next_, residual_, delta_;  // N × SN: the S stage slopes side by side
  std::array<MatrixFieldWorkspace<G>, S> field_;
  MatrixFreeGmres<Dual> gmres_;
};

}  // namespace ddb

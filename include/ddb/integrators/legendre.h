// The solver of the discrete Legendre transform of a DDB step for small fixed-size groups
// (paper, Section 4.1):
//   (dτ^{-1}_{hξ})* p = target(ξ, p),  p = ∂l/∂ξ(ξ)  (Lagrangian form, unknown ξ)
//                                      ξ = ∂H/∂μ(p)  (Hamiltonian form, unknown p)
// DDB's target is the momentum M_k; the symmetric variants' targets depend on the unknown.
// Two stages (docs/conventions.md §4):
//   predictor: p = near + c, the correction c = p − near extrapolated from the last solves at
//     the same h (quadratically once there are three: 2.8 → 2.0 sweeps per step on Scenario A,
//     1.02 → 1.00 Newton iterations on the heavy top, docs/design.md), then up to kMaxSweeps
//     fixed-point sweeps p ← p − r(p); they stop as soon as one contracts by less than ½ (the
//     step is then too large for them);
//   corrector: ceres::TinySolver on LegendreEquation's analytic Jacobian, to the relative
//     tolerance: first with the Jacobian of the predicted guess kept (runChordIterations: one
//     Jacobian per solve), then, if that has not converged within kChordIterations, with a
//     fresh Jacobian per iterate; the typed SolveFailure when the tolerance is not reached.
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/tiny_solver.h>
#include <ddb/integrators/injectivity_guard.h>
#include <ddb/integrators/legendre_equation.h>
#include <ddb/integrators/legendre_stats.h>

#include <Eigen/Core>
#include <cmath>

namespace ddb {

template <class R>
class DiscreteLegendreSolver {
 public:
  using G = typename R::Group;
  static constexpr int kDim = G::kDim;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;
  using Vector = Eigen::Matrix<double, kDim, 1>;
  /// Sweeps of the predictor at most: each gains a factor ~h‖ad_ξ‖; three bring a warm
  /// start within one Newton step of the tolerance on the paper's scenarios (docs/design.md).
  static constexpr int kMaxSweeps = 3;
  /// Iterations with the Jacobian of the predicted guess before fresh Jacobians take over.
  static constexpr int kChordIterations = 3;

  DiscreteLegendreSolver(const LiePoissonSystem<G>& system, const R& retraction, LegendreForm form,
                         SolverOptions options)
      : system_(system), retraction_(retraction), form_(form), options_(options) {
    if (form_ == LegendreForm::kLagrangian && system_.lagrangian() == nullptr) {
      throw InvalidArgument("form = lagrangian is invalid: system '" + system_.name() +
                            "' has no Lagrangian (use the Hamiltonian form)");
    }
  }

  /// Forgets the corrections of earlier solves (a new trajectory).
  void reset() { history_ = 0; }
  LegendreForm form() const { return form_; }
  /// Sweeps, Newton iterations and final residual of the last solve.
  const LegendreStats& stats() const { return stats_; }

  /// Solves (dτ^{-1}_{hξ})* p = target(ξ, p); returns ξ and sets p. `near` is a momentum
  /// close to the solution (the target at the start of the step), whose norm scales the
  /// relative tolerance.
  template <class Target>
  Algebra solve(const Target& target, const Dual& near, double t, double h, Dual& p) {
    InjectivityGuard<R>::beforeSolve(system_, near, t, h);
    const LegendreEquation<R, Target> equation{system_, retraction_, target, h, form_};
    if (h != h_) history_ = 0;  // corrections scale with h: only same-h ones extrapolate
    h_ = h;
    Dual guess = near;
    if (history_ == 1) guess += correction_;
    if (history_ == 2) guess += 2.0 * correction_ - previous_correction_;
    if (history_ == 3) guess += 3.0 * (correction_ - previous_correction_) + oldest_correction_;
    stats_ = LegendreStats{};
    stats_.fixed_point = sweep(equation, near.norm(), guess);
    unknown_ = form_ == LegendreForm::kLagrangian ? Vector(system_.velocity(guess)) : guess;
    const double scale = near.norm();
    TinySolveStats solved = runChordIterations(
        equation, unknown_, options_.relative_tolerance * scale, kChordIterations);
    stats_.newton = solved.iterations;
    if (!solved.converged) {  // from where the chord iterations left it, with fresh Jacobians
      solved =
          solveTinyWith(equation, unknown_, scale, options_, "discrete Legendre equation", t, h);
      stats_.newton += solved.iterations;
    }
    stats_.residual = solved.residual;
    Algebra xi;
    equation.unpack(unknown_.data(), xi, p);
    InjectivityGuard<R>::afterSolve(system_, near, xi, t, h);
    oldest_correction_ = previous_correction_;
    previous_correction_ = correction_;
    correction_ = p - near;
    history_ = history_ < 3 ? history_ + 1 : 3;
    return xi;
  }

  /// DDB's equation M = (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ).
  Algebra solve(const Dual& momentum, double t, double h, Dual& p) {
    return solve(FixedMomentum<G>{momentum}, momentum, t, h, p);
  }

 private:
  // Fixed-point sweeps p ← p − r(p) from `p`; returns how many were kept. A sweep whose
  // update is more than half the previous one ends them; one that even grew is not applied.
  template <class Equation>
  int sweep(const Equation& equation, double scale, Dual& p) const {
    // Within √tolerance one (chord) Newton iteration squares the error to the tolerance.
    const double close_enough = std::sqrt(options_.relative_tolerance) * scale;
    double last = INFINITY;
    for (int k = 0; k < kMaxSweeps; ++k) {
      const Dual update = equation.residualAtMomentum(p);
      const double size = update.norm();
      if (!(size <= last)) return k;  // diverging (or non-finite): keep p as it is
      p -= update;
      if (size <= close_enough || size > 0.5 * last) return k + 1;
      last = size;
    }
    return kMaxSweeps;
  }

  const LiePoissonSystem<G>& system_;
  const R& retraction_;
  LegendreForm form_;
  SolverOptions options_;
  LegendreStats stats_;
  int history_ = 0;  // corrections remembered (0 to 3)
  double h_ = 0.0;
  Dual correction_ = Dual::Zero(), previous_correction_ = Dual::Zero(),
       oldest_correction_ = Dual::Zero();
  Vector unknown_ = Vector::Zero();
};

}  // namespace ddb

// The discrete Legendre equation of a DDB Cayley step on a matrix group (SO(N), SU(N)),
// Hamiltonian form, solved matrix-free (docs/conventions.md §2 and §4):
//   target = (I + a) p (I − a),  a = h ξ(p)/2,  ξ = ∂H/∂μ(p),
// for p in u(N) (so(N)), not projected to su(N). First the fixed point
//   p ← target − [a, p] + a p a                                  (two products)
// from a predictor; when it contracts too slowly (h‖ξ‖ near 1), Newton–Krylov: GMRES
// on the exact Jacobian–vector products (four products each). Workspaces are allocated
// on the first solve of a size and reused: no iteration allocates.
//
// Convergence: the fixed-point update (equal to the residual r(p)) or the Newton
// residual below relative_tolerance·‖target‖; otherwise a SolveFailure with the last
// residual, and the caller keeps every state before it.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_free_gmres.h>
#include <ddb/core/tiny_solver.h>
#include <ddb/groups/cayley.h>
#include <ddb/integrators/legendre.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace ddb {

/// Iteration counts of the last solve.
struct MatrixLegendreStats {
  int fixed_point = 0;  // fixed-point sweeps
  int newton = 0;       // Newton steps
  int krylov = 0;       // Jacobian–vector products inside GMRES
  double residual = 0;  // final ‖r‖
};

template <class R>
class MatrixLegendreSolver {
 public:
  using G = typename R::Group;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;
  static_assert(isDynamicGroup<G>, "MatrixLegendreSolver is the solver of matrix groups");

  /// A fixed-point sweep that shrinks the update by less than this hands over to Newton.
  static constexpr double kSlowContraction = 0.5;
  static constexpr int kMaxFixedPoint = 60;
  static constexpr int kMaxNewton = 12;
  static constexpr int kMaxKrylov = 200;

  MatrixLegendreSolver(const LiePoissonSystem<G>& system, const R&, LegendreForm form,
                       SolverOptions options)
      : system_(system), form_(form), options_(options) {
    static_assert(std::is_same_v<R, Cayley<G>>,
                  "the matrix-free Legendre solver implements the Cayley retraction");
    if (form_ != LegendreForm::kHamiltonian) {
      throw InvalidArgument(
          "form = lagrangian is invalid: matrix groups use the Hamiltonian form (unknown p)");
    }
  }

  void reset() { has_guess_ = false; }
  LegendreForm form() const { return form_; }
  const MatrixLegendreStats& stats() const { return stats_; }

  /// Solves (I + hξ(p)/2) p (I − hξ(p)/2) = target(ξ, p); returns ξ and sets p.
  template <class Target>
  Algebra solve(const Target& target, const Dual& near, double t, double h, Dual& p) {
    constexpr bool kFixed = std::is_same_v<Target, FixedMomentum<G>>;
    allocate(near);
    stats_ = MatrixLegendreStats{};
    const auto targetValue = [&]() -> const Dual& {
      if constexpr (kFixed) {
        return target.momentum;
      } else {
        target_ = target(xi_, p_);
        return target_;
      }
    };
    // Predictor: the correction p − target of the previous step, carried over
    // (p − target = O(h) and varies by O(h) per step, so the guess is O(h²) off).
    if (has_guess_) {
      p_ = near + correction_;
    } else {
      p_ = near;
    }
    const double scale = near.norm();
    const double tolerance = options_.relative_tolerance * scale;
    double previous = INFINITY;
    bool converged = false, slow = false;
    for (int k = 0; k < kMaxFixedPoint; ++k) {
      updateVelocity(h);
      const Dual& W = targetValue();
      G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
      const double update = (next_ - p_).norm();
      p_.swap(next_);
      ++stats_.fixed_point;
      stats_.residual = update;
      if (!std::isfinite(update)) break;
      if (update <= tolerance) {
        converged = true;
        break;
      }
      if (k >= 2 && update > kSlowContraction * previous) {
        slow = true;
        break;
      }
      previous = update;
    }
    if (!converged && slow && kFixed) converged = newtonKrylov(targetValue(), h, tolerance);
    if (!converged) {
      throw SolveFailure(std::string("discrete Legendre equation (matrix-free, ") +
                             (stats_.newton > 0 ? "Newton-Krylov" : "fixed point") + ")",
                         -1, t, h, stats_.residual, tolerance);
    }
    updateVelocity(h);
    p = p_;
    correction_ = p_ - near;
    has_guess_ = true;
    return xi_;
  }

  /// DDB's equation: target = the momentum M_k.
  Algebra solve(const Dual& momentum, double t, double h, Dual& p) {
    return solve(FixedMomentum<G>{momentum}, momentum, t, h, p);
  }

 private:
  void allocate(const Dual& like) {
    if (p_.rows() == like.rows() && p_.cols() == like.cols()) return;
    for (Dual* m : {&p_, &next_, &xi_, &a_, &ap_, &apa_, &residual_, &delta_, &delta_a_, &t1_, &t2_,
                    &correction_, &target_}) {
      m->setZero(like.rows(), like.cols());
    }
    gmres_.resize(like.rows(), like.cols());
    has_guess_ = false;
  }

  // ξ = ∂H/∂μ(p), a = hξ/2.
  void updateVelocity(double h) {
    system_.hamiltonian().gradientInto(p_, xi_);
    a_ = (0.5 * h) * xi_;
  }

  // Newton on r(p) = (I + a)p(I − a) − W with GMRES on J δ = −r.
  bool newtonKrylov(const Dual& W, double h, double tolerance) {
    for (int k = 0; k < kMaxNewton; ++k) {
      updateVelocity(h);
      G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
      residual_ = p_ - next_;  // r(p)
      stats_.residual = residual_.norm();
      if (!std::isfinite(stats_.residual)) return false;
      if (stats_.residual <= tolerance) return true;
      ++stats_.newton;
      residual_ = -residual_;
      delta_.setZero();
      const auto jacobian = [&](const Dual& v, Dual& out) {
        system_.hamiltonian().hessianTimesInto(p_, v, delta_a_);
        delta_a_ *= 0.5 * h;
        G::cayleyLinearised(a_, p_, v, delta_a_, t1_, t2_, out);
      };
      // Inexact Newton: GMRES to 1e-4 of the current residual (never below a tenth of
      // the final tolerance), which keeps the outer convergence quadratic in practice.
      const double forcing = std::max(0.1 * tolerance, 1e-4 * stats_.residual);
      const auto krylov = gmres_.solve(jacobian, residual_, delta_, forcing, kMaxKrylov);
      stats_.krylov += krylov.iterations;
      p_ += delta_;
    }
    updateVelocity(h);
    G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
    stats_.residual = (p_ - next_).norm();
    return stats_.residual <= tolerance;
  }

  const LiePoissonSystem<G>& system_;
  LegendreForm form_;
  SolverOptions options_;
  bool has_guess_ = false;
  MatrixLegendreStats stats_;
  Dual p_, next_, xi_, a_, ap_, apa_, residual_, delta_, delta_a_, t1_, t2_, correction_, target_;
  MatrixFreeGmres<Dual> gmres_;
};

}  // namespace ddb

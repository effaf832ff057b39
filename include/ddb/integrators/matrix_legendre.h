// The discrete Legendre equation of a DDB Cayley step on a matrix group (SO(N), SU(N)),
// Hamiltonian form, solved matrix-free (docs/conventions.md §2 and §4):
//   target = (I + a) p (I − a),  a = h ξ(p)/2,  ξ = ∂H/∂μ(p),
// for p in u(N) (so(N)), not projected to su(N). First the fixed point
//   p ← target − [a, p] + a p a                                  (two products)
// from a predictor; when it contracts too slowly (h‖ξ‖ near 1), Newton–Krylov: GMRES
// on the exact Jacobian–vector products (four products each). Workspaces are allocated
// on the first solve of a size and reused: no iteration allocates.
//
// Ceres (ceres::Problem, dense QR, the Jacobian assembled from the same exact
// Jacobian–vector products, one per coordinate) solves the same equation in real
// coordinates of u(N) when asked, for small N only (at most kMaxCeresDimension unknowns):
// an independent check of the matrix-free iterations.
//
// Convergence: the error bound of the accepted fixed-point iterate, ρ/(1 − ρ) times the
// last update (the update equals the residual r(p)), with ρ the measured rate, or the
// Newton residual, below relative_tolerance·‖target‖; otherwise a SolveFailure with the last
// residual, and the caller keeps every state before it.
#pragma once

#include <ceres/ceres.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_free_gmres.h>
#include <ddb/core/tiny_solver.h>
#include <ddb/groups/cayley.h>
#include <ddb/integrators/legendre_equation.h>
#include <ddb/integrators/legendre_stats.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace ddb {

/// How the matrix-free solver proceeds: kAuto is the fixed point with Newton–Krylov as
/// the fallback; the others force one path (for tests and comparisons).
enum class MatrixLegendreStrategy { kAuto, kFixedPoint, kNewtonKrylov, kCeres };

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
  static constexpr int kMaxForcedFixedPoint = 2000;
  static constexpr Eigen::Index kMaxCeresDimension = 64;

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

  void reset() { guesses_ = 0; }
  LegendreForm form() const { return form_; }
  const LegendreStats& stats() const { return stats_; }
  void setStrategy(MatrixLegendreStrategy strategy) { strategy_ = strategy; }

  /// Solves (I + hξ(p)/2) p (I − hξ(p)/2) = target(ξ, p); returns ξ and sets p.
  template <class Target>
  Algebra solve(const Target& target, const Dual& near, double t, double h, Dual& p) {
    solveInPlace(target, near, t, h);
    p = p_;
    return xi_;
  }

  /// DDB's equation: target = the momentum M_k.
  Algebra solve(const Dual& momentum, double t, double h, Dual& p) {
    return solve(FixedMomentum<G>{momentum}, momentum, t, h, p);
  }

  /// Solves without copying out: the solution is solution(), ξ = velocity() and
  /// a = hξ/2 = halfStep(), valid until the next solve.
  template <class Target>
  void solveInPlace(const Target& target, const Dual& near, double t, double h) {
    constexpr bool kFixed = std::is_same_v<Target, FixedMomentum<G>>;
    allocate(near);
    stats_ = LegendreStats{};
    const auto targetValue = [&]() -> const Dual& {
      if constexpr (kFixed) {
        return target.momentum;
      } else {
        target_ = target(xi_, p_);
        return target_;
      }
    };
    // Predictor: the correction c = p − target varies smoothly along the trajectory
    // (c = O(h)); it is extrapolated linearly from the last two steps, 2c_{k−1} − c_{k−2}
    // (constant after the first step), so the guess is O(h²) closer than c_{k−1}.
    if (guesses_ >= 2) {
      p_ = near + 2.0 * correction_ - previous_correction_;
    } else if (guesses_ == 1) {
      p_ = near + correction_;
    } else {
      p_ = near;
    }
    const double scale = near.norm();
    const double tolerance = options_.relative_tolerance * scale;
    double previous = INFINITY;
    bool converged = false;
    const bool forced = strategy_ == MatrixLegendreStrategy::kFixedPoint;
    const bool fixed_point = strategy_ == MatrixLegendreStrategy::kAuto || forced;
    const int budget = (forced || !kFixed) ? kMaxForcedFixedPoint : kMaxFixedPoint;
    for (int k = 0; fixed_point && k < budget; ++k) {
      updateVelocity(h);
      const Dual& W = targetValue();
      G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
      const double update = (next_ - p_).norm();
      p_.swap(next_);
      ++stats_.fixed_point;
      if (!std::isfinite(update)) {
        stats_.residual = update;
        break;
      }
      // The accepted iterate is p_new: for a contraction of rate ρ its error is at most
      // ρ/(1 − ρ)·update, with ρ measured from the last two updates (the first sweep has
      // no estimate and is judged by its update).
      const double rate = std::isfinite(previous) ? update / previous : 1.0;
      const double error = rate < 0.5 ? update * rate / (1.0 - rate) : update;
      stats_.residual = error;
      if (error <= tolerance) {
        converged = true;
        break;
      }
      // Only a fixed target has the Newton–Krylov fallback; other targets iterate on.
      if (kFixed && !forced && k >= 2 && update > kSlowContraction * previous) {
        break;  // contracting too slowly: Newton–Krylov takes over
      }
      previous = update;
    }
    if constexpr (kFixed) {
      if (strategy_ == MatrixLegendreStrategy::kNewtonKrylov ||
          (strategy_ == MatrixLegendreStrategy::kAuto && !converged)) {
        converged = newtonKrylov(target.momentum, h, tolerance);
      }
      if (strategy_ == MatrixLegendreStrategy::kCeres) {
        converged = ceresSolve(target.momentum, h, tolerance);
      }
    } else if (strategy_ != MatrixLegendreStrategy::kAuto && !forced) {
      throw InvalidArgument(
          "strategy is invalid: only the fixed point solves a target that depends on p");
    }
    if (!converged && !std::isfinite(stats_.residual)) {
      // Overflow (e.g. |α| or h near the double range) is not a missed tolerance.
      throw NonFiniteState("discrete Legendre equation (matrix-free)", -1, t, h, p_, "iterate");
    }
    if (!converged) {
      throw SolveFailure(std::string("discrete Legendre equation (matrix-free, ") +
                             (stats_.newton > 0 ? "Newton" : "fixed point") + ")",
                         -1, t, h, stats_.residual, tolerance);
    }
    updateVelocity(h);
    previous_correction_.swap(correction_);
    correction_ = p_ - near;
    ++guesses_;
  }

  const Dual& solution() const { return p_; }
  const Algebra& velocity() const { return xi_; }
  const Algebra& halfStep() const { return a_; }

 private:
  void allocate(const Dual& like) {
    if (p_.rows() == like.rows() && p_.cols() == like.cols()) return;
    for (Dual* m : {&p_, &next_, &xi_, &a_, &ap_, &apa_, &residual_, &delta_, &delta_a_, &t1_, &t2_,
                    &correction_, &previous_correction_, &target_}) {
      m->setZero(like.rows(), like.cols());
    }
    gmres_.resize(like.rows(), like.cols());
    guesses_ = 0;
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

  // Real coordinates of u(N) (so(N)): the imaginary diagonal and the upper triangle.
  static constexpr bool kComplex = Eigen::NumTraits<typename Dual::Scalar>::IsComplex;
  static Eigen::Index coordinateCount(Eigen::Index n) { return kComplex ? n * n : n * (n - 1) / 2; }
  static void toCoordinates(const Dual& x, double* v) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      for (Eigen::Index i = 0; i <= j; ++i) {
        if constexpr (kComplex) {
          if (i == j) {
            *v++ = x(i, i).imag();
          } else {
            *v++ = x(i, j).real();
            *v++ = x(i, j).imag();
          }
        } else if (i < j) {
          *v++ = x(i, j);
        }
      }
    }
  }
  static void fromCoordinates(const double* v, Dual& x) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      for (Eigen::Index i = 0; i <= j; ++i) {
        if constexpr (kComplex) {
          if (i == j) {
            x(i, i) = typename Dual::Scalar(0.0, *v++);
          } else {
            const double re = *v++;
            x(i, j) = typename Dual::Scalar(re, *v++);
            x(j, i) = -std::conj(x(i, j));
          }
        } else if (i < j) {
          x(i, j) = *v++;
          x(j, i) = -x(i, j);
        } else {
          x(i, i) = 0.0;
        }
      }
    }
  }

  // r(p) = (I + a)p(I − a) − W in coordinates, with the Jacobian column by column.
  class CeresResidual : public ceres::CostFunction {
   public:
    CeresResidual(MatrixLegendreSolver& solver, const Dual& W, double h, int n)
        : solver_(solver), W_(W), h_(h) {
      set_num_residuals(n);
      mutable_parameter_block_sizes()->push_back(n);
    }
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
      MatrixLegendreSolver& s = solver_;
      const int n = num_residuals();
      fromCoordinates(parameters[0], s.p_);
      s.updateVelocity(h_);
      G::cayleyFixedPoint(W_, s.a_, s.p_, s.ap_, s.apa_, s.next_);
      s.residual_ = s.p_ - s.next_;
      toCoordinates(s.residual_, residuals);
      if (jacobians != nullptr && jacobians[0] != nullptr) {
        std::vector<double> unit(static_cast<std::size_t>(n), 0.0), column(unit);
        for (int k = 0; k < n; ++k) {
          unit[static_cast<std::size_t>(k)] = 1.0;
          fromCoordinates(unit.data(), s.delta_);
          unit[static_cast<std::size_t>(k)] = 0.0;
          s.system_.hamiltonian().hessianTimesInto(s.p_, s.delta_, s.delta_a_);
          s.delta_a_ *= 0.5 * h_;
          G::cayleyLinearised(s.a_, s.p_, s.delta_, s.delta_a_, s.t1_, s.t2_, s.next_);
          toCoordinates(s.next_, column.data());
          for (int i = 0; i < n; ++i) jacobians[0][i * n + k] = column[static_cast<std::size_t>(i)];
        }
      }
      return true;
    }

   private:
    MatrixLegendreSolver& solver_;
    const Dual& W_;
    double h_;
  };

  bool ceresSolve(const Dual& W, double h, double tolerance) {
    const Eigen::Index n = coordinateCount(W.rows());
    if (n > kMaxCeresDimension) {
      throwInvalid("strategy", "ceres",
                   "solves at most " + std::to_string(kMaxCeresDimension) + " unknowns, not " +
                       std::to_string(n));
    }
    std::vector<double> x(static_cast<std::size_t>(n));
    toCoordinates(p_, x.data());
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    CeresResidual residual(*this, W, h, static_cast<int>(n));
    problem.AddResidualBlock(&residual, nullptr, x.data());
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = 50;
    options.function_tolerance = 0.0;
    options.gradient_tolerance = 0.0;
    options.parameter_tolerance = 1e-16;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    stats_.newton += static_cast<int>(summary.iterations.size());
    fromCoordinates(x.data(), p_);
    updateVelocity(h);
    G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
    stats_.residual = (p_ - next_).norm();
    return stats_.residual <= tolerance;
  }

  const LiePoissonSystem<G>& system_;
  LegendreForm form_;
  SolverOptions options_;
  int guesses_ = 0;  // previous solutions the predictor may use
  MatrixLegendreStrategy strategy_ = MatrixLegendreStrategy::kAuto;
  LegendreStats stats_;
  Dual p_, next_, xi_, a_, ap_, apa_, residual_, delta_, delta_a_, t1_, t2_, correction_,
      previous_correction_, target_;
  MatrixFreeGmres<Dual> gmres_;
};

}  // namespace ddb

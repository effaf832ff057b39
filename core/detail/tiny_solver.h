// Solves the small fixed-size implicit equations r(x) = 0 (docs/reference/conventions.md §4) by
// Levenberg–Marquardt on the normal equations, the Jacobian either supplied by the equation
// (analytic) or from Jet autodiff (the one use of Ceres here: its Jet). Convergence is decided on
// the final residual:
//   ‖r(x)‖ <= relative_tolerance · scale,
// scale being the size of the equation's data (e.g. ‖M_k‖). Failure throws SolveFailure.
#pragma once

#include <ceres/jet.h>
#include <ddb/core/errors.h>
#include <ddb/core/solver_options.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>

namespace ddb {

/// What one solve took: Newton (Levenberg–Marquardt) iterations, the final ‖r‖, and
/// whether ‖r‖ met the relative tolerance.
struct TinySolveStats {
  int iterations = 0;
  double residual = 0.0;
  bool converged = false;
};

/// The linear solvers of the normal equations JᵀJ δ = Jᵀr (SPD). Their rounding only
/// slows Newton's convergence, not what it converges to: the residual is always the true one.
/// For n ≤ 4 the inverse by Eigen's closed form (cofactors, no pivoting loop: the 3 × 3 of SO(3)
/// costs a few dozen flops).
template <int N>
struct SmallInverseSolver {
  Eigen::Matrix<double, N, N> inverse;
  template <class Matrix>
  void compute(const Matrix& a) {
    inverse = a.inverse();
  }
  template <class Vector>
  Eigen::Matrix<double, N, 1> solve(const Vector& b) const {
    return inverse * b;
  }
};
/// For even n ≤ 8 (the 6 × 6 of SE(3)), block elimination on a = [[A, B], [Bᵀ, C]] with the
/// closed-form inverses of A and of the Schur complement S = C − Bᵀ A⁻¹ B (both SPD as a is):
/// two divisions and independent multiply-adds. A Cholesky factorisation chains six square
/// roots and divisions with its substitutions, and Eigen's LLT is out of line at run-time
/// block sizes; both cost a heavy-top DDB step more (docs/design/architecture.md, "Small Legendre
/// solves").
template <int N>
struct SchurComplementSolver {
  static constexpr int kHalf = N / 2;
  static_assert(N % 2 == 0 && kHalf <= 4, "halves with Eigen's closed-form inverse");
  using Half = Eigen::Matrix<double, kHalf, kHalf>;
  using HalfVector = Eigen::Matrix<double, kHalf, 1>;
  Half a_inverse, a_inverse_b, s_inverse;
  template <class Matrix>
  void compute(const Matrix& a) {
    a_inverse = a.template topLeftCorner<kHalf, kHalf>().inverse();
    a_inverse_b.noalias() = a_inverse * a.template topRightCorner<kHalf, kHalf>();
    Half schur = a.template bottomRightCorner<kHalf, kHalf>();
    schur.noalias() -= a.template bottomLeftCorner<kHalf, kHalf>() * a_inverse_b;
    s_inverse = schur.inverse();
  }
  template <class Vector>
  Eigen::Matrix<double, N, 1> solve(const Vector& b) const {
    const HalfVector top = a_inverse * b.template head<kHalf>();
    // A⁻¹ is symmetric, so Bᵀ A⁻¹ b₁ = (A⁻¹B)ᵀ b₁ needs no second product.
    const HalfVector bottom =
        s_inverse * (b.template tail<kHalf>() - a_inverse_b.transpose() * b.template head<kHalf>());
    Eigen::Matrix<double, N, 1> x;
    x << top - a_inverse_b * bottom, bottom;
    return x;
  }
};
/// Above, Cholesky a = L Lᵀ with loops of compile-time length that the compiler unrolls (the
/// implicit Runge–Kutta stages); the reciprocals of L's diagonal are kept, so that the two
/// triangular solves only multiply. No pivoting: a is SPD.
template <int N>
struct SmallCholeskySolver {
  Eigen::Matrix<double, N, N> lower;  // L below the diagonal; the diagonal is unused
  Eigen::Matrix<double, N, 1> inverse_diagonal;
  template <class Matrix>
  void compute(const Matrix& a) {
    for (int j = 0; j < N; ++j) {
      double diagonal = a(j, j);
      for (int k = 0; k < j; ++k) diagonal -= lower(j, k) * lower(j, k);
      inverse_diagonal(j) = 1.0 / std::sqrt(diagonal);
      for (int i = j + 1; i < N; ++i) {
        double sum = a(i, j);
        for (int k = 0; k < j; ++k) sum -= lower(i, k) * lower(j, k);
        lower(i, j) = sum * inverse_diagonal(j);
      }
    }
  }
  template <class Vector>
  Eigen::Matrix<double, N, 1> solve(const Vector& b) const {
    Eigen::Matrix<double, N, 1> x;
    for (int i = 0; i < N; ++i) {  // L y = b
      double sum = b(i);
      for (int k = 0; k < i; ++k) sum -= lower(i, k) * x(k);
      x(i) = sum * inverse_diagonal(i);
    }
    for (int i = N - 1; i >= 0; --i) {  // Lᵀ x = y
      double sum = x(i);
      for (int k = i + 1; k < N; ++k) sum -= lower(k, i) * x(k);
      x(i) = sum * inverse_diagonal(i);
    }
    return x;
  }
};
template <int N>
using NormalEquationSolver = std::conditional_t<
    (N <= 4), SmallInverseSolver<N>,
    std::conditional_t<(N % 2 == 0 && N <= 8), SchurComplementSolver<N>, SmallCholeskySolver<N>>>;

/// Levenberg–Marquardt on r(x) = 0, N equations in N unknowns: each iteration solves the
/// normal equations (JᵀJ + D) δ = −Jᵀr in Jacobi-scaled unknowns, D the trust region's diagonal
/// (u · diag JᵀJ, clamped), and takes the step if the cost ½‖r‖² falls (ρ > 0), widening the
/// region, or narrows it. The iteration is Ceres 2.1's TinySolver's, operation for operation
/// (the library's results did not move when this replaced it: docs/reference/conventions.md §4);
/// written here so that only Ceres's Jet is used, whose interface every Ceres 2.x keeps. A trust
/// region started at 1e12 makes every step (almost) pure Newton.
///
/// `Function` has `NUM_PARAMETERS` (= N) and `bool operator()(const double* x, double* r,
/// double* jacobian) const`, the Jacobian column-major, `jacobian` possibly null; its return is
/// not read (a non-finite residual shows in the cost, and the callers test that).
template <class Function, int N = Function::NUM_PARAMETERS>
class TinyLevenbergMarquardt {
 public:
  using Vector = Eigen::Matrix<double, N, 1>;

  struct Options {
    int max_iterations = 30;  // iterations 1 .. max_iterations − 1 take steps
    /// Stop when ‖δ‖ < parameter_tolerance · (‖x‖ + parameter_tolerance).
    double parameter_tolerance = 1e-16;
    /// Stop when ½‖r(x)‖² < cost_threshold.
    double cost_threshold = 0.0;
    double initial_trust_region_radius = 1e12;
    /// Stop after the first step, taken or refused, with the cost at the point returned (the
    /// chord iterations: their next step starts from a fresh solve).
    bool single_step = false;
  };
  struct Summary {
    int iterations = 0;
    double final_cost = 0.0;  // ½‖r(x)‖² at the returned x
  };

  /// From x, in place.
  Summary solve(const Function& function, Vector& x, const Options& options) {
    Summary summary;
    update(function, x, true);
    summary.final_cost = cost_;
    if (cost_ < options.cost_threshold) return summary;
    double u = 1.0 / options.initial_trust_region_radius;
    double v = 2;
    for (summary.iterations = 1; summary.iterations < options.max_iterations;
         summary.iterations++) {
      regularized_ = jtj_;
      constexpr double kMinDiagonal = 1e-6, kMaxDiagonal = 1e32;
      // The square of √(u·d), as Ceres 2.1 rounds it (2.2 adds u·d: other bits).
      for (int i = 0; i < N; ++i) {
        const double d = std::sqrt(u * std::min(std::max(jtj_(i, i), kMinDiagonal), kMaxDiagonal));
        regularized_(i, i) += d * d;
      }
      linear_solver_.compute(regularized_);
      const Vector step = linear_solver_.solve(g_);
      const Vector dx = scaling_.asDiagonal() * step;
      // ‖x‖ + tolerance: the test works near x = 0 too.
      if (dx.norm() < options.parameter_tolerance * (x.norm() + options.parameter_tolerance)) {
        break;
      }
      const Vector x_new = x + dx;
      Vector r_new;
      function(x_new.data(), r_new.data(), nullptr);
      const double cost_change = 2 * cost_ - r_new.squaredNorm();
      const double model_cost_change = step.dot(2 * g_ - jtj_ * step);
      // ρ: the actual fall of the cost over the linear model's.
      const double rho = cost_change / model_cost_change;
      if (rho > 0) {
        x = x_new;
        if (options.single_step) {
          cost_ = r_new.squaredNorm() / 2;
          break;
        }
        update(function, x, false);
        if (cost_ < options.cost_threshold) break;
        const double tmp = 2 * rho - 1;
        u = u * std::max(1 / 3., 1 - tmp * tmp * tmp);
        v = 2;
      } else {
        if (options.single_step) break;
        u *= v;
        v *= 2;
      }
    }
    summary.final_cost = cost_;
    return summary;
  }

 private:
  using Square = Eigen::Matrix<double, N, N>;

  /// r, J, JᵀJ, Jᵀ(−r) and the cost at x; the Jacobi scaling 1 / (1 + ‖J's columns‖) from the
  /// first point's J (the 1 keeps small columns finite).
  void update(const Function& function, const Vector& x, bool first) {
    function(x.data(), residual_.data(), jacobian_.data());
    residual_ = -residual_;
    if (first) scaling_ = 1.0 / (1.0 + jacobian_.colwise().norm().array());
    jacobian_ = jacobian_ * scaling_.asDiagonal();
    jtj_ = jacobian_.transpose() * jacobian_;
    g_ = jacobian_.transpose() * residual_;
    cost_ = residual_.squaredNorm() / 2;
  }

  NormalEquationSolver<N> linear_solver_;
  double cost_ = 0.0;
  Vector residual_, g_, scaling_;
  Square jacobian_, jtj_, regularized_;
};

/// The cost ½‖r‖² under which a solve aiming at ‖r‖ <= target stops: ‖r‖ < target/4, a margin
/// below the tolerance that the callers then check on ‖r‖ itself.
inline double stoppingCost(double target) { return 0.5 * (0.25 * target) * (0.25 * target); }

/// Runs Levenberg–Marquardt on r(x) = 0 in place from the initial guess x, at most
/// `max_iterations` iterations, until ‖r‖ < target/4, and reports (no throw). `Function` as
/// TinyLevenbergMarquardt's.
template <class Function, int N = Function::NUM_PARAMETERS>
TinySolveStats runTinySolver(const Function& function, Eigen::Matrix<double, N, 1>& x,
                             double target, int max_iterations) {
  typename TinyLevenbergMarquardt<Function, N>::Options options;
  options.max_iterations = max_iterations;
  options.cost_threshold = stoppingCost(target);
  TinyLevenbergMarquardt<Function, N> solver;
  const auto summary = solver.solve(function, x, options);
  // final_cost = ½‖r(x)‖² at the returned x: every accepted step re-evaluates it there,
  // and a rejected one leaves x and the cost as they were.
  const double norm = std::sqrt(2.0 * summary.final_cost);
  return {summary.iterations, norm, norm <= target};
}

/// Solves r(x) = 0 to ‖r‖ <= relative_tolerance · scale or throws SolveFailure.
template <class Function, int N = Function::NUM_PARAMETERS>
TinySolveStats solveTinyWith(const Function& function, Eigen::Matrix<double, N, 1>& x, double scale,
                             const SolverOptions& options, const char* what, double t, double h) {
  const double target = options.relative_tolerance * scale;
  const TinySolveStats stats = runTinySolver(function, x, target, options.max_iterations);
  if (!std::isfinite(stats.residual)) {  // overflow, named as such (docs/reference/guarantees.md)
    Eigen::Matrix<double, N, 1> r;
    function(x.data(), r.data(), nullptr);
    throw NonFiniteState(what, -1, t, h, r, "residual");
  }
  if (!stats.converged) throw SolveFailure(what, -1, t, h, stats.residual, target);
  return stats;
}

/// An equation's function with its Jacobian evaluated once, at the first point asked, and
/// reused at every later point (the simplified Newton, or chord, method): from a guess
/// within δ of the solution it contracts like δ per iteration, so a predicted guess needs
/// one iteration as Newton does, at one Jacobian per solve instead of one per iterate.
/// The residual of the last point is kept too: the solver evaluates an accepted point
/// twice (without and then with the Jacobian).
template <class Function>
class FrozenJacobian {
 public:
  enum { NUM_RESIDUALS = Function::NUM_RESIDUALS, NUM_PARAMETERS = Function::NUM_PARAMETERS };

  explicit FrozenJacobian(const Function& function) : function_(function) {}

  bool operator()(const double* x, double* r, double* jacobian) const {
    const Eigen::Map<const Vector> point(x);
    Eigen::Map<Vector> residual(r);
    if (jacobian != nullptr && !frozen_) {
      function_(x, r, jacobian_.data());
      frozen_ = true;
    } else if (has_last_ && point == last_point_) {
      residual = last_residual_;
    } else {
      function_(x, r, nullptr);
    }
    last_point_ = point;
    last_residual_ = residual;
    has_last_ = true;
    if (jacobian != nullptr) {
      Eigen::Map<Square> out(jacobian);
      out = jacobian_;
    }
    return true;
  }

 private:
  using Vector = Eigen::Matrix<double, NUM_RESIDUALS, 1>;
  using Square = Eigen::Matrix<double, NUM_RESIDUALS, NUM_PARAMETERS>;
  const Function& function_;
  mutable bool frozen_ = false, has_last_ = false;
  mutable Square jacobian_;
  mutable Vector last_point_, last_residual_;
};

/// Chord iterations on r(x) = 0 with the Jacobian of the initial guess (FrozenJacobian above),
/// at most `max_iterations`, until ‖r‖ < target/4 as runTinySolver; reports (no throw). Each
/// iteration is one solve of a single step (`single_step`), which ends right after its step is
/// taken (or refused) with the new point's cost and without the second pass (scaling, JᵀJ, Jᵀr)
/// at it; the next solve's first pass does that work only if the point has not converged, which
/// is checked here. A step that is refused or that does not move x ends the chord (the caller
/// goes on with fresh Jacobians): a restarted solve would only repeat it.
template <class Function, int N = Function::NUM_PARAMETERS>
TinySolveStats runChordIterations(const Function& function, Eigen::Matrix<double, N, 1>& x,
                                  double target, int max_iterations) {
  const FrozenJacobian<Function> frozen(function);
  using Solver = TinyLevenbergMarquardt<FrozenJacobian<Function>, N>;
  typename Solver::Options options;
  options.max_iterations = 2;  // iterations 1 .. max − 1: one step
  options.single_step = true;
  options.cost_threshold = stoppingCost(target);
  Solver solver;
  TinySolveStats stats;
  for (;;) {
    const Eigen::Matrix<double, N, 1> before = x;
    // final_cost = ½‖r(x)‖² at the returned x, as in runTinySolver.
    const double cost = solver.solve(frozen, x, options).final_cost;
    stats.residual = std::sqrt(2.0 * cost);
    if (x == before) break;  // converged at x already, or the step was refused or negligible
    if (++stats.iterations == max_iterations || cost < options.cost_threshold) break;
  }
  stats.converged = stats.residual <= target;
  return stats;
}

/// An equation's function with the Jacobian by Jet autodiff: `Residual` has
/// `template <class T> bool operator()(const T* x, T* r) const`, N equations in N unknowns;
/// the residual at x and, when asked, ∂r/∂x column-major, from one evaluation on Jet<double, N>.
template <class Residual, int N>
class AutoDiffEquation {
 public:
  enum { NUM_RESIDUALS = N, NUM_PARAMETERS = N };

  explicit AutoDiffEquation(const Residual& residual) : residual_(residual) {}

  bool operator()(const double* x, double* r, double* jacobian) const {
    if (jacobian == nullptr) return residual_(x, r);
    using J = ceres::Jet<double, N>;
    J seeded[N], out[N];
    for (int i = 0; i < N; ++i) seeded[i] = J(x[i], i);
    const bool ok = residual_(seeded, out);
    Eigen::Map<Eigen::Matrix<double, N, N>> d(jacobian);
    for (int i = 0; i < N; ++i) {
      r[i] = out[i].a;
      d.row(i) = out[i].v;
    }
    return ok;
  }

 private:
  const Residual& residual_;
};

/// The same with the Jacobian by Jet autodiff (AutoDiffEquation).
template <int N, class Residual>
TinySolveStats solveTiny(const Residual& residual, Eigen::Matrix<double, N, 1>& x, double scale,
                         const SolverOptions& options, const char* what, double t, double h) {
  const AutoDiffEquation<Residual, N> function(residual);
  return solveTinyWith(function, x, scale, options, what, t, h);
}

}  // namespace ddb

// Solves the small fixed-size implicit equations r(x) = 0 with ceres::TinySolver
// (docs/reference/conventions.md §4), the Jacobian either supplied by the equation (analytic) or
// from Jet autodiff. TinySolver has no converged flag and an absolute function
// tolerance, so convergence is decided here on the final residual:
//   ‖r(x)‖ <= relative_tolerance · scale,
// scale being the size of the equation's data (e.g. ‖M_k‖). Failure throws SolveFailure.
#pragma once

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>
#include <ceres/version.h>
#include <ddb/core/errors.h>
#include <ddb/core/solver_options.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <type_traits>

// runChordIterations below drives TinySolver one LM iteration per Solve and reads its state
// between Solves (function_tolerance = ∞ ends a Solve right after its step; final_cost is
// the cost at the returned point). That is how Ceres 2.1's TinySolver behaves, and the only
// version this was tested with; another would need the chord loop checked again
// (tests/unit/test_legendre_solver.cc), so it is refused here rather than trusted silently.
static_assert(CERES_VERSION_MAJOR == 2 && CERES_VERSION_MINOR == 1,
              "ddb's chord iterations rely on Ceres 2.1's TinySolver (core/detail/tiny_solver.h)");

namespace ddb {

/// What one solve took: Newton (Levenberg–Marquardt) iterations, the final ‖r‖, and
/// whether ‖r‖ met the relative tolerance.
struct TinySolveStats {
  int iterations = 0;
  double residual = 0.0;
  bool converged = false;
};

/// TinySolver's linear solvers for its normal equations JᵀJ δ = Jᵀr (SPD). Their rounding only
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

/// Runs TinySolver on r(x) = 0 in place from the initial guess x, at most `max_iterations`
/// iterations, and reports (no throw). `Function` is a TinySolver function (NUM_RESIDUALS =
/// NUM_PARAMETERS = N; `operator()(x, r, J)` with J column-major, J may be null). The trust
/// region starts huge, so every step is (almost) pure Newton.
template <class Function, int N = Function::NUM_PARAMETERS>
TinySolveStats runTinySolver(const Function& function, Eigen::Matrix<double, N, 1>& x,
                             double target, int max_iterations) {
  ceres::TinySolver<Function, NormalEquationSolver<N>> solver;
  solver.options.max_num_iterations = max_iterations;
  solver.options.gradient_tolerance = 0.0;
  solver.options.function_tolerance = 0.0;  // absolute in Ceres 2.1: useless here
  solver.options.parameter_tolerance = 1e-16;
  solver.options.cost_threshold = 0.5 * (0.25 * target) * (0.25 * target);
  solver.options.initial_trust_region_radius = 1e12;
  const auto& summary = solver.Solve(function, &x);
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

/// A TinySolver function with its Jacobian evaluated once, at the first point asked, and
/// reused at every later point (the simplified Newton, or chord, method): from a guess
/// within δ of the solution it contracts like δ per iteration, so a predicted guess needs
/// one iteration as Newton does, at one Jacobian per solve instead of one per iterate.
/// The residual of the last point is kept too: TinySolver evaluates an accepted point
/// twice (without and then with the Jacobian).
template <class Function>
class FrozenJacobian {
 public:
  using Scalar = double;
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
    return true;  // TinySolver ignores the return (docs/reference/conventions.md §4)
  }

 private:
  using Vector = Eigen::Matrix<double, NUM_RESIDUALS, 1>;
  using Square = Eigen::Matrix<double, NUM_RESIDUALS, NUM_PARAMETERS>;
  const Function& function_;
  mutable bool frozen_ = false, has_last_ = false;
  mutable Square jacobian_;
  mutable Vector last_point_, last_residual_;
};

/// Chord iterations on r(x) = 0 with the Jacobian of the initial guess (FrozenJacobian below),
/// at most `max_iterations`, until ‖r‖ < target/4 as runTinySolver; reports (no throw). Each
/// iteration is one TinySolver Solve of a single LM iteration: function_tolerance = ∞ ends the
/// Solve right after its step is taken (or rejected), with the new point's cost and without
/// TinySolver's second residual-and-Jacobian pass (scaling, JᵀJ, Jᵀr) at it; the next Solve's
/// first pass does that work only if the point has not converged, which is checked here. A step
/// that is rejected or that does not move x ends the chord (the caller goes on with fresh
/// Jacobians): a restarted Solve would only repeat it.
template <class Function, int N = Function::NUM_PARAMETERS>
TinySolveStats runChordIterations(const Function& function, Eigen::Matrix<double, N, 1>& x,
                                  double target, int max_iterations) {
  const FrozenJacobian<Function> frozen(function);
  ceres::TinySolver<FrozenJacobian<Function>, NormalEquationSolver<N>> solver;
  solver.options.max_num_iterations = 2;  // iterations 1..max − 1: one LM iteration
  solver.options.gradient_tolerance = 0.0;
  solver.options.function_tolerance = INFINITY;
  solver.options.parameter_tolerance = 1e-16;
  solver.options.cost_threshold = 0.5 * (0.25 * target) * (0.25 * target);
  solver.options.initial_trust_region_radius = 1e12;
  TinySolveStats stats;
  for (;;) {
    const Eigen::Matrix<double, N, 1> before = x;
    // final_cost = ½‖r(x)‖² at the returned x, as in runTinySolver.
    const double cost = solver.Solve(frozen, &x).final_cost;
    stats.residual = std::sqrt(2.0 * cost);
    if (x == before) break;  // converged at x already, or the step was rejected or negligible
    if (++stats.iterations == max_iterations || cost < solver.options.cost_threshold) break;
  }
  stats.converged = stats.residual <= target;
  return stats;
}

/// The same with the Jacobian by Jet autodiff. `Residual` has
/// `template <class T> bool operator()(const T* x, T* r) const`.
template <int N, class Residual>
TinySolveStats solveTiny(const Residual& residual, Eigen::Matrix<double, N, 1>& x, double scale,
                         const SolverOptions& options, const char* what, double t, double h) {
  const ceres::TinySolverAutoDiffFunction<Residual, N, N> function(residual);
  return solveTinyWith(function, x, scale, options, what, t, h);
}

}  // namespace ddb

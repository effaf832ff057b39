// Solves the small fixed-size implicit equations r(x) = 0 with ceres::TinySolver and
// Jet autodiff (docs/conventions.md §4). TinySolver has no converged flag and an absolute
// function tolerance, so convergence is decided here on the final residual:
//   ‖r(x)‖ <= relative_tolerance · scale,
// scale being the size of the equation's data (e.g. ‖M_k‖). Failure throws SolveFailure.
#pragma once

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>
#include <ddb/core/errors.h>

#include <Eigen/Core>

namespace ddb {

struct SolverOptions {
  /// Relative residual tolerance (1e-14: round-off level for O(1) data).
  double relative_tolerance = 1e-14;
  int max_iterations = 30;
};

/// Solves residual(x) = 0 for x (in place, from the initial guess); returns ‖r(x)‖.
/// `Residual` has `template <class T> bool operator()(const T* x, T* r) const`.
template <int N, class Residual>
double solveTiny(const Residual& residual, Eigen::Matrix<double, N, 1>& x, double scale,
                 const SolverOptions& options, const char* what, double t, double h) {
  using AutoDiff = ceres::TinySolverAutoDiffFunction<Residual, N, N>;
  const AutoDiff function(residual);
  ceres::TinySolver<AutoDiff> solver;
  const double target = options.relative_tolerance * scale;
  solver.options.max_num_iterations = options.max_iterations;
  solver.options.gradient_tolerance = 0.0;
  solver.options.function_tolerance = 0.0;  // absolute in Ceres 2.1: useless here
  solver.options.parameter_tolerance = 1e-16;
  solver.options.cost_threshold = 0.5 * (0.25 * target) * (0.25 * target);
  solver.options.initial_trust_region_radius = 1e12;  // start as (almost) pure Newton
  solver.Solve(function, &x);

  Eigen::Matrix<double, N, 1> r;
  residual(x.data(), r.data());
  const double norm = r.norm();
  if (!std::isfinite(norm)) throw NonFiniteState(what, -1, t, h, r, "residual");
  if (!(norm <= target)) throw SolveFailure(what, -1, t, h, norm, target);
  return norm;
}

}  // namespace ddb

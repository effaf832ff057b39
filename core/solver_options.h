// SolverOptions: how hard the implicit solves of every method try (Legendre equations,
// implicit Runge–Kutta stages); a constructor argument of the DDB methods and of
// ImplicitRungeKutta (docs/reference/conventions.md §4).
#pragma once

namespace ddb {

struct SolverOptions {
  /// Relative residual tolerance (1e-14: round-off level for O(1) data).
  double relative_tolerance = 1e-14;
  int max_iterations = 30;
  /// Fixed-point sweeps at most before Newton in a small Legendre solve
  /// (integrators/solvers/legendre.h); 0: Newton from the extrapolated guess at once (always so
  /// when ∂H/∂μ is itself a solve, Hamiltonian::gradientIsASolve). Negative counts as 0.
  int max_sweeps = 10;
};

}  // namespace ddb

// What the last solve of a discrete Legendre equation took (both solvers: the small
// fixed-size one in legendre.h and the matrix-free one in matrix_legendre.h).
#pragma once

namespace ddb {

struct LegendreStats {
  int fixed_point = 0;  // fixed-point sweeps (the predictor's, for small systems)
  int newton = 0;       // Newton steps
  int krylov = 0;       // Jacobian–vector products inside GMRES (matrix-free solver only)
  int refinements = 0;  // frozen sweeps for an exact one-product update (matrix-free only)
  // final measured ‖r‖ (small solver's sweeps: docs/reference/conventions.md §4)
  double residual = 0;
};

}  // namespace ddb

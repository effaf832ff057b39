// The stages of one explicit Runge–Kutta step, k_i = f(μ + h Σ_{j<i} a_ij k_j), then
// μ ← μ + h Σ b_i k_i, on any state the backend's algebra serves (core/matrix_backend.h): the
// one body of ExplicitRungeKutta's step, which a system runs with its own field inlined
// (LiePoissonSystem::explicitStep; docs/design/architecture.md, "Explicit steps").
#pragma once

#include <ddb/core/butcher_tableau.h>
#include <ddb/core/matrix_backend.h>

namespace ddb {

/// The sweep over `tableau`'s stages with the slopes, the stage argument and the weighted sum in
/// w (ExplicitStages, core/lie_poisson_system.h); field(x, out) evaluates f(x) into out. The stage
/// loops are unrolled (the tableau stays data), so that a small system's slopes stay in registers
/// between the field's evaluations; the operations and their order are those of the plain loops
/// (the same roundings without floating-point contraction).
template <int S, class Dual, class Stages, class Field>
EIGEN_ALWAYS_INLINE void explicitRungeKuttaSweep(const ButcherTableau<S>& tableau, double h,
                                                 Dual& mu, Stages& w, const Field& field) {
  using B = MatrixBackend<Dual>;
  auto& k = w.slopes;
  Dual& stage = w.stage;
  Dual& sum = w.sum;
#pragma GCC unroll 16
  for (int i = 0; i < S; ++i) {
    B::copy(mu, stage);
#pragma GCC unroll 16
    for (int j = 0; j < i; ++j) {
      if (tableau.a[i][j] != 0.0) B::axpy(h * tableau.a[i][j], k[j], stage);
    }
    field(stage, k[i]);
  }
  B::scale(tableau.b[0], k[0], sum);
#pragma GCC unroll 16
  for (int i = 1; i < S; ++i) B::axpy(tableau.b[i], k[i], sum);
  B::axpy(h, sum, mu);
}

}  // namespace ddb

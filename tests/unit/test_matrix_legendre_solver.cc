// The matrix groups' Legendre solver on the fluid (docs/reference/conventions.md §2): its three
// strategies (fixed point, Newton–Krylov, Ceres) solve the same equation, and Newton–Krylov takes
// over where the fixed point stalls.

#include <ddb/groups/cayley.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/solvers/matrix_legendre_ceres.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "zeitlin_step_fraction.h"

namespace ddb::test {
namespace matrix_legendre_solver_tests {

using Matrix = Eigen::MatrixXcd;

// Fixed point, Newton–Krylov and Ceres solve the same Legendre equation to 1e-12.
TEST(MatrixLegendreSolver, FixedPointNewtonKrylovAndCeresAgree) {
  const int n = 8;  // u(8): 64 unknowns, the largest Ceres is asked to take
  const auto fluid = makeZeitlinFluid(n, 0.5);
  const Matrix W = randomVorticity(n, 21);
  const double h = zeitlinStepFraction(W, 0.8);
  std::vector<Matrix> results;
  for (auto strategy : {MatrixLegendreStrategy::kFixedPoint, MatrixLegendreStrategy::kNewtonKrylov,
                        MatrixLegendreStrategy::kExternal}) {
    Ddb<Cayley<SUN>> method(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian);
    if (strategy == MatrixLegendreStrategy::kExternal) {
      useCeres(method.legendreSolver());
    } else {
      method.legendreSolver().setStrategy(strategy);
    }
    results.push_back(method.step(W, 0.0, h));
    const auto& stats = method.legendreSolver().stats();
    std::cout << "strategy " << int(strategy) << ": fixed point " << stats.fixed_point
              << ", Newton " << stats.newton << ", Krylov " << stats.krylov << ", residual "
              << stats.residual << "\n";
  }
  EXPECT_LT((results[1] - results[0]).norm(), 1e-12 * W.norm());
  EXPECT_LT((results[2] - results[0]).norm(), 1e-12 * W.norm());
}

TEST(MatrixLegendreSolver, NewtonKrylovTakesOverWhereTheFixedPointStalls) {
  // h‖P‖₂/ħ ≈ 1.5: the fixed point contracts too slowly (docs/reference/conventions.md §2).
  const int n = 12;
  const auto fluid = makeZeitlinFluid(n, 0.5);
  const Matrix W = randomVorticity(n, 8);
  Ddb<Cayley<SUN>> method(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian);
  const Matrix next = method.step(W, 0.0, zeitlinStepFraction(W, 1.5));
  EXPECT_GT(method.legendreSolver().stats().newton, 0);
  EXPECT_LT((SUN::casimirs(next) - SUN::casimirs(W)).norm(), 1e-13 * W.norm());
}

}  // namespace matrix_legendre_solver_tests
}  // namespace ddb::test
